// `celform new` and `celform info`: making a project from a mesh, and what a project holds.
#include "cli/command.h"
#include "cli/options.h"

#include "celform/algorithms/symmetry.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/document/document.h"
#include "celform/model/io/image_io.h"
#include "celform/model/io/project_file.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QTextStream>

namespace celform::app {
namespace {

/// The plane detected on the model and how far each axis plane is from mirroring it (the mean
/// distance of a reflected vertex to the nearest vertex, as a fraction of the model's diagonal).
QJsonObject symmetryJson(const algo::TriMesh& mesh)
{
    const algo::SymmetryEstimate& s = mesh.symmetry();
    return {{"detected", model::mirrorPlaneName(model::detectMirrorPlane(mesh))},
        {"error", QJsonObject{{"x", s.error[0]}, {"y", s.error[1]}, {"z", s.error[2]}}}};
}

int runNew(const Invocation& in)
{
    if (!in.isSet("out"))
        throw UsageError{Cli::tr("--out is required")};
    const QString mesh = in.argument(0);
    const QString out = in.value("out");
    // The project replaces whatever is at --out: never one of the files it is made from.
    for (const QString& input : QStringList{mesh} + in.values("drawing"))
        if (sameFile(out, input))
            throw UsageError{Cli::tr("--out “%1” is one of the files being read; give a new .celform file").arg(out)};
    if (QFileInfo(out).suffix().compare(QLatin1String("celform"), Qt::CaseInsensitive) != 0)
        throw UsageError{Cli::tr("--out must end in .celform, not “%1”").arg(out)};
    double fps = 24.0;
    if (in.isSet("fps")) {
        fps = parseNumber("fps", in.value("fps"));
        if (!(fps > 0.0 && fps <= model::kMaxFps))
            throw UsageError{Cli::tr("--fps must lie in (0, %1]").arg(model::kMaxFps)};
    }
    model::Document doc;
    for (const QString& w : doc.newFromMesh(mesh, fps, in.isSet("sequence")))
        printErr(Cli::tr("warning: %1: %2").arg(mesh, w));
    for (const QString& image : in.values("drawing"))
        doc.drawings().importDrawing(image);
    doc.saveAs(out);
    return kExitOk;
}

/// The drawings' sizes from their images' headers: info decodes no pixels (nor loads OpenImageIO
/// for them).
std::vector<QSize> drawingSizes(const model::ProjectData& data, const QString& path)
{
    std::vector<QSize> sizes;
    for (const auto& d : data.drawings)
        sizes.push_back(
            model::decodedImageSize(d.imageData, d.imageFormat, QStringLiteral("%1 (%2)").arg(path, d.name)));
    return sizes;
}

} // namespace

QJsonObject projectInfoJson(const model::ProjectData& data, const QString& path)
{
    const std::vector<QSize> sizes = drawingSizes(data, path);
    using model::vec3Json;
    QJsonObject root{{"file", QFileInfo(path).absoluteFilePath()}, {"format_version", model::kProjectFormatVersion},
        {"current_frame", data.currentFrame}, {"mirror_plane", model::mirrorPlaneName(data.mirrorPlane)}};
    if (data.baseMesh) {
        const auto& mesh = *data.baseMesh;
        const auto box = algo::boundingBox(mesh.vertices);
        root.insert("base_mesh",
            QJsonObject{{"name", data.baseMeshName}, {"vertex_count", double(mesh.vertexCount())},
                {"triangle_count", double(mesh.faceCount())},
                {"bounding_box", QJsonObject{{"min", vec3Json(box.min())}, {"max", vec3Json(box.max())}}},
                {"centroid", vec3Json(algo::centroid(mesh.vertices))}, {"has_uvs", mesh.hasUvs()},
                {"materials", double(mesh.materials.size())}, {"face_sets", double(data.faceSets.size())},
                {"symmetry", symmetryJson(mesh)}});
    } else {
        root.insert("base_mesh", QJsonValue::Null);
    }
    QJsonArray drawings;
    for (std::size_t i = 0; i < data.drawings.size(); ++i) {
        const model::Drawing& d = data.drawings[i];
        QJsonObject o{{"id", double(d.id)}, {"name", d.name}, {"format", d.imageFormat}, {"width", sizes[i].width()},
            {"height", sizes[i].height()}, {"bytes", double(d.imageData.size())}, {"opacity", d.opacity},
            {"frame", d.frame}, {"aligned", d.aligned}};
        if (d.aligned)
            o.insert("camera", model::cameraJson(d.camera));
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
        keys.append(QJsonObject{{"id", double(k.id)}, {"name", k.name}, {"direction", vec3Json(k.direction)},
            {"enabled", k.enabled}, {"camera", model::cameraJson(k.camera)}, {"drawings", linked}, {"frames", frames}});
    }
    root.insert("key_viewpoints", keys);
    const char* unspecified[] = {"dummy", "cosine", "cosine2"};
    root.insert("blend",
        QJsonObject{{"sharpness", data.blend.sharpness}, {"unspecified", unspecified[int(data.blend.unspecified)]},
            {"time", data.blend.time == model::TimeInterpolation::PeriodicSpline ? "periodic" : "natural"}});
    if (data.look.renderCamera)
        root.insert("render_camera", model::cameraJson(*data.look.renderCamera));
    // Loop subdivision: the render level and the viewport's (-1: the render level).
    root.insert("subdivision", data.look.subdivision.level);
    root.insert("viewport_subdivision", data.look.subdivision.viewportLevel);
    // The scene's time: frame F is the animation at time F / fps.
    root.insert("fps", data.time.fps);
    root.insert("frame_range", QJsonArray{data.time.firstFrame, data.time.lastFrame});
    root.insert("current_frame", data.currentFrame);
    root.insert("camera_keys", int(data.look.cameraPath.keys.size()));
    // The light track (issue 26): the keyed lights, empty when the single light serves every frame.
    root.insert("light_keys", model::lightTrackJson(data.look.lightTrack));
    // The artist's say over the depth analysis (issue 26): focal points and segment overrides.
    root.insert("face_importance", faceImportanceJson(data));
    root.insert("segment_overrides", segmentOverridesJson(data));
    if (data.animated()) {
        const algo::BaseAnimation& a = *data.baseAnimation;
        root.insert("base_animation",
            QJsonObject{{"first_frame", a.firstFrame}, {"frame_count", a.frameCount},
                {"morph_targets", int(a.morphTargets.size())}, {"joints", a.jointCount},
                {"vertex_frames", double(a.storedFrameCount(data.baseMesh->vertexCount()))}});
    } else {
        root.insert("base_animation", QJsonValue::Null);
    }

    return root;
}

namespace {

int runInfo(const Invocation& in)
{
    const QString path = in.argument(0);
    const model::ProjectData data = model::loadProject(path, model::DrawingImages::Skip);
    if (in.isSet("json")) {
        printJson(projectInfoJson(data, path));
        return kExitOk;
    }
    const std::vector<QSize> sizes = drawingSizes(data, path);
    QString text;
    QTextStream s(&text);
    s << Cli::tr("Project: %1 (format %2)").arg(path).arg(model::kProjectFormatVersion) << '\n';
    if (data.baseMesh)
        s << Cli::tr("Base model: %1, %2 vertices, %3 triangles")
                 .arg(data.baseMeshName)
                 .arg(qint64(data.baseMesh->vertexCount()))
                 .arg(qint64(data.baseMesh->faceCount()))
          << '\n';
    else
        s << Cli::tr("Base model: none") << '\n';
    s << Cli::tr("Mirror plane: %1").arg(model::mirrorPlaneName(data.mirrorPlane)) << '\n';
    s << Cli::tr("Drawings: %1").arg(data.drawings.size()) << '\n';
    for (std::size_t i = 0; i < data.drawings.size(); ++i)
        s << "  " << data.drawings[i].name << " (" << sizes[i].width() << "x" << sizes[i].height() << ' '
          << data.drawings[i].imageFormat << ")\n";
    s << Cli::tr("Frames: %1-%2 at %3 fps").arg(data.time.firstFrame).arg(data.time.lastFrame).arg(data.time.fps)
      << '\n';
    if (data.animated())
        s << Cli::tr("Animated base: %1 frames from frame %2")
                 .arg(data.baseAnimation->frameCount)
                 .arg(data.baseAnimation->firstFrame)
          << '\n';
    if (!data.look.cameraPath.empty())
        s << Cli::tr("Camera path: %1 keys").arg(data.look.cameraPath.keys.size()) << '\n';
    if (!data.look.lightTrack.empty())
        s << Cli::tr("Light track: %1 keys").arg(data.look.lightTrack.keys.size()) << '\n';
    s << Cli::tr("Key viewpoints: %1").arg(data.keys.size()) << '\n';
    for (const auto& k : data.keys)
        s << "  " << k.name << " (" << k.direction.x() << ", " << k.direction.y() << ", " << k.direction.z() << ")\n";
    s.flush();
    printOut(text);
    return kExitOk;
}

} // namespace

std::vector<SubCommand> projectCommands()
{
    return {
        {"new", {"celform new MESH --out P.celform [--drawing IMAGE]... [--fps F] [--sequence]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Creates a project from a mesh file, or from an animated base (a glTF/GLB with skins or morph "
                "targets, or an OBJ/PLY sequence such as walk_####.obj)."),
            {{"MESH", QT_TRANSLATE_NOOP("celform::app::Cli", "Mesh file (OBJ, PLY, STL, OFF, glTF, GLB).")}},
            {{"out", "P.celform", QT_TRANSLATE_NOOP("celform::app::Cli", "Project file to write.")},
                {"fps", "F",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Frames per second an animated base is sampled at (default 24); frame F is time F / fps.")},
                {"sequence", nullptr,
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "MESH is one numbered file of a sequence (walk_0001.obj): read it with its numbered "
                        "siblings as frames.")},
                {"drawing", "IMAGE",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Reference drawing to embed (repeatable).")}},
            runNew},
        {"info", {"celform info P.celform [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Prints what a project holds."), {{"P", kProjectArgument}},
            {{"json", nullptr, kJsonOption}}, runInfo},
    };
}

} // namespace celform::app
