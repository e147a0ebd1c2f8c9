// celform.Document: opening and saving projects, what they hold, drawings, key viewpoints, the
// falloff brush, the project's settings (`celform set`) and the shot's camera path. Each edit calls
// the document operation the command line's sub-command calls (app/cli/project.cpp, keys.cpp,
// look.cpp, camera.cpp), with the options read by the command line's readers (cli_args.h).
#include "cli_args.h"
#include "document.h"

#include "cli/options.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/framed_camera.h"
#include "celform/model/data/mirror_plane.h"
#include "celform/model/io/image_io.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <QFileInfo>
#include <QJsonArray>

namespace celform::python {

using app::Cli;
using app::UsageError;

PyDocument::PyDocument()
{
    ensureApplication();
    doc = std::make_unique<model::Document>();
}

QString PyDocument::source() const
{
    return doc->filePath().isEmpty() ? Cli::tr("(unsaved document)") : doc->filePath();
}

void PyDocument::requireIdle() const
{
    if (jobs.load() > 0) {
        PyErr_SetString(PyExc_RuntimeError,
            "the document is being rendered or exported on another thread; edit it when "
            "that call has returned");
        throw py::error_already_set();
    }
}

namespace {

/// A read-only numpy view of an Eigen row-major matrix that owner keeps alive.
template <typename Matrix> py::array readOnlyView(const Matrix& matrix, py::object owner)
{
    using T = typename Matrix::Scalar;
    py::array a(py::dtype::of<T>(), {py::ssize_t(matrix.rows()), py::ssize_t(matrix.cols())},
        {py::ssize_t(sizeof(T) * std::size_t(matrix.cols())), py::ssize_t(sizeof(T))}, matrix.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

/// The base model's vertices or faces as a read-only array over the mesh itself: the mesh is
/// immutable and shared, and the array keeps this version of it alive.
py::object meshArray(const PyDocument& d, bool faces)
{
    if (!d->hasMesh())
        return py::none();
    auto mesh = d->data().baseMesh;
    py::capsule owner(new std::shared_ptr<const algo::TriMesh>(mesh),
        [](void* p) { delete static_cast<std::shared_ptr<const algo::TriMesh>*>(p); });
    return faces ? readOnlyView(mesh->faces, owner) : readOnlyView(mesh->vertices, owner);
}

py::kwargs withOption(py::kwargs kwargs, const char* name, const py::object& value)
{
    kwargs[name] = value;
    return kwargs;
}

void requireMesh(const PyDocument& d)
{
    if (!d->hasMesh())
        throw model::IoError(d.source(), Cli::tr("has no base model"));
}

const model::KeyViewpoint& keyNamed(const PyDocument& d, const QString& name)
{
    const model::KeyViewpoint* key = d->data().keyByName(name);
    if (!key)
        throw model::IoError(d.source(), Cli::tr("has no key named “%1”").arg(name));
    return *key;
}

/// A line on (Python's) standard error, where the command line prints its warnings.
void printLine(const QString& line)
{
    py::module_::import("sys").attr("stderr").attr("write")(toPython(line + QLatin1Char('\n')));
}

void printWarnings(const QString& file, const QStringList& warnings)
{
    for (const QString& w : warnings)
        printLine(Cli::tr("warning: %1: %2").arg(file, w));
}

/// `celform info --json`'s object for the open document (project.cpp, projectInfoJson), with the
/// key light beside it.
QJsonObject infoJson(const PyDocument& d)
{
    QJsonObject root = app::projectInfoJson(d->data(), d.source());
    if (d->filePath().isEmpty())
        root.insert("file", QString());
    root.insert("light", model::lightJson(d->data().look.light));
    return root;
}

void newFromMesh(PyDocument& d, const py::object& mesh, const py::object& fpsValue, bool sequence,
    const std::vector<py::object>& drawings)
{
    const QString path = toQString(mesh);
    double fps = 24.0;
    if (!fpsValue.is_none()) {
        // As `celform new --fps` reads it (project.cpp).
        const CliOptions o(QStringLiteral("new"), py::kwargs(py::dict(py::arg("fps") = fpsValue)));
        fps = app::parseNumber("fps", o.in().value("fps"));
        if (!(fps > 0.0 && fps <= model::kMaxFps))
            throw UsageError{Cli::tr("--fps must lie in (0, %1]").arg(model::kMaxFps)};
    }
    d.requireIdle();
    printWarnings(path, d->newFromMesh(path, fps, sequence));
    for (const py::object& image : drawings)
        guardedEdit(d, [&] { return d->drawings().importDrawing(toQString(image)); });
}

/// `celform key add` on the document (keys.cpp, runKey): options as its keywords.
py::object addKey(PyDocument& d, const py::object& name, py::kwargs kwargs)
{
    const CliOptions o(QStringLiteral("key"), withOption(kwargs, "name", name));
    const app::Invocation& in = o.in();
    const app::KeyAddOptions options = app::readKeyAddOptions(in);
    const QString& keyName = options.name;
    requireMesh(d);
    const model::ObjectId id = guardedEdit(d, [&] {
        QStringList meshWarnings;
        const model::ObjectId made = app::addKeyViewpoint(*d.doc, in, options, meshWarnings);
        if (in.isSet("mesh"))
            printWarnings(in.value("mesh"), meshWarnings);
        return made;
    });
    const model::KeyViewpoint& key = *d->data().key(id);
    if (key.name != keyName.trimmed())
        printLine(Cli::tr("warning: %1: a key named “%2” exists; the new key is named “%3”")
                      .arg(d.source(), keyName.trimmed(), key.name));
    return toPython(QJsonObject{{"id", double(key.id)}, {"name", key.name},
        {"direction", model::vec3Json(key.direction)}, {"camera", model::cameraJson(key.camera)}});
}

/// `celform key set` (keys.cpp, runKeySet).
py::object setKeyMesh(PyDocument& d, const QString& keyName, const py::object& mesh, int frame)
{
    const CliOptions o(QStringLiteral("key"),
        py::kwargs(py::dict(py::arg("key") = toPython(keyName), py::arg("mesh") = mesh, py::arg("frame") = frame)));
    const int f = app::parseFrame("frame", o.in().value("frame"));
    requireMesh(d);
    const model::ObjectId id = keyNamed(d, keyName).id;
    const QString path = o.in().value("mesh");
    guardedEdit(d, [&] { printWarnings(path, d->keys().importKeyDeformation(id, model::importMesh(path), path, f)); });
    const model::KeyViewpoint& set = *d->data().key(id);
    QJsonArray frames;
    for (const auto& [k, offsets] : set.offsetsByFrame)
        frames.append(k);
    return toPython(QJsonObject{{"id", double(set.id)}, {"name", set.name}, {"frame", f},
        {"moved_vertices", double(set.offsetsByFrame.at(f).indices.size())}, {"keyed_frames", frames}});
}

/// `celform brush` (keys.cpp, runBrush): one stroke of one step through the key's camera.
py::object brush(PyDocument& d, const py::object& key, py::kwargs kwargs)
{
    const CliOptions o(QStringLiteral("brush"), withOption(kwargs, "key", key));
    const app::Invocation& in = o.in();
    const app::BrushOptions options = app::readBrushOptions(in);
    const model::KeyViewpoint& k = app::brushKey(*d.doc, options, d.source());
    return toPython(guardedEdit(d, [&] { return app::brushStroke(*d.doc, k, options, printLine); }));
}

/// `celform set` (look.cpp, runSet): each setting one document operation, as the editor's panels.
void setSettings(PyDocument& d, const py::kwargs& kwargs)
{
    const CliOptions o(QStringLiteral("set"), kwargs);
    const app::ProjectSettings settings = app::readProjectSettings(o.in());
    guardedEdit(d, [&] { app::applyProjectSettings(*d.doc, settings, d.source(), printLine); });
}

/// `celform camera` (camera.cpp, runCamera): a turntable, a key, clearing.
void cameraEdit(PyDocument& d, const py::kwargs& kwargs)
{
    const CliOptions o(QStringLiteral("camera"), kwargs);
    const app::Invocation& in = o.in();
    if (in.countSet({"turntable", "key", "clear"}) != 1)
        throw UsageError{Cli::tr("exactly one of --turntable, --key, --clear or --list is required")};
    app::checkCameraPathOptions(in);
    const app::CameraPathEdit edit = app::readCameraPathEdit(in);
    requireMesh(d);
    guardedEdit(d, [&] { app::applyCameraPathEdit(*d.doc, in, edit); });
}

} // namespace

void bindDocument(py::module_& m, py::class_<PyDocument>& c)
{
    c.def(py::init([](const py::object& path) {
        auto d = std::make_unique<PyDocument>();
        if (!path.is_none())
            (*d)->open(toQString(path));
        return d;
    }),
        py::arg("path") = py::none(),
        "An empty document, or the project file at path (celform.IoError when it cannot be read).");
    c.def("__repr__", [](const PyDocument& d) {
        const model::ProjectData& data = d->data();
        return toPython(QStringLiteral("<celform.Document %1: %2 vertices, %3 keys, %4 drawings%5>")
                            .arg(d->filePath().isEmpty() ? QStringLiteral("(unsaved)") : d->filePath())
                            .arg(data.baseMesh ? qint64(data.baseMesh->vertexCount()) : 0)
                            .arg(data.keys.size())
                            .arg(data.drawings.size())
                            .arg(d->isModified() ? QStringLiteral(", modified") : QString()));
    });
    c.def(
        "open",
        [](PyDocument& d, const py::object& path) {
            d.requireIdle();
            d->open(toQString(path));
        },
        py::arg("path"), "Replaces the document by a project file; unchanged when it cannot be read.");
    c.def("new_from_mesh", &newFromMesh, py::arg("mesh"), py::arg("fps") = py::none(), py::arg("sequence") = false,
        py::arg("drawings") = std::vector<py::object>{},
        "`celform new`: a project on a mesh file (or an animated base), with drawings embedded.");
    c.def(
        "save",
        [](PyDocument& d, const py::object& path) {
            const QString target = path.is_none() ? d->filePath() : toQString(path);
            if (target.isEmpty())
                throw UsageError{Cli::tr("--out is required")};
            if (QFileInfo(target).suffix().compare(QLatin1String("celform"), Qt::CaseInsensitive) != 0)
                throw UsageError{Cli::tr("--out must end in .celform, not “%1”").arg(target)};
            d.requireIdle();
            py::gil_scoped_release release;
            d->saveAs(target);
        },
        py::arg("path") = py::none(), "Saves atomically (keeping P.bak), to path or the document's own file.");
    c.def_property_readonly("file_path", [](const PyDocument& d) -> py::object {
        return d->filePath().isEmpty() ? py::object(py::none()) : py::object(toPython(d->filePath()));
    });
    c.def_property_readonly("modified", [](const PyDocument& d) { return d->isModified(); });
    c.def_property(
        "current_frame", [](const PyDocument& d) { return d->currentFrame(); },
        [](PyDocument& d, int frame) {
            d.requireIdle();
            d->setCurrentFrame(app::parseFrame("frame", QString::number(frame)));
        },
        "The playhead (not an edit).");
    c.def(
        "undo", [](PyDocument& d) { guardedEdit(d, [&] { d->undoStack()->undo(); }); }, "Undoes the last edit.");
    c.def("redo", [](PyDocument& d) { guardedEdit(d, [&] { d->undoStack()->redo(); }); });
    c.def_property_readonly(
        "history",
        [](const PyDocument& d) {
            QStringList steps;
            for (int i = 0; i < d->undoStack()->index(); ++i)
                steps << d->undoStack()->text(i);
            return toPython(steps);
        },
        "The undo steps done, oldest first (one per edit, named as in the editor).");
    c.def(
        "info", [](const PyDocument& d) { return toPython(infoJson(d)); },
        "What the project holds: the object `celform info --json` prints.");
    c.def_property_readonly(
        "vertices", [](const PyDocument& d) { return meshArray(d, false); },
        "The base model's vertices (#V x 3 float32, read-only, no copy), or None.");
    c.def_property_readonly(
        "faces", [](const PyDocument& d) { return meshArray(d, true); },
        "The base model's triangles (#F x 3 int32, read-only, no copy), or None.");
    c.def_property_readonly(
        "keys",
        [](const PyDocument& d) {
            QStringList names;
            for (const auto& k : d->data().keys)
                names << k.name;
            return toPython(names);
        },
        "The key viewpoints' names.");
    c.def_property_readonly(
        "drawings",
        [](const PyDocument& d) {
            QStringList names;
            for (const auto& dr : d->data().drawings)
                names << dr.name;
            return toPython(names);
        },
        "The reference drawings' names.");
    c.def(
        "import_drawing",
        [](PyDocument& d, const py::object& path) {
            return guardedEdit(d, [&] {
                const model::ObjectId id = d->drawings().importDrawing(toQString(path));
                return toPython(d->data().drawing(id)->name);
            });
        },
        py::arg("path"), "Embeds a reference drawing; returns its name.");
    c.def("add_key", &addKey, py::arg("name"),
        "`celform key add`: a key viewpoint. Keywords: view or eye/target/up, mesh or from_base, frame, drawing.");
    c.def(
        "set_key_mesh",
        [](PyDocument& d, const std::string& key, const py::object& mesh, int frame) {
            return setKeyMesh(d, QString::fromStdString(key), mesh, frame);
        },
        py::arg("key"), py::arg("mesh"), py::arg("frame") = 0,
        "`celform key set`: a key's shape at a frame from a mesh.");
    c.def(
        "remove_key",
        [](PyDocument& d, const std::string& key) {
            const model::ObjectId id = keyNamed(d, QString::fromStdString(key)).id;
            guardedEdit(d, [&] { d->keys().removeKey(id); });
        },
        py::arg("key"));
    c.def(
        "set_key_enabled",
        [](PyDocument& d, const std::string& key, bool enabled) {
            const model::ObjectId id = keyNamed(d, QString::fromStdString(key)).id;
            guardedEdit(d, [&] { d->keys().setKeyEnabled(id, enabled); });
        },
        py::arg("key"), py::arg("enabled"));
    c.def("brush", &brush, py::arg("key"),
        "`celform brush`: one falloff-brush stroke. Keywords: vertex, radius, drag=(dx, dy) or push=dz, falloff, "
        "strength, mirror, frame.");
    c.def("set", &setSettings,
        "`celform set`: sharpness, unspecified, time, light, style, render_view, subdivision, viewport_subdivision.");
    c.def("camera", &cameraEdit,
        "`celform camera`: turntable=FRAMES (axis, elevation, start, start_angle), key=F with view or eye/target/up, "
        "or clear=True.");
    c.def(
        "camera_path",
        [](const PyDocument& d) {
            return toPython(QJsonObject{{"keys", model::cameraPathJson(d->data().look.cameraPath)}})["keys"];
        },
        "The camera path's keys, as `celform camera --list --json` gives them.");

    m.def(
        "open",
        [](const py::object& path) {
            auto d = std::make_unique<PyDocument>();
            (*d)->open(toQString(path));
            return d;
        },
        py::arg("path"), "Opens a project file: a Document.");
    m.def(
        "new",
        [](const py::object& mesh, const py::object& fps, bool sequence, const std::vector<py::object>& drawings) {
            auto d = std::make_unique<PyDocument>();
            newFromMesh(*d, mesh, fps, sequence, drawings);
            return d;
        },
        py::arg("mesh"), py::arg("fps") = py::none(), py::arg("sequence") = false,
        py::arg("drawings") = std::vector<py::object>{}, "`celform new`: a Document on a mesh (not saved yet).");
}

} // namespace celform::python
