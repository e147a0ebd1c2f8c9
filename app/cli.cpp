// Sub-commands of `celform`. Each parses its own options, works on a Document, prints JSON with
// --json, and reports bad input as one line naming the file and the problem (exit 3).
#include "cli.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/model/project_file.h"
#include "celform/model/mesh_io.h"
#include "celform/model/render_output.h"
#include "celform/model/view_blend.h"
#include "celform/algorithms/brush.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSize>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <exception>
#include <iterator>
#include <new>

namespace celform::app {
namespace {

// Gives lupdate the context "celform::app::Cli" for every Cli::tr() below.
struct Cli {
    Q_DECLARE_TR_FUNCTIONS(celform::app::Cli)
};

const QStringList kSubCommands = {QStringLiteral("new"), QStringLiteral("info"), QStringLiteral("key"),
    QStringLiteral("brush"), QStringLiteral("eval"), QStringLiteral("set"), QStringLiteral("render"),
    QStringLiteral("highlight"), QStringLiteral("patch")};

/// Thrown for a usage error; main turns it into exit code 2 with the message and a hint.
struct UsageError {
    QString message;
};

void printErr(const QString& line)
{
    QTextStream(stderr) << line << Qt::endl;
}
void printOut(const QString& text)
{
    QTextStream(stdout) << text;
}

QJsonArray vec3(const Eigen::Vector3d& v)
{
    return {v.x(), v.y(), v.z()};
}

/// Parses sub-command options; unknown options and a wrong number of positional arguments
/// are usage errors.
void parseOrThrow(QCommandLineParser& parser, const QStringList& args, int positionalCount, const QString& synopsis)
{
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    parser.addHelpOption();
    if (!parser.parse(args))
        throw UsageError{parser.errorText() + QLatin1Char('\n') + Cli::tr("usage: %1").arg(synopsis)};
    if (parser.isSet(QStringLiteral("help"))) {
        printOut(parser.helpText());
        throw UsageError{}; // help printed: exit 0 is handled by the caller through an empty message
    }
    if (parser.positionalArguments().size() != positionalCount)
        throw UsageError{Cli::tr("usage: %1").arg(synopsis)};
}

int commandNew(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Creates a project from a mesh file."));
    parser.addPositionalArgument(QStringLiteral("MESH"), Cli::tr("Mesh file (OBJ, PLY, STL, OFF, glTF, GLB)."));
    const QCommandLineOption out(QStringLiteral("out"), Cli::tr("Project file to write."), QStringLiteral("P.celform"));
    const QCommandLineOption drawing(
        QStringLiteral("drawing"), Cli::tr("Reference drawing to embed (repeatable)."), QStringLiteral("IMAGE"));
    parser.addOptions({out, drawing});
    parseOrThrow(parser, args, 1, QStringLiteral("celform new MESH --out P.celform [--drawing IMAGE]..."));
    if (!parser.isSet(out))
        throw UsageError{Cli::tr("--out is required\nusage: %1")
                             .arg(QStringLiteral("celform new MESH --out P.celform [--drawing IMAGE]..."))};

    model::Document doc;
    const QStringList warnings = doc.newFromMesh(parser.positionalArguments().front());
    for (const QString& w : warnings)
        printErr(Cli::tr("warning: %1: %2").arg(parser.positionalArguments().front(), w));
    for (const QString& image : parser.values(drawing))
        doc.importDrawing(image);
    doc.saveAs(parser.value(out));
    return kExitOk;
}

QJsonObject cameraJson(const model::Camera& c)
{
    return {{"eye", vec3(c.eye)}, {"target", vec3(c.target)}, {"up", vec3(c.up)}, {"right", vec3(c.right())},
        {"true_up", vec3(c.trueUp())}, {"forward", vec3(c.forward())},
        {"projection", c.projection == model::Projection::Perspective ? "perspective" : "orthographic"},
        {"fov_y_degrees", c.fovYDegrees}, {"ortho_height", c.orthoHeight}};
}

int commandInfo(const QStringList& args)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Prints what a project holds."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print machine-readable JSON."));
    parser.addOption(json);
    parseOrThrow(parser, args, 1, QStringLiteral("celform info P.celform [--json]"));

    const QString path = parser.positionalArguments().front();
    const model::ProjectData data = model::loadProject(path);

    QJsonObject root{{"file", QFileInfo(path).absoluteFilePath()}, {"format_version", model::kProjectFormatVersion}};
    if (data.baseMesh) {
        const auto& mesh = *data.baseMesh;
        const auto box = algo::boundingBox(mesh.vertices);
        root.insert("base_mesh",
            QJsonObject{{"name", data.baseMeshName}, {"vertex_count", double(mesh.vertexCount())},
                {"triangle_count", double(mesh.faceCount())},
                {"bounding_box", QJsonObject{{"min", vec3(box.min())}, {"max", vec3(box.max())}}},
                {"centroid", vec3(algo::centroid(mesh.vertices))}, {"has_uvs", mesh.hasUvs()},
                {"materials", double(mesh.materials.size())}, {"face_sets", double(data.faceSets.size())}});
    } else {
        root.insert("base_mesh", QJsonValue::Null);
    }
    QJsonArray drawings;
    for (const auto& d : data.drawings) {
        QJsonObject o{{"id", double(d.id)}, {"name", d.name}, {"format", d.imageFormat}, {"width", d.image.width()},
            {"height", d.image.height()}, {"bytes", double(d.imageData.size())}, {"opacity", d.opacity},
            {"frame", d.frame}, {"aligned", d.aligned}};
        if (d.aligned)
            o.insert("camera", cameraJson(d.camera));
        drawings.append(o);
    }
    root.insert("drawings", drawings);
    QJsonArray keys;
    for (const auto& k : data.keys) {
        QJsonArray frames, linked;
        for (const auto& [frame, offsets] : k.offsetsByFrame)
            frames.append(QJsonObject{{"frame", frame}, {"moved_vertices", double(offsets.indices.size())}});
        for (auto id : k.drawingIds)
            if (const auto* d = data.drawing(id))
                linked.append(d->name);
        keys.append(QJsonObject{{"id", double(k.id)}, {"name", k.name}, {"direction", vec3(k.direction)},
            {"enabled", k.enabled}, {"camera", cameraJson(k.camera)}, {"drawings", linked}, {"frames", frames}});
    }
    root.insert("key_viewpoints", keys);
    const char* unspecified[] = {"dummy", "cosine", "cosine2"};
    root.insert("blend",
        QJsonObject{{"sharpness", data.blend.sharpness}, {"unspecified", unspecified[int(data.blend.unspecified)]},
            {"time", data.blend.time == model::TimeInterpolation::PeriodicSpline ? "periodic" : "natural"}});
    if (data.look.renderCamera)
        root.insert("render_camera", cameraJson(*data.look.renderCamera));

    if (parser.isSet(json)) {
        printOut(QString::fromUtf8(QJsonDocument(root).toJson(QJsonDocument::Indented)));
        return kExitOk;
    }
    QString text;
    QTextStream s(&text);
    s << Cli::tr("Project: %1 (format %2)").arg(path).arg(model::kProjectFormatVersion) << '\n';
    if (data.baseMesh) {
        const auto& m = root["base_mesh"].toObject();
        s << Cli::tr("Base model: %1, %2 vertices, %3 triangles")
                 .arg(data.baseMeshName)
                 .arg(qint64(m["vertex_count"].toDouble()))
                 .arg(qint64(m["triangle_count"].toDouble()))
          << '\n';
    } else {
        s << Cli::tr("Base model: none") << '\n';
    }
    s << Cli::tr("Drawings: %1").arg(data.drawings.size()) << '\n';
    for (const auto& d : data.drawings)
        s << "  " << d.name << " (" << d.image.width() << "x" << d.image.height() << ' ' << d.imageFormat << ")\n";
    s << Cli::tr("Key viewpoints: %1").arg(data.keys.size()) << '\n';
    for (const auto& k : data.keys)
        s << "  " << k.name << " (" << k.direction.x() << ", " << k.direction.y() << ", " << k.direction.z() << ")\n";
    printOut(text);
    return kExitOk;
}

