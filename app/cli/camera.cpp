// `celform camera`: the shot's camera path (paper 1, figures 10-12) from the command
// line: a turntable, a key at a frame, clearing, listing. Edits go through the document and are
// saved in the project.
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"

#include <QJsonArray>
#include <QTextStream>

namespace celform::app {
namespace {

int runCamera(const Invocation& in)
{
    if (in.countSet({"turntable", "key", "clear", "list"}) != 1)
        throw UsageError{Cli::tr("exactly one of --turntable, --key, --clear or --list is required")};
    checkCameraPathOptions(in);
    if (in.isSet("json") && !in.isSet("list"))
        throw UsageError{Cli::tr("--json goes with --list")};

    const CameraPathEdit edit = readCameraPathEdit(in);

    const QString path = in.argument(0);
    if (in.isSet("list")) {
        const model::ProjectData data = model::loadProject(path, model::DrawingImages::Skip);
        const model::CameraPath& cameraPath = data.look.cameraPath;
        if (in.isSet("json")) {
            printJson({{"keys", model::cameraPathJson(cameraPath)}, {"fps", data.time.fps},
                {"frame_range", QJsonArray{data.time.firstFrame, data.time.lastFrame}}});
            return kExitOk;
        }
        QString text;
        QTextStream s(&text);
        if (cameraPath.empty())
            s << Cli::tr("No camera path: renders use the render camera.") << '\n';
        for (const model::CameraKey& k : cameraPath.keys)
            s << k.frame << '\t' << k.camera.eye.x() << ',' << k.camera.eye.y() << ',' << k.camera.eye.z() << '\t'
              << k.camera.target.x() << ',' << k.camera.target.y() << ',' << k.camera.target.z() << '\n';
        s.flush();
        printOut(text);
        return kExitOk;
    }

    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    applyCameraPathEdit(*doc, in, edit);
    doc->saveAs(path);
    return kExitOk;
}

std::vector<OptionSpec> cameraOptions()
{
    std::vector<OptionSpec> options = {
        {"turntable", "FRAMES",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Replace the path by a turntable: one revolution in FRAMES frames (also sets the frame range).")},
        {"axis", "X,Y,Z", QT_TRANSLATE_NOOP("celform::app::Cli", "Turntable axis (default 0,1,0).")},
        {"elevation", "DEG",
            QT_TRANSLATE_NOOP("celform::app::Cli", "Turntable camera height above the orbit plane (default 15).")},
        {"start", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Turntable's first frame (default 0).")},
        {"start-angle", "DEG", QT_TRANSLATE_NOOP("celform::app::Cli", "Turntable's angle at its first frame.")},
        {"key", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Key the camera given by the camera options at frame F.")},
        {"clear", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Remove the camera path.")},
        {"list", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Print the camera keys.")},
        {"json", nullptr, kJsonOption}};
    for (const OptionSpec& o : camera_options::specs())
        options.push_back(o);
    return options;
}

} // namespace

void checkCameraPathOptions(const Invocation& in)
{
    if (!in.isSet("turntable") && in.countSet({"axis", "elevation", "start", "start-angle"}) > 0)
        throw UsageError{Cli::tr("--axis, --elevation, --start and --start-angle go with --turntable only")};
    if (!in.isSet("key") && in.countSet({"view", "eye", "target", "up"}) > 0)
        throw UsageError{Cli::tr("camera options go with --key only")};
}

CameraPathEdit readCameraPathEdit(const Invocation& in)
{
    CameraPathEdit edit;
    if (in.isSet("turntable")) {
        edit.turntable.frames = parseInt("turntable", in.value("turntable"));
        if (edit.turntable.frames < 2 || edit.turntable.frames > model::kMaxFramesPerRender)
            throw UsageError{Cli::tr("--turntable takes 2 to %1 frames").arg(model::kMaxFramesPerRender)};
        if (in.isSet("axis"))
            edit.turntable.axis = parseDirection("axis", in.value("axis"));
        if (in.isSet("elevation"))
            edit.turntable.elevationDegrees = parseNumber("elevation", in.value("elevation"));
        if (in.isSet("start"))
            edit.turntable.startFrame = parseFrame("start", in.value("start"));
        if (in.isSet("start-angle"))
            edit.turntable.startDegrees = parseNumber("start-angle", in.value("start-angle"));
        const QString problem = model::turntableProblem(edit.turntable);
        if (!problem.isEmpty())
            throw UsageError{problem};
    }
    if (in.isSet("key")) {
        edit.keyFrame = parseFrame("key", in.value("key"));
        camera_options::checkCombination(in, true);
        if (camera_options::byCamera(in))
            edit.job.camera = camera_options::explicitCamera(in);
        else
            edit.job.view = camera_options::view(in);
    }
    return edit;
}

void applyCameraPathEdit(model::Document& doc, const Invocation& in, const CameraPathEdit& edit)
{
    if (in.isSet("turntable")) {
        doc.animation().makeTurntable(edit.turntable);
    } else if (in.isSet("key")) {
        // A view direction frames the model as `celform render --view` does.
        const model::Camera camera = model::renderJobCamera(doc.data(), doc.data().look, edit.job, edit.keyFrame);
        doc.animation().setCameraKey(edit.keyFrame, camera);
    } else {
        doc.animation().clearCameraPath();
    }
}

std::vector<SubCommand> cameraCommands()
{
    return {
        {"camera",
            {"celform camera P (--turntable FRAMES [--axis X,Y,Z] [--elevation DEG] [--start F] [--start-angle DEG] "
             "| --key F (--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z) | --clear | --list [--json])"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Edits the shot's camera path: a turntable, keyed cameras, clearing; renders and eval without camera "
                "options look through it."),
            {{"P", kProjectArgument}}, cameraOptions(), runCamera},
    };
}

} // namespace celform::app
