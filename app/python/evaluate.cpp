// Document.eval(): the view-dependent shape at a frame (`celform eval`, keys.cpp, runEval), through
// the renderer's own FrameEvaluator. The shape, the base and the direction come back as numpy arrays
// over the evaluator's own buffers (no copy): an Evaluation keeps them alive.
#include "cli_args.h"
#include "document.h"

#include "cli/options.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/render/render_job.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <QJsonArray>

namespace celform::python {
namespace {

using app::Cli;

/// One evaluated frame: the evaluator (its shape and base buffers) and the project data it read,
/// kept as long as Python holds the Evaluation or one of its arrays.
struct Evaluation {
    model::ProjectData data; // a copy: the base model is shared, not copied
    model::FrameEvaluator evaluator;
    int frame = 0;
};

py::array view(const std::shared_ptr<Evaluation>& e, const algo::Positions& positions)
{
    // The capsule holds the Evaluation: the array lives on after it.
    py::capsule owner(
        new std::shared_ptr<Evaluation>(e), [](void* p) { delete static_cast<std::shared_ptr<Evaluation>*>(p); });
    py::array a(py::dtype::of<float>(), {py::ssize_t(positions.rows()), py::ssize_t(3)},
        {py::ssize_t(3 * sizeof(float)), py::ssize_t(sizeof(float))}, positions.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

std::shared_ptr<Evaluation> evaluate(PyDocument& d, const py::kwargs& kwargs)
{
    // The options of `celform eval`, read as there.
    const CliOptions o(QStringLiteral("eval"), kwargs);
    const app::Invocation& in = o.in();
    model::RenderJob job;
    app::camera_options::checkCombination(in, false);
    if (app::camera_options::byCamera(in))
        job.camera = app::camera_options::explicitCamera(in);
    if (app::camera_options::byView(in))
        job.view = app::camera_options::view(in);
    auto e = std::make_shared<Evaluation>();
    e->frame = in.isSet("frame") ? app::parseFrame("frame", in.value("frame")) : 0;
    e->data = d->data();
    if (!e->data.baseMesh)
        throw model::IoError(d.source(), Cli::tr("has no base model"));
    QString error;
    if (!e->evaluator.prepare(e->data, &error))
        throw model::IoError(d.source(), error);
    {
        py::gil_scoped_release release;
        if (job.view)
            e->evaluator.evaluateDirection(e->data, e->frame, job.view->normalized());
        else
            e->evaluator.evaluate(e->data, e->frame, model::renderJobCamera(e->data, e->data.look, job, e->frame).eye);
    }
    if (in.isSet("out")) {
        algo::TriMesh mesh;
        mesh.faces = e->data.baseMesh->faces;
        mesh.vertices = e->evaluator.shape();
        model::exportMesh(mesh, in.value("out"));
    }
    return e;
}

QJsonObject evaluationJson(const Evaluation& e)
{
    const model::BlendResult& blend = e.evaluator.blend();
    QJsonArray shares;
    for (const auto& share : blend.shares)
        shares.append(
            QJsonObject{{"key", e.data.key(share.key)->name}, {"id", double(share.key)}, {"weight", share.weight}});
    return {{"view", model::vec3Json(e.evaluator.direction().normalized())}, {"frame", e.frame}, {"keys", shares},
        {"base_weight", blend.baseShare}, {"facet", blend.raw.facet}, {"falloff", blend.raw.falloff}};
}

} // namespace

void bindEvaluate(py::module_& m, py::class_<PyDocument>& document)
{
    py::class_<Evaluation, std::shared_ptr<Evaluation>> c(
        m, "Evaluation", "The view-dependent model at one frame, as `celform eval` evaluates it.");
    c.def_property_readonly(
        "shape", [](const std::shared_ptr<Evaluation>& e) { return view(e, e->evaluator.shape()); },
        "The blended shape (#V x 3 float32, base vertex order; read-only, no copy).");
    c.def_property_readonly(
        "base", [](const std::shared_ptr<Evaluation>& e) { return view(e, e->evaluator.base()); },
        "The base model at the frame (animated bases move), before the keys' offsets.");
    c.def_property_readonly("faces", [](const std::shared_ptr<Evaluation>& e) {
        const algo::Faces& f = e->data.baseMesh->faces;
        py::capsule owner(
            new std::shared_ptr<Evaluation>(e), [](void* p) { delete static_cast<std::shared_ptr<Evaluation>*>(p); });
        py::array a(py::dtype::of<std::int32_t>(), {py::ssize_t(f.rows()), py::ssize_t(3)},
            {py::ssize_t(3 * sizeof(std::int32_t)), py::ssize_t(sizeof(std::int32_t))}, f.data(), owner);
        py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
        return a;
    });
    c.def_property_readonly(
        "direction",
        [](const std::shared_ptr<Evaluation>& e) {
            const Eigen::Vector3d v = e->evaluator.direction().normalized();
            return py::array_t<double>(3, v.data());
        },
        "The view direction (unit, from the base centroid towards the eye).");
    c.def_property_readonly("frame", [](const std::shared_ptr<Evaluation>& e) { return e->frame; });
    c.def("__repr__", [](const std::shared_ptr<Evaluation>& e) {
        QStringList shares;
        for (const auto& share : e->evaluator.blend().shares)
            shares << QStringLiteral("%1 %2").arg(e->data.key(share.key)->name).arg(share.weight, 0, 'g', 4);
        return toPython(QStringLiteral("<celform.Evaluation frame %1: %2; base %3>")
                            .arg(e->frame)
                            .arg(shares.isEmpty() ? QStringLiteral("no keys") : shares.join(QStringLiteral(", ")))
                            .arg(e->evaluator.blend().baseShare, 0, 'g', 4));
    });
    c.def_property_readonly(
        "weights",
        [](const std::shared_ptr<Evaluation>& e) {
            py::dict w;
            for (const auto& share : e->evaluator.blend().shares)
                w[toPython(e->data.key(share.key)->name)] = share.weight;
            return w;
        },
        "The keys' weights by name.");
    c.def_property_readonly(
        "base_weight", [](const std::shared_ptr<Evaluation>& e) { return e->evaluator.blend().baseShare; });
    c.def(
        "json", [](const std::shared_ptr<Evaluation>& e) { return toPython(evaluationJson(*e)); },
        "The object `celform eval --json` prints.");
    c.def(
        "write",
        [](const std::shared_ptr<Evaluation>& e, const py::object& path) {
            algo::TriMesh mesh;
            mesh.faces = e->data.baseMesh->faces;
            mesh.vertices = e->evaluator.shape();
            model::exportMesh(mesh, toQString(path));
        },
        py::arg("path"), "Writes the blended mesh (OBJ or PLY, base vertex order), as `eval --out`.");
    document.def("eval", &evaluate,
        "`celform eval`: the shape at a view (view or eye/target/up; else the camera path or render camera) and "
        "frame; out=MESH writes it too. Returns an Evaluation.");
}

} // namespace celform::python