/// Parses N comma-separated finite numbers ("X,Y,Z", "DX,DY"); anything else is a usage error.
template <int N> Eigen::Matrix<double, N, 1> parseNumbers(const QString& option, const QString& text)
{
    const QStringList parts = text.split(QLatin1Char(','));
    Eigen::Matrix<double, N, 1> v;
    bool ok = parts.size() == N;
    for (int i = 0; ok && i < N; ++i)
        v[i] = parts[i].trimmed().toDouble(&ok);
    if (!ok || !v.allFinite())
        throw UsageError{N == 3 ? Cli::tr("--%1 needs three numbers X,Y,Z, not “%2”").arg(option, text)
                : N == 4        ? Cli::tr("--%1 needs four numbers X,Y,Z,R, not “%2”").arg(option, text)
                                : Cli::tr("--%1 needs two numbers A,B, not “%2”").arg(option, text)};
    return v;
}

Eigen::Vector3d parseVector(const QString& option, const QString& text)
{
    return parseNumbers<3>(option, text);
}

double parseNumber(const QString& option, const QString& text)
{
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        throw UsageError{Cli::tr("--%1 needs a number, not “%2”").arg(option, text)};
    return v;
}

int parseInt(const QString& option, const QString& text)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok)
        throw UsageError{Cli::tr("--%1 needs a whole number, not “%2”").arg(option, text)};
    return v;
}

/// Opens a project for an edit; the caller saves it.
std::unique_ptr<model::Document> openProject(const QString& path)
{
    auto doc = std::make_unique<model::Document>();
    doc->open(path);
    return doc;
}

const model::KeyViewpoint& findKey(const model::Document& doc, const QString& name, const QString& path)
{
    const model::KeyViewpoint* key = doc.data().keyByName(name);
    if (!key)
        throw model::IoError(path, Cli::tr("has no key named “%1”").arg(name));
    return *key;
}

/// A camera looking at the base centroid from a view direction, far enough to see the model.
model::Camera cameraFromView(const model::ProjectData& data, const Eigen::Vector3d& view, double aspect = 1.0)
{
    model::Camera camera;
    const Eigen::Vector3d centre = algo::centroid(data.baseMesh->vertices);
    // The sphere around the centroid holding every vertex fits the narrower field of view.
    const double radius = std::max(
        std::sqrt(
            (data.baseMesh->vertices.cast<double>().rowwise() - centre.transpose()).rowwise().squaredNorm().maxCoeff()),
        1e-6);
    const double halfY = camera.fovYDegrees * M_PI / 360.0;
    const double halfMin = std::min(halfY, std::atan(std::tan(halfY) * aspect));
    camera.target = centre;
    camera.eye = centre + view.normalized() * (1.05 * radius / std::sin(halfMin));
    camera.up = std::abs(view.normalized().y()) > 0.99 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(0, 1, 0);
    return camera;
}

/// The camera options of `key add` and `render`: --view, or --eye, --target and --up together.
struct CameraOptions {
    const QCommandLineOption view{QStringLiteral("view"),
        Cli::tr("View direction from the model's centroid towards the eye."), QStringLiteral("X,Y,Z")};
    const QCommandLineOption eye{QStringLiteral("eye"), Cli::tr("Camera position."), QStringLiteral("X,Y,Z")};
    const QCommandLineOption target{
        QStringLiteral("target"), Cli::tr("Point the camera looks at."), QStringLiteral("X,Y,Z")};
    const QCommandLineOption up{QStringLiteral("up"), Cli::tr("Camera up vector."), QStringLiteral("X,Y,Z")};

    [[nodiscard]] QList<QCommandLineOption> all() const { return {view, eye, target, up}; }
    [[nodiscard]] bool byView(const QCommandLineParser& p) const { return p.isSet(view); }
    [[nodiscard]] bool byCamera(const QCommandLineParser& p) const
    {
        return p.isSet(eye) || p.isSet(target) || p.isSet(up);
    }
    [[nodiscard]] bool cameraComplete(const QCommandLineParser& p) const
    {
        return p.isSet(eye) && p.isSet(target) && p.isSet(up);
    }
    /// The camera of --eye, --target and --up; a usage error when they make none.
    [[nodiscard]] model::Camera explicitCamera(const QCommandLineParser& p) const
    {
        model::Camera camera;
        camera.eye = parseVector(QStringLiteral("eye"), p.value(eye));
        camera.target = parseVector(QStringLiteral("target"), p.value(target));
        camera.up = parseVector(QStringLiteral("up"), p.value(up));
        if (!camera.isValid())
            throw UsageError{Cli::tr("--eye, --target and --up do not make a camera (eye equals target, or up is "
                                     "parallel to the view)")};
        return camera;
    }
    /// The --view direction, or fallback when absent; a usage error when zero.
    [[nodiscard]] Eigen::Vector3d viewDirection(const QCommandLineParser& p, const Eigen::Vector3d& fallback) const
    {
        const Eigen::Vector3d v = p.isSet(view) ? parseVector(QStringLiteral("view"), p.value(view)) : fallback;
        if (v.norm() == 0.0)
            throw UsageError{Cli::tr("--view must not be zero")};
        return v;
    }
};

