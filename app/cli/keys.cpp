// `celform key add`, `celform brush` and `celform eval`: key viewpoints, their deformation with the
// falloff brush, and the view-dependent blend they make (paper 1, sections 3.1 and 3.2).
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/data/mirror_plane.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"

#include <QJsonArray>

namespace celform::app {
namespace {

const char* const kFrameOption = QT_TRANSLATE_NOOP("celform::app::Cli", "Frame of the deformation (default 0).");

/// `key set`: a key's deformation at a frame from a mesh (paper 1, section 4.2: keyed frames such
/// as the front and side views at frames 10 and 30), replacing one stored there; one undo step.
int runKeySet(const Invocation& in)
{
    if (!in.isSet("key") || !in.isSet("mesh"))
        throw UsageError{Cli::tr("key set needs --key and --mesh")};
    if (in.isSet("name") || in.isSet("from-base") || in.isSet("drawing")
        || in.countSet({"view", "eye", "target", "up"}) > 0)
        throw UsageError{Cli::tr("key set takes only --key, --mesh, --frame and --json")};
    const int frame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    const QString path = in.argument(1);
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    const model::KeyViewpoint* key = doc->data().keyByName(in.value("key"));
    if (!key)
        throw model::IoError(path, Cli::tr("has no key named “%1”").arg(in.value("key")));
    const model::ObjectId id = key->id;
    for (const QString& w :
        doc->keys().importKeyDeformation(id, model::importMesh(in.value("mesh")), in.value("mesh"), frame))
        printErr(Cli::tr("warning: %1: %2").arg(in.value("mesh"), w));
    doc->saveAs(path);
    if (in.isSet("json")) {
        const model::KeyViewpoint& set = *doc->data().key(id);
        QJsonArray frames;
        for (const auto& [f, offsets] : set.offsetsByFrame)
            frames.append(f);
        printJson({{"id", double(set.id)}, {"name", set.name}, {"frame", frame},
            {"moved_vertices", double(set.offsetsByFrame.at(frame).indices.size())}, {"keyed_frames", frames}});
    }
    return kExitOk;
}

int runKey(const Invocation& in)
{
    if (in.argument(0) == QLatin1String("set"))
        return runKeySet(in);
    if (in.argument(0) != QLatin1String("add"))
        throw UsageError{Cli::tr("unknown key action “%1”").arg(in.argument(0))};
    const KeyAddOptions options = readKeyAddOptions(in);
    const QString& name = options.name;

    const QString path = in.argument(1);
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    QStringList meshWarnings;
    const model::ObjectId id = addKeyViewpoint(*doc, in, options, meshWarnings);
    for (const QString& w : meshWarnings)
        printErr(Cli::tr("warning: %1: %2").arg(in.value("mesh"), w));
    doc->saveAs(path);
    // A name in use is made unique, as the editor makes it (Document::uniqueKeyName): say so, since
    // later commands (brush --key) need the name given to the key.
    if (const QString& given = doc->data().key(id)->name; given != name.trimmed())
        printErr(Cli::tr("warning: %1: a key named “%2” exists; the new key is named “%3”")
                     .arg(path, name.trimmed(), given));
    if (in.isSet("json")) {
        const model::KeyViewpoint& key = *doc->data().key(id);
        printJson({{"id", double(key.id)}, {"name", key.name}, {"direction", model::vec3Json(key.direction)},
            {"camera", model::cameraJson(key.camera)}});
    }
    return kExitOk;
}

int runBrush(const Invocation& in)
{
    const BrushOptions brush = readBrushOptions(in);

    const QString path = in.argument(0);
    auto doc = openProject(path);
    const model::KeyViewpoint& key = brushKey(*doc, brush, path);
    const QJsonObject report = brushStroke(*doc, key, brush, printErr);
    doc->saveAs(path);
    if (in.isSet("json"))
        printJson(report);
    return kExitOk;
}

int runEval(const Invocation& in)
{
    model::RenderJob job;
    camera_options::checkCombination(in, false);
    if (camera_options::byCamera(in))
        job.camera = camera_options::explicitCamera(in);
    if (camera_options::byView(in))
        job.view = camera_options::view(in);
    const int frame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;

    const QString path = in.argument(0);
    const model::ProjectData data = model::loadProject(path);
    if (!data.baseMesh)
        throw model::IoError(path, Cli::tr("has no base model"));
    // The renderer's own evaluation (frame_evaluator.h): without camera options, the camera path
    // (or the render camera) at the frame, and the animated base there.
    model::FrameEvaluator evaluator;
    QString error;
    if (!evaluator.prepare(data, &error))
        throw model::IoError(path, error);
    if (job.view)
        evaluator.evaluateDirection(data, frame, job.view->normalized());
    else
        evaluator.evaluate(data, frame, model::renderJobCamera(data, data.look, job, frame).eye);
    const model::BlendResult& blend = evaluator.blend();
    const Eigen::Vector3d view = evaluator.direction();
    if (in.isSet("out")) {
        algo::TriMesh mesh;
        mesh.faces = data.baseMesh->faces;
        mesh.vertices = evaluator.shape();
        model::exportMesh(mesh, in.value("out"));
    }
    if (in.isSet("json")) {
        QJsonArray shares;
        for (const auto& share : blend.shares)
            shares.append(
                QJsonObject{{"key", data.key(share.key)->name}, {"id", double(share.key)}, {"weight", share.weight}});
        printJson({{"view", model::vec3Json(view.normalized())}, {"frame", frame}, {"keys", shares},
            {"base_weight", blend.baseShare}, {"facet", blend.raw.facet}, {"falloff", blend.raw.falloff}});
        return kExitOk;
    }
    QString text;
    for (const auto& share : blend.shares)
        text += QStringLiteral("%1\t%2\n").arg(data.key(share.key)->name).arg(share.weight, 0, 'g', 10);
    text += QStringLiteral("(base)\t%1\n").arg(blend.baseShare, 0, 'g', 10);
    printOut(text);
    return kExitOk;
}

std::vector<OptionSpec> evalOptions()
{
    std::vector<OptionSpec> options = camera_options::specs();
    options.push_back({"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame (default 0).")});
    options.push_back({"out", "MESH",
        QT_TRANSLATE_NOOP("celform::app::Cli", "Write the blended mesh (OBJ or PLY, base vertex order).")});
    options.push_back(
        {"json", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Print the camera, keys and weights as JSON.")});
    return options;
}

} // namespace

BrushOptions readBrushOptions(const Invocation& in)
{
    if (!in.isSet("key") || !in.isSet("vertex") || !in.isSet("radius") || in.isSet("drag") == in.isSet("push"))
        throw UsageError{Cli::tr("--key, --vertex, --radius and exactly one of --drag or --push are required")};
    BrushOptions brush;
    brush.key = in.value("key");
    brush.picked = parseInt("vertex", in.value("vertex"));
    brush.radius = parseNumber("radius", in.value("radius"));
    if (brush.radius <= 0)
        throw UsageError{Cli::tr("--radius must be positive")};
    if (in.isSet("drag")) {
        // Floats: the amounts must survive the float offsets the document stores.
        const Eigen::VectorXd drag = parseFloats("drag", in.value("drag"), 2);
        brush.step = {model::BrushMotion::Drag, drag[0], drag[1]};
    } else {
        brush.step = {model::BrushMotion::Push, parseFloat("push", in.value("push")), 0.0};
    }
    brush.frame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    if (in.isSet("falloff")) {
        const std::pair<const char*, algo::BrushFalloff> curves[] = {{"paper", algo::BrushFalloff::Paper},
            {"smooth", algo::BrushFalloff::Smooth}, {"sphere", algo::BrushFalloff::Sphere}};
        brush.profile.falloff
            = parseChoice(in.value("falloff"), curves, Cli::tr("--falloff must be paper, smooth or sphere, not “%1”"));
    }
    if (in.isSet("strength")) {
        brush.profile.strength = parseNumber("strength", in.value("strength"));
        if (!(brush.profile.strength > 0.0 && brush.profile.strength <= 1.0))
            throw UsageError{Cli::tr("--strength must be in (0, 1]")};
    }

    brush.mirror = parseMirror("mirror", in.isSet("mirror") ? in.value("mirror") : QStringLiteral("off"));
    return brush;
}

const model::KeyViewpoint& brushKey(const model::Document& doc, const BrushOptions& brush, const QString& path)
{
    const model::KeyViewpoint* key = doc.data().keyByName(brush.key);
    if (!key)
        throw model::IoError(path, Cli::tr("has no key named “%1”").arg(brush.key));
    const qint64 vertexCount = doc.hasMesh() ? qint64(doc.data().baseMesh->vertexCount()) : 0;
    if (brush.picked < 0 || brush.picked >= vertexCount)
        throw model::IoError(
            path, Cli::tr("has no vertex %1 (the base model has %2 vertices)").arg(brush.picked).arg(vertexCount));
    return *key;
}

QJsonObject brushStroke(model::Document& doc, const model::KeyViewpoint& key, const BrushOptions& brush,
    const std::function<void(const QString&)>& warn)
{
    // auto: the project's plane (detected on the model when it was imported).
    const model::MirrorPlane mirror = brush.mirror.value_or(doc.data().mirrorPlane);
    const QString keyName = key.name;
    const int picked = brush.picked;
    // One stroke of one step, seen through the key's camera, as the editor's brush tool runs it.
    model::BrushStroke stroke = doc.keys().beginBrushStroke(
        key.id, brush.frame, std::uint32_t(picked), brush.radius, key.camera, mirror, brush.profile);
    if (stroke.twinMissing)
        warn(Cli::tr("warning: vertex %1 has no mirror twin across the %2 plane; only its side moved")
                 .arg(picked)
                 .arg(model::mirrorPlaneName(mirror)));
    doc.keys().applyBrushStroke(stroke, brush.step);
    doc.keys().endBrushStroke(stroke);
    return {{"key", keyName}, {"picked", picked}, {"frame", brush.frame},
        {"moved_vertices", double(stroke.indices.size())}, {"mirror_plane", model::mirrorPlaneName(mirror)},
        {"mirrored_vertices", double(stroke.mirrorSelection.indices.size())},
        {"twin", stroke.mirrorSelection.indices.empty() ? -1.0 : double(stroke.mirrorSelection.picked)}};
}

KeyAddOptions readKeyAddOptions(const Invocation& in)
{
    if (!in.isSet("name") || in.isSet("mesh") == in.isSet("from-base"))
        throw UsageError{Cli::tr("--name and exactly one of --mesh or --from-base are required")};
    KeyAddOptions key;
    key.name = in.value("name");
    if (key.name.trimmed().isEmpty())
        throw UsageError{Cli::tr("--name needs a name, not “%1”").arg(key.name)};
    camera_options::checkCombination(in, true);
    key.byView = camera_options::byView(in);
    key.view = key.byView ? camera_options::view(in) : Eigen::Vector3d::Zero();
    key.camera = key.byView ? model::Camera{} : camera_options::explicitCamera(in);
    key.frame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    return key;
}

model::ObjectId addKeyViewpoint(
    model::Document& doc, const Invocation& in, const KeyAddOptions& key, QStringList& meshWarnings)
{
    const model::Camera camera = key.byView ? model::cameraFromView(doc.data(), key.view) : key.camera;
    std::vector<model::ObjectId> drawingIds;
    if (in.isSet("drawing")) {
        const model::ObjectId drawing = doc.drawings().importDrawing(in.value("drawing"));
        doc.drawings().setDrawingCamera(drawing, camera);
        drawingIds.push_back(drawing);
    }
    const model::ObjectId id = doc.keys().createKey(key.name, camera, drawingIds, {}, key.frame);
    if (in.isSet("mesh"))
        meshWarnings
            = doc.keys().importKeyDeformation(id, model::importMesh(in.value("mesh")), in.value("mesh"), key.frame);
    return id;
}

std::vector<SubCommand> keyCommands()
{
    std::vector<OptionSpec> keyOptions = {{"name", "N", QT_TRANSLATE_NOOP("celform::app::Cli", "Name of the new key.")},
        {"key", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "set: the key whose deformation is set.")},
        {"mesh", "KEY.obj",
            QT_TRANSLATE_NOOP(
                "celform::app::Cli", "Key deformation: a mesh with the base model's vertex count and order.")},
        {"from-base", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Start as a copy of the base model.")},
        {"frame", "F", kFrameOption},
        {"drawing", "IMAGE",
            QT_TRANSLATE_NOOP(
                "celform::app::Cli", "Reference drawing to embed and link, aligned with the key's camera.")},
        {"json", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Print the new key as JSON.")}};
    for (const OptionSpec& o : camera_options::specs())
        keyOptions.push_back(o);
    return {
        {"key",
            {"celform key add P --name N (--mesh KEY.obj | --from-base) (--view X,Y,Z | --eye X,Y,Z --target X,Y,Z "
             "--up X,Y,Z) [--frame F] [--drawing IMAGE] [--json]",
                "celform key set P --key NAME --mesh M.obj [--frame F] [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Adds a key viewpoint with its key deformation (add), or sets an existing key's deformation at a "
                "frame from a mesh, replacing one stored there (set)."),
            {{"add", QT_TRANSLATE_NOOP("celform::app::Cli", "The action (add or set).")}, {"P", kProjectArgument}},
            keyOptions, runKey},
        {"brush",
            {"celform brush P --key N --vertex I --radius R (--drag DX,DY | --push DZ) [--falloff C] [--strength S] "
             "[--mirror auto|x|y|z|off] [--frame F] [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Deforms a key with the falloff brush, seen from the key's camera."),
            {{"P", kProjectArgument}},
            {{"key", "N", QT_TRANSLATE_NOOP("celform::app::Cli", "Name of the key to deform.")},
                {"vertex", "I", QT_TRANSLATE_NOOP("celform::app::Cli", "Index of the picked vertex.")},
                {"radius", "R", QT_TRANSLATE_NOOP("celform::app::Cli", "Selection radius in world units.")},
                {"drag", "DX,DY",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Move along the camera's right and up vectors, in world units.")},
                {"push", "DZ",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Move along the viewing direction (away from the camera), in world units.")},
                {"falloff", "C",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Falloff curve: paper ((1 - d/r)^2, the default), smooth or sphere.")},
                {"strength", "S", QT_TRANSLATE_NOOP("celform::app::Cli", "Strength in (0, 1], 1 by default.")},
                {"mirror", "auto|x|y|z|off",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Move the mirror image too, across the plane perpendicular to that model axis through the "
                        "model's centre; auto: the project's plane (detected on the model); off by default.")},
                {"frame", "F", kFrameOption},
                {"json", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Print what moved as JSON.")}},
            runBrush},
        {"eval",
            {"celform eval P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F] [--out MESH] "
             "[--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Evaluates the view-dependent shape at a frame: for a view direction or a camera, else through the "
                "camera path (or the render camera) at that frame."),
            {{"P", kProjectArgument}}, evalOptions(), runEval},
    };
}

} // namespace celform::app