int commandKey(const QStringList& args)
{
    const QString synopsis = QStringLiteral(
        "celform key add P --name N (--mesh KEY.obj | --from-base) (--view X,Y,Z | --eye X,Y,Z --target X,Y,Z "
        "--up X,Y,Z) [--frame F] [--drawing IMAGE] [--json]");
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Adds a key viewpoint with its key deformation."));
    parser.addPositionalArgument(QStringLiteral("add"), Cli::tr("The action (add)."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption name(QStringLiteral("name"), Cli::tr("Name of the new key."), QStringLiteral("N"));
    const QCommandLineOption mesh(QStringLiteral("mesh"),
        Cli::tr("Key deformation: a mesh with the base model's vertex count and order."), QStringLiteral("KEY.obj"));
    const QCommandLineOption fromBase(QStringLiteral("from-base"), Cli::tr("Start as a copy of the base model."));
    const CameraOptions cameraOptions;
    const QCommandLineOption frame(
        QStringLiteral("frame"), Cli::tr("Frame of the deformation (default 0)."), QStringLiteral("F"));
    const QCommandLineOption drawing(QStringLiteral("drawing"),
        Cli::tr("Reference drawing to embed and link, aligned with the key's camera."), QStringLiteral("IMAGE"));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print the new key as JSON."));
    parser.addOptions({name, mesh, fromBase, frame, drawing, json});
    parser.addOptions(cameraOptions.all());
    parseOrThrow(parser, args, 2, synopsis);
    if (parser.positionalArguments().front() != QLatin1String("add"))
        throw UsageError{
            Cli::tr("unknown key action “%1”\nusage: %2").arg(parser.positionalArguments().front(), synopsis)};
    if (!parser.isSet(name) || parser.isSet(mesh) == parser.isSet(fromBase))
        throw UsageError{
            Cli::tr("--name and exactly one of --mesh or --from-base are required\nusage: %1").arg(synopsis)};
    const bool byView = cameraOptions.byView(parser);
    const bool byCamera = cameraOptions.byCamera(parser);
    if (byView == byCamera || (byCamera && !cameraOptions.cameraComplete(parser)))
        throw UsageError{Cli::tr("give either --view or all of --eye, --target and --up\nusage: %1").arg(synopsis)};
    const int f = parser.isSet(frame) ? parseInt(QStringLiteral("frame"), parser.value(frame)) : 0;

    const QString path = parser.positionalArguments().at(1);
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    const model::Camera camera = byView
        ? cameraFromView(doc->data(), cameraOptions.viewDirection(parser, Eigen::Vector3d::Zero()))
        : cameraOptions.explicitCamera(parser);
    std::vector<model::ObjectId> drawingIds;
    if (parser.isSet(drawing)) {
        const model::ObjectId d = doc->importDrawing(parser.value(drawing));
        doc->setDrawingCamera(d, camera);
        drawingIds.push_back(d);
    }
    model::SparseOffsets offsets;
    if (parser.isSet(mesh)) {
        const QString meshPath = parser.value(mesh);
        model::MeshImport imported = model::importMesh(meshPath);
        if (imported.mesh.vertexCount() != doc->data().baseMesh->vertexCount())
            throw model::IoError(meshPath,
                Cli::tr("has %1 vertices, but the base model has %2: a key deformation "
                        "needs the base model's vertex count and order")
                    .arg(imported.mesh.vertexCount())
                    .arg(doc->data().baseMesh->vertexCount()));
        offsets = model::SparseOffsets::difference(imported.mesh.vertices, doc->data().baseMesh->vertices);
    }
    const model::ObjectId id = doc->createKey(parser.value(name), camera, drawingIds, std::move(offsets), f);
    doc->saveAs(path);
    const model::KeyViewpoint& key = *doc->data().key(id);
    if (parser.isSet(json)) {
        printOut(
            QString::fromUtf8(QJsonDocument(QJsonObject{{"id", double(key.id)}, {"name", key.name},
                                                {"direction", vec3(key.direction)}, {"camera", cameraJson(key.camera)}})
                                  .toJson(QJsonDocument::Indented)));
    }
    return kExitOk;
}

int commandBrush(const QStringList& args)
{
    const QString synopsis = QStringLiteral(
        "celform brush P --key N --vertex I --radius R (--drag DX,DY | --push DZ) [--frame F] [--json]");
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Deforms a key with the falloff brush, seen from the key's camera."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption key(QStringLiteral("key"), Cli::tr("Name of the key to deform."), QStringLiteral("N"));
    const QCommandLineOption vertex(
        QStringLiteral("vertex"), Cli::tr("Index of the picked vertex."), QStringLiteral("I"));
    const QCommandLineOption radius(
        QStringLiteral("radius"), Cli::tr("Selection radius in world units."), QStringLiteral("R"));
    const QCommandLineOption drag(QStringLiteral("drag"),
        Cli::tr("Move along the camera's right and up vectors, in world units."), QStringLiteral("DX,DY"));
    const QCommandLineOption push(QStringLiteral("push"),
        Cli::tr("Move along the viewing direction (away from the camera), in world units."), QStringLiteral("DZ"));
    const QCommandLineOption frame(
        QStringLiteral("frame"), Cli::tr("Frame of the deformation (default 0)."), QStringLiteral("F"));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print what moved as JSON."));
    parser.addOptions({key, vertex, radius, drag, push, frame, json});
    parseOrThrow(parser, args, 1, synopsis);
    if (!parser.isSet(key) || !parser.isSet(vertex) || !parser.isSet(radius)
        || parser.isSet(drag) == parser.isSet(push))
        throw UsageError{
            Cli::tr("--key, --vertex, --radius and exactly one of --drag or --push are required\nusage: %1")
                .arg(synopsis)};
    const int picked = parseInt(QStringLiteral("vertex"), parser.value(vertex));
    const double r = parseNumber(QStringLiteral("radius"), parser.value(radius));
    if (r <= 0)
        throw UsageError{Cli::tr("--radius must be positive")};
    const int f = parser.isSet(frame) ? parseInt(QStringLiteral("frame"), parser.value(frame)) : 0;

    const QString path = parser.positionalArguments().front();
    auto doc = openProject(path);
    const model::KeyViewpoint& k = findKey(*doc, parser.value(key), path);
    if (picked < 0 || picked >= doc->data().baseMesh->vertexCount())
        throw model::IoError(path,
            Cli::tr("has no vertex %1 (the base model has %2 vertices)")
                .arg(picked)
                .arg(doc->data().baseMesh->vertexCount()));
    const QString keyName = k.name;
    model::BrushStroke stroke = doc->beginBrushStroke(k.id, f, std::uint32_t(picked), r, k.camera);
    if (parser.isSet(drag)) {
        const Eigen::Vector2d d = parseNumbers<2>(QStringLiteral("drag"), parser.value(drag));
        doc->applyBrushStroke(stroke, {model::BrushMotion::Drag, d.x(), d.y()});
    } else {
        doc->applyBrushStroke(
            stroke, {model::BrushMotion::Push, parseNumber(QStringLiteral("push"), parser.value(push)), 0.0});
    }
    doc->endBrushStroke(stroke);
    const auto& selection = stroke.selection;
    doc->saveAs(path);
    if (parser.isSet(json))
        printOut(QString::fromUtf8(QJsonDocument(
            QJsonObject{{"key", keyName}, {"picked", picked}, {"moved_vertices", double(selection.indices.size())}})
                                       .toJson(QJsonDocument::Indented)));
    return kExitOk;
}

int commandEval(const QStringList& args)
{
    const QString synopsis = QStringLiteral("celform eval P --view X,Y,Z [--frame F] [--out MESH] [--json]");
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Evaluates the view-dependent shape for a view direction."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption view(QStringLiteral("view"),
        Cli::tr("View direction from the model's centroid towards the eye."), QStringLiteral("X,Y,Z"));
    const QCommandLineOption frame(QStringLiteral("frame"), Cli::tr("Frame (default 0)."), QStringLiteral("F"));
    const QCommandLineOption out(QStringLiteral("out"),
        Cli::tr("Write the blended mesh (OBJ or PLY, base vertex order)."), QStringLiteral("MESH"));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print the keys and weights as JSON."));
    parser.addOptions({view, frame, out, json});
    parseOrThrow(parser, args, 1, synopsis);
    if (!parser.isSet(view))
        throw UsageError{Cli::tr("--view is required\nusage: %1").arg(synopsis)};
    const Eigen::Vector3d v = parseVector(QStringLiteral("view"), parser.value(view));
    const int f = parser.isSet(frame) ? parseInt(QStringLiteral("frame"), parser.value(frame)) : 0;

    const QString path = parser.positionalArguments().front();
    const model::ProjectData data = model::loadProject(path);
    if (!data.baseMesh)
        throw model::IoError(path, Cli::tr("has no base model"));
    model::BlendEvaluator blender;
    QString error;
    if (!blender.update(data, &error))
        throw model::IoError(path, error);
    const model::BlendResult blend = blender.weights(data, v);
    if (parser.isSet(out)) {
        algo::TriMesh mesh;
        mesh.faces = data.baseMesh->faces;
        blender.shape(data, v, f, mesh.vertices);
        model::exportMesh(mesh, parser.value(out));
    }
    QJsonArray shares;
    for (const auto& share : blend.shares)
        shares.append(
            QJsonObject{{"key", data.key(share.key)->name}, {"id", double(share.key)}, {"weight", share.weight}});
    const QJsonObject result{{"view", vec3(v.normalized())}, {"frame", f}, {"keys", shares},
        {"base_weight", blend.baseShare}, {"facet", blend.raw.facet}, {"falloff", blend.raw.falloff}};
    if (parser.isSet(json)) {
        printOut(QString::fromUtf8(QJsonDocument(result).toJson(QJsonDocument::Indented)));
    } else {
        QString text;
        for (const auto& share : blend.shares)
            text += QStringLiteral("%1\t%2\n").arg(data.key(share.key)->name).arg(share.weight, 0, 'g', 10);
        text += QStringLiteral("(base)\t%1\n").arg(blend.baseShare, 0, 'g', 10);
        printOut(text);
    }
    return kExitOk;
}

/// Parses a light override like "point:X,Y,Z" or "directional:X,Y,Z".
model::Light parseLight(const QString& value)
{
    const int colon = int(value.indexOf(QLatin1Char(':')));
    const QString type = value.left(colon);
    model::Light l;
    if (colon < 0 || (type != QLatin1String("point") && type != QLatin1String("directional")))
        throw UsageError{Cli::tr("--light takes point:X,Y,Z or directional:X,Y,Z, not “%1”").arg(value)};
    l.type = type == QLatin1String("point") ? model::LightType::Point : model::LightType::Directional;
    l.vector = parseVector(QStringLiteral("light"), value.mid(colon + 1));
    if (l.type == model::LightType::Directional) {
        if (l.vector.norm() == 0)
            throw UsageError{Cli::tr("a directional light needs a non-zero direction")};
        l.vector.normalize();
    }
    return l;
}

/// Parses a shading style name.
model::ShadingStyle parseStyle(const QString& text)
{
    const std::pair<const char*, model::ShadingStyle> styles[]
        = {{"toon", model::ShadingStyle::Toon}, {"gooch", model::ShadingStyle::Gooch},
            {"comic", model::ShadingStyle::Comic}, {"lambert", model::ShadingStyle::Lambert}};
    for (const auto& [name, style] : styles)
        if (text == QLatin1String(name))
            return style;
    throw UsageError{Cli::tr("--style takes toon, gooch, comic or lambert, not “%1”").arg(text)};
}

int commandSet(const QStringList& args)
{
    const QString synopsis
        = QStringLiteral("celform set P [--sharpness A] [--unspecified dummy|cosine|cosine2] [--time natural|periodic] "
                         "[--light point:X,Y,Z|directional:X,Y,Z] [--style toon|gooch|comic|lambert] "
                         "[--render-view X,Y,Z|none]");
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Changes project settings."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption sharpness(
        QStringLiteral("sharpness"), Cli::tr("Blend sharpness alpha (> 0)."), QStringLiteral("A"));
    const QCommandLineOption unspecified(
        QStringLiteral("unspecified"), Cli::tr("Unspecified-region mode."), QStringLiteral("MODE"));
    const QCommandLineOption light(QStringLiteral("light"),
        Cli::tr("Key light: a point position or a direction towards the light."), QStringLiteral("TYPE:X,Y,Z"));
    const QCommandLineOption style(QStringLiteral("style"), Cli::tr("Shading style."), QStringLiteral("STYLE"));
    const QCommandLineOption time(QStringLiteral("time"),
        Cli::tr("Interpolation of key deformations over frames: natural (cubic spline, held outside the keyed "
                "frames) or periodic (a looping cycle)."),
        QStringLiteral("natural|periodic"));
    const QCommandLineOption renderView(QStringLiteral("render-view"),
        Cli::tr("The render camera: looking at the model's centroid from this direction, framed; none removes it."),
        QStringLiteral("X,Y,Z|none"));
    parser.addOptions({sharpness, unspecified, time, light, style, renderView});
    parseOrThrow(parser, args, 1, synopsis);
    if (!parser.isSet(sharpness) && !parser.isSet(unspecified) && !parser.isSet(time) && !parser.isSet(light)
        && !parser.isSet(style) && !parser.isSet(renderView))
        throw UsageError{Cli::tr("nothing to set\nusage: %1").arg(synopsis)};

    model::BlendSettings blend;
    model::Look look;
    const QString path = parser.positionalArguments().front();
    // Parse every option before touching the file: a usage error changes nothing.
    std::optional<double> alpha;
    if (parser.isSet(sharpness)) {
        alpha = parseNumber(QStringLiteral("sharpness"), parser.value(sharpness));
        if (*alpha <= 0)
            throw UsageError{Cli::tr("--sharpness must be positive")};
    }
    std::optional<model::UnspecifiedMode> mode;
    if (parser.isSet(unspecified)) {
        const QString m = parser.value(unspecified);
        if (m == QLatin1String("dummy"))
            mode = model::UnspecifiedMode::Dummy;
        else if (m == QLatin1String("cosine"))
            mode = model::UnspecifiedMode::Cosine;
        else if (m == QLatin1String("cosine2"))
            mode = model::UnspecifiedMode::Cosine2;
        else
            throw UsageError{Cli::tr("--unspecified takes dummy, cosine or cosine2, not “%1”").arg(m)};
    }
    std::optional<model::TimeInterpolation> newTime;
    if (parser.isSet(time)) {
        const QString t = parser.value(time);
        if (t == QLatin1String("natural"))
            newTime = model::TimeInterpolation::NaturalSpline;
        else if (t == QLatin1String("periodic"))
            newTime = model::TimeInterpolation::PeriodicSpline;
        else
            throw UsageError{Cli::tr("--time takes natural or periodic, not “%1”").arg(t)};
    }
    const std::optional<model::Light> newLight
        = parser.isSet(light) ? std::optional<model::Light>(parseLight(parser.value(light))) : std::nullopt;
    const std::optional<model::ShadingStyle> newStyle
        = parser.isSet(style) ? std::optional<model::ShadingStyle>(parseStyle(parser.value(style))) : std::nullopt;
    std::optional<Eigen::Vector3d> newRenderView; // zero: remove the render camera
    if (parser.isSet(renderView)) {
        const QString v = parser.value(renderView);
        newRenderView
            = v == QLatin1String("none") ? Eigen::Vector3d::Zero() : parseVector(QStringLiteral("render-view"), v);
        if (v != QLatin1String("none") && newRenderView->norm() == 0.0)
            throw UsageError{Cli::tr("--render-view must not be zero")};
    }

    auto doc = openProject(path);
    if (alpha)
        doc->setSharpness(*alpha);
    if (mode)
        doc->setUnspecifiedMode(*mode);
    if (newTime)
        doc->setTimeInterpolation(*newTime);
    look = doc->data().look;
    if (newLight)
        look.light = *newLight;
    if (newStyle)
        look.style = *newStyle;
    if (newRenderView) {
        if (newRenderView->norm() == 0.0)
            look.renderCamera.reset();
        else if (!doc->hasMesh())
            throw model::IoError(path, Cli::tr("has no base model to frame a render camera on"));
        else // framed for the widest 16:9 shot; narrower ones fit too with the vertical fit
            look.renderCamera = cameraFromView(doc->data(), *newRenderView, 16.0 / 9.0);
    }
    doc->setLook(look);
    doc->saveAs(path);
    return kExitOk;
}

/// Parses "--op TYPE:V[,V]" (translate:A,B rotate:DEG scale:DELTA split:G1,G2 square:SIGMA,N).
algo::HighlightOperation parseHighlightOperation(const QString& value)
{
    const int colon = int(value.indexOf(QLatin1Char(':')));
    const auto type = colon > 0 ? model::highlightOperationType(value.left(colon)) : std::nullopt;
    if (!type)
        throw UsageError{Cli::tr("--op takes translate:A,B, rotate:DEG, scale:DELTA, split:G1,G2 or square:SIGMA,N, "
                                 "not “%1”")
                             .arg(value)};
    algo::HighlightOperation op;
    op.type = *type;
    if (model::highlightOperationArity(*type) == 1) {
        op.a = float(parseNumber(QStringLiteral("op"), value.mid(colon + 1)));
    } else {
        const Eigen::Vector2d v = parseNumbers<2>(QStringLiteral("op"), value.mid(colon + 1));
        op.a = float(v.x());
        op.b = float(v.y());
    }
    algo::HighlightLayer check;
    check.shape.operations = {op};
    const QString problem = model::highlightLayerProblem(check);
    if (!problem.isEmpty())
        throw UsageError{Cli::tr("--op “%1”: %2").arg(value, problem)};
    return op;
}

/// Parses "--combine union:OTHER" or "--combine subtract:OTHER".
std::pair<algo::HighlightBoolean, QString> parseCombination(const QString& value)
{
    const int colon = int(value.indexOf(QLatin1Char(':')));
    const QString mode = value.left(colon);
    if (colon < 0 || (mode != QLatin1String("union") && mode != QLatin1String("subtract"))
        || value.mid(colon + 1).isEmpty())
        throw UsageError{Cli::tr("--combine takes union:OTHER or subtract:OTHER, not “%1”").arg(value)};
    return {mode == QLatin1String("union") ? algo::HighlightBoolean::Union : algo::HighlightBoolean::Subtraction,
        value.mid(colon + 1)};
}

/// The project file's form of a track, with "all" spelled out for a track on every face.
QJsonObject listedTrackJson(const model::HighlightTrack& t)
{
    QJsonObject o = model::highlightTrackJson(t);
    if (t.patch.isEmpty())
        o.insert("patch", QStringLiteral("all"));
    return o;
}

int commandHighlight(const QStringList& args)
{
    const QString synopsis = QStringLiteral(
        "celform highlight P (--list [--json] | --add NAME [--patch FACESET|all] [--epsilon E] [--guide X,Y,Z] "
        "[--color R,G,B] [--cut C] [--op TYPE:VALUES]... [--combine union|subtract:OTHER]... [--smooth N] "
        "[--visible on|off] [--frame F] [--json] | --remove NAME | --rename NAME --to NEW)");
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Adds, keys and lists stylized highlight layers."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption list(QStringLiteral("list"), Cli::tr("List the highlight layers."));
    const QCommandLineOption add(
        QStringLiteral("add"), Cli::tr("Add a layer, or with --frame key an existing one."), QStringLiteral("NAME"));
    const QCommandLineOption patch(QStringLiteral("patch"),
        Cli::tr("Face set the highlight may appear on (all: every face)."), QStringLiteral("FACESET"));
    const QCommandLineOption epsilon(
        QStringLiteral("epsilon"), Cli::tr("Size of the area, in (0, 1] (default 0.05)."), QStringLiteral("E"));
    const QCommandLineOption guide(QStringLiteral("guide"),
        Cli::tr("Direction of the u axis on models without UVs (default 0,1,0)."), QStringLiteral("X,Y,Z"));
    const QCommandLineOption color(
        QStringLiteral("color"), Cli::tr("Linear RGB colour in [0, 1] (default 1,1,1)."), QStringLiteral("R,G,B"));
    const QCommandLineOption cut(QStringLiteral("cut"),
        Cli::tr("Off-specular cut: no highlight where N.L <= C (default -1: off)."), QStringLiteral("C"));
    const QCommandLineOption op(QStringLiteral("op"),
        Cli::tr("Operation, in order (repeatable): translate:A,B rotate:DEG scale:DELTA split:G1,G2 "
                "square:SIGMA,N."),
        QStringLiteral("TYPE:VALUES"));
    const QCommandLineOption combine(QStringLiteral("combine"),
        Cli::tr("Unite with or subtract another layer's area (repeatable)."), QStringLiteral("MODE:OTHER"));
    const QCommandLineOption smooth(QStringLiteral("smooth"),
        Cli::tr("Rounds of normal smoothing over the patch for this layer (default 0: the surface's normals)."),
        QStringLiteral("N"));
    const QCommandLineOption visible(QStringLiteral("visible"),
        Cli::tr("Draw the layer (on) or use it only in combinations (off)."), QStringLiteral("on|off"));
    const QCommandLineOption frame(
        QStringLiteral("frame"), Cli::tr("Frame of the keyframe (default 0)."), QStringLiteral("F"));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print machine-readable JSON."));
    const QCommandLineOption remove(QStringLiteral("remove"),
        Cli::tr("Remove a layer and its use in other layers' combinations."), QStringLiteral("NAME"));
    const QCommandLineOption rename(
        QStringLiteral("rename"), Cli::tr("Rename a layer (with --to)."), QStringLiteral("NAME"));
    const QCommandLineOption to(QStringLiteral("to"), Cli::tr("The new name of --rename."), QStringLiteral("NEW"));
    parser.addOptions(
        {list, add, patch, epsilon, guide, color, cut, op, combine, smooth, visible, frame, json, remove, rename, to});
    parseOrThrow(parser, args, 1, synopsis);

    // Every option is checked before the file is touched.
    const bool editing = parser.isSet(patch) || parser.isSet(epsilon) || parser.isSet(guide) || parser.isSet(color)
        || parser.isSet(cut) || parser.isSet(op) || parser.isSet(combine) || parser.isSet(smooth)
        || parser.isSet(visible) || parser.isSet(frame);
    const int actions
        = int(parser.isSet(list)) + int(parser.isSet(add)) + int(parser.isSet(remove)) + int(parser.isSet(rename));
    if (actions != 1 || (!parser.isSet(add) && editing) || parser.isSet(rename) != parser.isSet(to))
        throw UsageError{Cli::tr(
            "give one of --list, --add NAME with its options, --remove NAME or --rename NAME --to NEW\nusage: %1")
                             .arg(synopsis)};
    const QString path = parser.positionalArguments().front();
    if (parser.isSet(remove) || parser.isSet(rename)) {
        // The same edits as the Highlights dock's Remove and rename: combinations follow.
        auto doc = openProject(path);
        model::Look look = doc->data().look;
        const QString name = parser.value(parser.isSet(remove) ? remove : rename);
        const auto it = std::find_if(look.highlights.begin(), look.highlights.end(),
            [&](const model::HighlightTrack& t) { return t.name == name; });
        if (it == look.highlights.end())
            throw model::IoError(path, Cli::tr("has no highlight layer named “%1”").arg(name));
        if (parser.isSet(remove)) {
            look.highlights.erase(it);
            for (auto& t : look.highlights)
                t.combineWith.erase(std::remove_if(t.combineWith.begin(), t.combineWith.end(),
                                        [&](const auto& c) { return c.second == name; }),
                    t.combineWith.end());
        } else {
            const QString newName = parser.value(to).trimmed();
            if (newName.isEmpty()
                || std::any_of(look.highlights.begin(), look.highlights.end(),
                    [&](const model::HighlightTrack& t) { return t.name == newName; }))
                throw UsageError{Cli::tr("--to needs a new name no other layer has, not “%1”").arg(parser.value(to))};
            it->name = newName;
            for (auto& t : look.highlights)
                for (auto& c : t.combineWith)
                    if (c.second == name)
                        c.second = newName;
        }
        doc->setLook(look);
        doc->saveAs(path);
        return kExitOk;
    }
    if (parser.isSet(list)) {
        const model::ProjectData data = model::loadProject(path);
        QJsonArray layers;
        for (const model::HighlightTrack& t : data.look.highlights)
            layers.append(listedTrackJson(t));
        if (parser.isSet(json)) {
            printOut(QString::fromUtf8(QJsonDocument(QJsonObject{{"layers", layers}}).toJson(QJsonDocument::Indented)));
        } else {
            QString text;
            for (const model::HighlightTrack& t : data.look.highlights)
                text += Cli::tr("%1\tpatch %2\t%3 keyframes\n")
                            .arg(t.name, t.patch.isEmpty() ? QStringLiteral("all") : t.patch)
                            .arg(t.keys.size());
            printOut(text);
        }
        return kExitOk;
    }

    const QString name = parser.value(add);
    if (name.isEmpty())
        throw UsageError{Cli::tr("--add needs a layer name")};
    std::optional<float> newEpsilon, newCut;
    if (parser.isSet(epsilon)) {
        newEpsilon = float(parseNumber(QStringLiteral("epsilon"), parser.value(epsilon)));
        if (!(*newEpsilon > 0.f && *newEpsilon <= 1.f))
            throw UsageError{Cli::tr("--epsilon must lie in (0, 1], not “%1”").arg(parser.value(epsilon))};
    }
    if (parser.isSet(cut)) {
        newCut = float(parseNumber(QStringLiteral("cut"), parser.value(cut)));
        if (!(*newCut >= -1.f && *newCut <= 1.f))
            throw UsageError{Cli::tr("--cut must lie in [-1, 1], not “%1”").arg(parser.value(cut))};
    }
    std::optional<Eigen::Vector3f> newGuide, newColor;
    if (parser.isSet(guide)) {
        newGuide = parseVector(QStringLiteral("guide"), parser.value(guide)).cast<float>();
        if (newGuide->norm() == 0.f)
            throw UsageError{Cli::tr("--guide must not be zero")};
    }
    if (parser.isSet(color)) {
        newColor = parseVector(QStringLiteral("color"), parser.value(color)).cast<float>();
        if (newColor->minCoeff() < 0.f || newColor->maxCoeff() > 1.f)
            throw UsageError{Cli::tr("--color components must lie in [0, 1], not “%1”").arg(parser.value(color))};
    }
    std::vector<algo::HighlightOperation> newOperations;
    for (const QString& v : parser.values(op))
        newOperations.push_back(parseHighlightOperation(v));
    std::vector<std::pair<algo::HighlightBoolean, QString>> newCombinations;
    for (const QString& v : parser.values(combine)) {
        newCombinations.push_back(parseCombination(v));
        if (newCombinations.back().second == name)
            throw UsageError{Cli::tr("--combine needs another layer than “%1” itself").arg(name)};
    }
    std::optional<int> newSmoothing;
    if (parser.isSet(smooth)) {
        newSmoothing = parseInt(QStringLiteral("smooth"), parser.value(smooth));
        if (*newSmoothing < 0 || *newSmoothing > model::kMaxHighlightSmoothing)
            throw UsageError{Cli::tr("--smooth must lie in [0, %1], not “%2”")
                                 .arg(model::kMaxHighlightSmoothing)
                                 .arg(parser.value(smooth))};
    }
    std::optional<bool> newVisible;
    if (parser.isSet(visible)) {
        const QString v = parser.value(visible);
        if (v != QLatin1String("on") && v != QLatin1String("off"))
            throw UsageError{Cli::tr("--visible takes on or off, not “%1”").arg(v)};
        newVisible = v == QLatin1String("on");
    }
    const int f = parser.isSet(frame) ? parseInt(QStringLiteral("frame"), parser.value(frame)) : 0;

    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    model::Look look = doc->data().look;
    auto it = std::find_if(
        look.highlights.begin(), look.highlights.end(), [&](const model::HighlightTrack& t) { return t.name == name; });
    if (it != look.highlights.end() && !parser.isSet(frame))
        throw model::IoError(path,
            Cli::tr("already has a highlight layer named “%1”; give --frame F to set a keyframe of it").arg(name));
    if (it == look.highlights.end()) {
        model::HighlightTrack track;
        track.name = name;
        look.highlights.push_back(std::move(track));
        it = std::prev(look.highlights.end());
    }
    model::HighlightTrack& track = *it;
    // The key starts from the layer as it is at F, then takes the given values.
    algo::HighlightLayer layer = track.keys.empty() ? algo::HighlightLayer{} : track.layerAt(f);
    if (newEpsilon)
        layer.shape.epsilon = *newEpsilon;
    if (newCut)
        layer.offSpecularCut = *newCut;
    if (newColor)
        layer.color = *newColor;
    if (parser.isSet(op))
        layer.shape.operations = newOperations;
    track.setKey(f, layer);
    if (parser.isSet(patch))
        track.patch = parser.value(patch) == QLatin1String("all") ? QString() : parser.value(patch);
    if (newGuide)
        track.guide = *newGuide;
    if (newVisible)
        track.visible = *newVisible;
    if (newSmoothing)
        track.smoothing = *newSmoothing;
    if (parser.isSet(combine))
        track.combineWith = newCombinations;

    const std::vector<QString> faceSets = doc->data().faceSetNames();
    if (!track.patch.isEmpty() && std::find(faceSets.begin(), faceSets.end(), track.patch) == faceSets.end())
        throw model::IoError(path, Cli::tr("has no face set named “%1”").arg(track.patch));
    for (const auto& [mode, other] : track.combineWith)
        if (std::none_of(look.highlights.begin(), look.highlights.end(),
                [&](const model::HighlightTrack& t) { return t.name == other; }))
            throw model::IoError(path, Cli::tr("has no highlight layer named “%1”").arg(other));
    const QString problem = model::highlightTracksProblem(look.highlights, faceSets);
    if (!problem.isEmpty())
        throw model::IoError(path, problem);
    // Keys with different operation types do not interpolate: the earlier one holds.
    for (std::size_t k = 1; k < track.keys.size(); ++k)
        if (!algo::sameHighlightStructure(track.keys[k - 1].layer, track.keys[k].layer))
            printErr(Cli::tr("warning: %1: the keyframes %2 and %3 of “%4” have different operations; the earlier "
                             "one holds between them")
                         .arg(path)
                         .arg(track.keys[k - 1].frame)
                         .arg(track.keys[k].frame)
                         .arg(name));
    const QJsonObject result = listedTrackJson(track);
    doc->setLook(look);
    doc->saveAs(path);
    if (parser.isSet(json))
        printOut(QString::fromUtf8(QJsonDocument(result).toJson(QJsonDocument::Indented)));
    return kExitOk;
}

/// Face indices from "A-B,C,...", each below faceCount (a usage error otherwise).
std::vector<std::int32_t> parseFaceList(const QString& text, Eigen::Index faceCount, const QString& path)
{
    std::vector<std::int32_t> faces;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList ends = part.trimmed().split(QLatin1Char('-'));
        bool okA = false, okB = true;
        const qlonglong a = ends[0].toLongLong(&okA);
        const qlonglong b = ends.size() == 2 ? ends[1].toLongLong(&okB) : a;
        if (ends.size() > 2 || !okA || !okB || a < 0 || b < a)
            throw UsageError{Cli::tr("--faces takes indices and ranges like 0-99,120, not “%1”").arg(text)};
        if (b >= faceCount)
            throw model::IoError(path, Cli::tr("has %1 faces; face %2 does not exist").arg(faceCount).arg(b));
        for (qlonglong f = a; f <= b; ++f)
            faces.push_back(std::int32_t(f));
    }
    return faces;
}

int commandPatch(const QStringList& args)
{
    const QString synopsis = QStringLiteral(
        "celform patch P (--list [--json] | --add NAME [--sphere X,Y,Z,R]... [--faces A-B,C]... [--material M]... "
        "[--json] | --subtract NAME [the same selections] | --remove NAME)");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        Cli::tr("Makes, lists and removes patches: named face sets that highlight layers are limited to."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const QCommandLineOption list(QStringLiteral("list"), Cli::tr("List the patches."));
    const QCommandLineOption add(QStringLiteral("add"),
        Cli::tr("Add the selected faces to a patch (made when missing)."), QStringLiteral("NAME"));
    const QCommandLineOption subtract(
        QStringLiteral("subtract"), Cli::tr("Take the selected faces out of a patch."), QStringLiteral("NAME"));
    const QCommandLineOption remove(QStringLiteral("remove"),
        Cli::tr("Delete a patch; its highlight layers go back to all faces."), QStringLiteral("NAME"));
    const QCommandLineOption sphere(QStringLiteral("sphere"),
        Cli::tr("Select the faces with a corner inside a sphere (repeatable)."), QStringLiteral("X,Y,Z,R"));
    const QCommandLineOption facesOption(
        QStringLiteral("faces"), Cli::tr("Select faces by index (repeatable)."), QStringLiteral("A-B,C"));
    const QCommandLineOption material(
        QStringLiteral("material"), Cli::tr("Select a material's faces (repeatable)."), QStringLiteral("M"));
    const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Print machine-readable JSON."));
    parser.addOptions({list, add, subtract, remove, sphere, facesOption, material, json});
    parseOrThrow(parser, args, 1, synopsis);
    const int actions
        = int(parser.isSet(list)) + int(parser.isSet(add)) + int(parser.isSet(subtract)) + int(parser.isSet(remove));
    const bool selecting = parser.isSet(sphere) || parser.isSet(facesOption) || parser.isSet(material);
    if (actions != 1 || ((parser.isSet(list) || parser.isSet(remove)) && selecting)
        || ((parser.isSet(add) || parser.isSet(subtract)) && !selecting))
        throw UsageError{Cli::tr("give one of --list, --add NAME or --subtract NAME with a selection, or --remove "
                                 "NAME\nusage: %1")
                             .arg(synopsis)};
    const QString path = parser.positionalArguments().front();
    std::vector<Eigen::Vector4d> spheres;
    for (const QString& text : parser.values(sphere)) {
        spheres.push_back(parseNumbers<4>(QStringLiteral("sphere"), text));
        if (!(spheres.back()[3] > 0.0))
            throw UsageError{Cli::tr("--sphere needs a positive radius, not “%1”").arg(text)};
    }
    auto patchJson = [](const algo::FaceSet& set) {
        return QJsonObject{{"name", QString::fromStdString(set.name)}, {"face_count", double(set.faces.size())}};
    };
    if (parser.isSet(list)) {
        const model::ProjectData data = model::loadProject(path);
        QJsonArray patches;
        QString text;
        for (const auto& set : data.faceSets) {
            patches.append(patchJson(set));
            text += Cli::tr("%1\t%2 faces\n").arg(QString::fromStdString(set.name)).arg(set.faces.size());
        }
        printOut(parser.isSet(json)
                ? QString::fromUtf8(QJsonDocument(QJsonObject{{"patches", patches}}).toJson(QJsonDocument::Indented))
                : text);
        return kExitOk;
    }
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    const model::ProjectData& data = doc->data();
    if (parser.isSet(remove)) {
        const QString name = parser.value(remove);
        if (!data.faceSet(name))
            throw model::IoError(path, Cli::tr("has no patch named “%1”").arg(name));
        doc->removeFaceSet(name);
        doc->saveAs(path);
        return kExitOk;
    }
    const algo::TriMesh& mesh = *data.baseMesh;
    std::vector<std::int32_t> selected;
    for (const QString& text : parser.values(facesOption)) {
        const auto faces = parseFaceList(text, mesh.faceCount(), path);
        selected.insert(selected.end(), faces.begin(), faces.end());
    }
    for (const QString& name : parser.values(material)) {
        const auto it = std::find_if(mesh.materials.begin(), mesh.materials.end(),
            [&](const algo::Material& m) { return QString::fromStdString(m.name) == name; });
        if (it == mesh.materials.end())
            throw model::IoError(path, Cli::tr("has no material named “%1”").arg(name));
        const auto index = std::int32_t(it - mesh.materials.begin());
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            if ((mesh.faceMaterials.empty() ? 0 : mesh.faceMaterials[std::size_t(f)]) == index)
                selected.push_back(std::int32_t(f));
    }
    for (const Eigen::Vector4d& s : spheres) {
        const Eigen::Vector3f centre = s.head<3>().cast<float>();
        const float r2 = float(s[3] * s[3]);
        for (Eigen::Index f = 0; f < mesh.faceCount(); ++f)
            for (int k = 0; k < 3; ++k)
                if ((mesh.vertices.row(mesh.faces(f, k)).transpose() - centre).squaredNorm() <= r2) {
                    selected.push_back(std::int32_t(f));
                    break;
                }
    }
    std::sort(selected.begin(), selected.end());
    selected.erase(std::unique(selected.begin(), selected.end()), selected.end());
    const QString name = parser.isSet(add) ? parser.value(add) : parser.value(subtract);
    if (name.trimmed().isEmpty())
        throw UsageError{Cli::tr("a patch needs a name")};
    const algo::FaceSet* existing = data.faceSet(name);
    if (parser.isSet(subtract) && !existing)
        throw model::IoError(path, Cli::tr("has no patch named “%1”").arg(name));
    const std::vector<std::int32_t> before = existing ? existing->faces : std::vector<std::int32_t>{};
    std::vector<std::int32_t> after;
    if (parser.isSet(add))
        std::set_union(before.begin(), before.end(), selected.begin(), selected.end(), std::back_inserter(after));
    else
        std::set_difference(before.begin(), before.end(), selected.begin(), selected.end(), std::back_inserter(after));
    doc->setFaceSet(name, after, Cli::tr("Edit Patch “%1”").arg(name));
    doc->saveAs(path);
    if (parser.isSet(json))
        printOut(
            QString::fromUtf8(QJsonDocument(patchJson(*doc->data().faceSet(name))).toJson(QJsonDocument::Indented)));
    return kExitOk;
}

/// Parses "WxH" (a usage error when malformed or out of range).
QSize parseSize(const QString& text)
{
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = parts.size() == 2 ? parts[0].toInt(&okW) : 0;
    const int h = parts.size() == 2 ? parts[1].toInt(&okH) : 0;
    if (!okW || !okH || w < 1 || h < 1 || w > 16384 || h > 16384)
        throw UsageError{Cli::tr("--size takes WIDTHxHEIGHT between 1 and 16384, not “%1”").arg(text)};
    return {w, h};
}

/// The frame's file name: a run of # in the name becomes the zero-padded frame number; without
/// one, "_FFFF" goes before the suffix when several frames are rendered.
QString framePath(const QString& pattern, int frame, bool sequence)
{
    const int first = int(pattern.indexOf(QLatin1Char('#')));
    if (first >= 0) {
        int last = first;
        while (last + 1 < pattern.size() && pattern[last + 1] == QLatin1Char('#'))
            ++last;
        return pattern.left(first) + QStringLiteral("%1").arg(frame, last - first + 1, 10, QLatin1Char('0'))
            + pattern.mid(last + 1);
    }
    if (!sequence)
        return pattern;
    const QFileInfo info(pattern);
    return info.dir().filePath(
        QStringLiteral("%1_%2.%3").arg(info.completeBaseName()).arg(frame, 4, 10, QLatin1Char('0')).arg(info.suffix()));
}

int commandRender(const QStringList& args)
{
    const QString synopsis = QStringLiteral(
        "celform render P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F | --frames A-B] "
        "[--size WxH] [--style toon|gooch|comic|lambert] [--lines on|off] [--light point:X,Y,Z|directional:X,Y,Z] "
        "[--stereo off|anaglyph|dubois|halfcolor|sbs|tb] [--pass beauty|lines|tone|highlights|depth|normal|id] "
        "[--out FILE.png|.exr|.tif]");
    QCommandLineParser parser;
    parser.setApplicationDescription(Cli::tr("Renders the project's look without a display (CPU renderer)."));
    parser.addPositionalArgument(QStringLiteral("P"), Cli::tr("Project file (.celform)."));
    const CameraOptions cameraOptions;
    const QCommandLineOption frame(
        QStringLiteral("frame"), Cli::tr("Frame to render (default 0)."), QStringLiteral("F"));
    const QCommandLineOption frames(
        QStringLiteral("frames"), Cli::tr("Frames to render, A-B inclusive."), QStringLiteral("A-B"));
    const QCommandLineOption size(
        QStringLiteral("size"), Cli::tr("Image size (default 1280x720)."), QStringLiteral("WxH"));
    const QCommandLineOption style(
        QStringLiteral("style"), Cli::tr("Shading style for this render."), QStringLiteral("STYLE"));
    const QCommandLineOption lines(
        QStringLiteral("lines"), Cli::tr("Draw the lines (on) or not (off)."), QStringLiteral("on|off"));
    const QCommandLineOption light(
        QStringLiteral("light"), Cli::tr("Key light for this render."), QStringLiteral("TYPE:X,Y,Z"));
    const QCommandLineOption stereo(QStringLiteral("stereo"), Cli::tr("Stereo output."), QStringLiteral("MODE"));
    const QCommandLineOption pass(QStringLiteral("pass"), Cli::tr("Write one render pass."), QStringLiteral("NAME"));
    const QCommandLineOption out(QStringLiteral("out"),
        Cli::tr("Output image (default: the project's name with .png)."), QStringLiteral("FILE"));
    parser.addOptions({frame, frames, size, style, lines, light, stereo, pass, out});
    parser.addOptions(cameraOptions.all());
    parseOrThrow(parser, args, 1, synopsis);

    // Every option is checked before any work: a usage error renders nothing.
    const bool byCamera = cameraOptions.byCamera(parser);
    if (cameraOptions.byView(parser) && byCamera)
        throw UsageError{Cli::tr("give either --view or --eye, --target and --up\nusage: %1").arg(synopsis)};
    if (byCamera && !cameraOptions.cameraComplete(parser))
        throw UsageError{Cli::tr("--eye, --target and --up go together\nusage: %1").arg(synopsis)};
    if (parser.isSet(frame) && parser.isSet(frames))
        throw UsageError{Cli::tr("give either --frame or --frames")};
    int firstFrame = parser.isSet(frame) ? parseInt(QStringLiteral("frame"), parser.value(frame)) : 0;
    int lastFrame = firstFrame;
    if (parser.isSet(frames)) {
        const QStringList range = parser.value(frames).split(QLatin1Char('-'));
        bool okA = false, okB = false;
        firstFrame = range.size() == 2 ? range[0].toInt(&okA) : 0;
        lastFrame = range.size() == 2 ? range[1].toInt(&okB) : 0;
        if (!okA || !okB || lastFrame < firstFrame)
            throw UsageError{Cli::tr("--frames takes A-B with A <= B, not “%1”").arg(parser.value(frames))};
    }
    const QSize imageSize = parser.isSet(size) ? parseSize(parser.value(size)) : QSize(1280, 720);
    const std::optional<model::ShadingStyle> styleOverride
        = parser.isSet(style) ? std::optional<model::ShadingStyle>(parseStyle(parser.value(style))) : std::nullopt;
    std::optional<bool> linesOverride;
    if (parser.isSet(lines)) {
        const QString v = parser.value(lines);
        if (v != QLatin1String("on") && v != QLatin1String("off"))
            throw UsageError{Cli::tr("--lines takes on or off, not “%1”").arg(v)};
        linesOverride = v == QLatin1String("on");
    }
    const std::optional<model::Light> lightOverride
        = parser.isSet(light) ? std::optional<model::Light>(parseLight(parser.value(light))) : std::nullopt;
    algo::StereoOutput stereoOutput = algo::StereoOutput::Off;
    if (parser.isSet(stereo)) {
        const QString v = parser.value(stereo);
        const std::pair<const char*, algo::StereoOutput> modes[]
            = {{"off", algo::StereoOutput::Off}, {"anaglyph", algo::StereoOutput::Anaglyph},
                {"dubois", algo::StereoOutput::Dubois}, {"halfcolor", algo::StereoOutput::HalfColor},
                {"sbs", algo::StereoOutput::SideBySide}, {"tb", algo::StereoOutput::TopBottom}};
        bool found = false;
        for (const auto& [n, m] : modes)
            if (v == QLatin1String(n)) {
                stereoOutput = m;
                found = true;
            }
        if (!found)
            throw UsageError{Cli::tr("--stereo takes off, anaglyph, dubois, halfcolor, sbs or tb, not “%1”").arg(v)};
    }
    const QString passName = parser.value(pass);
    if (parser.isSet(pass) && !model::renderPassNames().contains(passName))
        throw UsageError{Cli::tr("--pass takes one of %1, not “%2”")
                             .arg(model::renderPassNames().join(QStringLiteral(", ")), passName)};
    if (stereoOutput != algo::StereoOutput::Off && parser.isSet(pass) && passName != QLatin1String("beauty"))
        throw UsageError{Cli::tr("a stereo render writes the beauty pass only")};
    const QString path = parser.positionalArguments().front();
    const QString outPattern = parser.isSet(out)
        ? parser.value(out)
        : QFileInfo(path).dir().filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".png"));
    const QString suffix = QFileInfo(outPattern).suffix().toLower();
    if (!QStringList{QStringLiteral("png"), QStringLiteral("exr"), QStringLiteral("tif"), QStringLiteral("tiff"),
            QStringLiteral("jpg"), QStringLiteral("jpeg")}
             .contains(suffix))
        throw UsageError{Cli::tr("--out must end in .png, .exr, .tif or .jpg, not “%1”").arg(outPattern)};

    const model::ProjectData data = model::loadProject(path);
    if (!data.baseMesh)
        throw model::IoError(path, Cli::tr("has no base model"));
    model::Look look = data.look;
    if (styleOverride) {
        look.style = *styleOverride;
        look.materialStyles.clear();
    }
    if (linesOverride)
        look.showLines = *linesOverride;
    if (lightOverride)
        look.light = *lightOverride;
    // Without camera options: the project's render camera, else a framed view from (0.35, 0.25, 1).
    const model::Camera camera = byCamera ? cameraOptions.explicitCamera(parser)
        : (!cameraOptions.byView(parser) && look.renderCamera)
        ? *look.renderCamera
        : cameraFromView(data, cameraOptions.viewDirection(parser, Eigen::Vector3d(0.35, 0.25, 1.0)),
            double(imageSize.width()) / imageSize.height());

    model::BlendEvaluator blender;
    QString error;
    if (!blender.update(data, &error))
        throw model::IoError(path, error);
    const Eigen::Vector3d direction = blender.viewDirection(data, camera.eye);
    algo::RenderCache cache;
    const bool sequence = lastFrame > firstFrame;
    for (int f = firstFrame; f <= lastFrame; ++f) {
        algo::Positions shape;
        blender.shape(data, direction, f, shape);
        const algo::RenderPasses passes = model::renderShape(
            data, look, shape, f, camera, imageSize.width(), imageSize.height(), stereoOutput, cache);
        const QString target = framePath(outPattern, f, sequence);
        if (suffix == QLatin1String("exr") && !parser.isSet(pass) && stereoOutput == algo::StereoOutput::Off)
            model::writePassesExr(passes, target);
        else
            model::writeImage(model::passImage(passes, parser.isSet(pass) ? passName : QStringLiteral("beauty"),
                                  suffix == QLatin1String("exr")),
                target);
    }
    return kExitOk;
}

} // namespace

bool isCommandLineInvocation(const QStringList& arguments)
{
    if (arguments.size() < 2)
        return false;
    const QString& first = arguments.at(1);
    return kSubCommands.contains(first) || first == QLatin1String("--version") || first == QLatin1String("-v")
        || first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help");
}

int runCommandLine(const QStringList& arguments)
{
    const QString first = arguments.value(1);
    // Command syntax is not translated; only the word "usage" is.
    const QString usage = Cli::tr("usage:")
        + QStringLiteral(
            " celform [PROJECT] [--screenshot FILE.png]\n"
            "  celform new MESH --out P.celform [--drawing IMAGE]...\n"
            "  celform info P.celform [--json]\n"
            "  celform key add P --name N (--mesh KEY.obj | --from-base) (--view X,Y,Z | --eye X,Y,Z --target X,Y,Z "
            "--up X,Y,Z) [--frame F] [--drawing IMAGE] [--json]\n"
            "  celform brush P --key N --vertex I --radius R (--drag DX,DY | --push DZ) [--frame F] [--json]\n"
            "  celform eval P --view X,Y,Z [--frame F] [--out MESH] [--json]\n"
            "  celform set P [--sharpness A] [--unspecified dummy|cosine|cosine2] [--time natural|periodic] [--light "
            "point:X,Y,Z|directional:X,Y,Z] "
            "[--style toon|gooch|comic|lambert] [--render-view X,Y,Z|none]\n"
            "  celform render P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F | --frames A-B] "
            "[--size WxH] [--style toon|gooch|comic|lambert] [--lines on|off] [--light TYPE:X,Y,Z] "
            "[--stereo off|anaglyph|dubois|halfcolor|sbs|tb] [--pass NAME] [--out FILE.png|.exr|.tif]\n"
            "  celform highlight P --list [--json]\n"
            "  celform highlight P --add NAME [--patch FACESET|all] [--epsilon E] [--guide X,Y,Z] [--color R,G,B] "
            "[--cut C] [--op translate:A,B|rotate:DEG|scale:DELTA|split:G1,G2|square:SIGMA,N]... "
            "[--combine union|subtract:OTHER]... [--smooth N] [--visible on|off] [--frame F] [--json]\n"
            "  celform highlight P (--remove NAME | --rename NAME --to NEW)\n"
            "  celform patch P --list [--json]\n"
            "  celform patch P (--add NAME | --subtract NAME) [--sphere X,Y,Z,R]... [--faces A-B,C]... "
            "[--material M]... [--json]\n"
            "  celform patch P --remove NAME\n"
            "  celform --version\n"
            "Exit codes: 0 success, 2 usage error, 3 bad input.");
    try {
        if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
            printOut(QStringLiteral("celform %1\n").arg(QCoreApplication::applicationVersion()));
            return kExitOk;
        }
        if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
            printOut(usage + QLatin1Char('\n'));
            return kExitOk;
        }
        // QCommandLineParser wants the program name first.
        QStringList rest = arguments.mid(1);
        rest[0] = QStringLiteral("celform ") + first;
        if (first == QLatin1String("new"))
            return commandNew(rest);
        if (first == QLatin1String("info"))
            return commandInfo(rest);
        if (first == QLatin1String("key"))
            return commandKey(rest);
        if (first == QLatin1String("brush"))
            return commandBrush(rest);
        if (first == QLatin1String("eval"))
            return commandEval(rest);
        if (first == QLatin1String("set"))
            return commandSet(rest);
        if (first == QLatin1String("render"))
            return commandRender(rest);
        if (first == QLatin1String("highlight"))
            return commandHighlight(rest);
        if (first == QLatin1String("patch"))
            return commandPatch(rest);
        printErr(usage);
        return kExitUsage;
    } catch (const UsageError& e) {
        if (e.message.isEmpty())
            return kExitOk; // --help
        printErr(QStringLiteral("celform: ") + e.message);
        return kExitUsage;
    } catch (const model::IoError& e) {
        printErr(QStringLiteral("celform: ") + e.message());
        return kExitBadInput;
    } catch (const model::EditRefused& e) {
        printErr(QStringLiteral("celform: ") + arguments.value(2) + QStringLiteral(": ") + e.message());
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        printErr(Cli::tr("celform: out of memory"));
        return kExitBadInput;
    } catch (const std::exception& e) {
        printErr(QStringLiteral("celform: ") + QString::fromLocal8Bit(e.what()));
        return kExitBadInput;
    }
}

} // namespace celform::app
