// `celform set` and `celform render`: the project's blend settings and look, and the display-free
// CPU renderer that draws them (DESIGN.md, "Rendering").
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/document/document.h"
#include "celform/model/render/frame_schedule.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/image_io.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QThread>

#include <algorithm>
#include <optional>

namespace celform::app {
namespace {

// Unqualified return types: lupdate misreads a qualified one as the context of Cli::tr() strings.
using model::RenderJob;
using model::TimeInterpolation;
using model::UnspecifiedMode;
using StereoOutput = algo::StereoOutput;

UnspecifiedMode parseUnspecified(const QString& text)
{
    const std::pair<const char*, UnspecifiedMode> modes[] = {{"dummy", model::UnspecifiedMode::Dummy},
        {"cosine", model::UnspecifiedMode::Cosine}, {"cosine2", model::UnspecifiedMode::Cosine2}};
    return parseChoice(text, modes, Cli::tr("--unspecified takes dummy, cosine or cosine2, not “%1”"));
}

TimeInterpolation parseTime(const QString& text)
{
    const std::pair<const char*, TimeInterpolation> modes[] = {
        {"natural", model::TimeInterpolation::NaturalSpline}, {"periodic", model::TimeInterpolation::PeriodicSpline}};
    return parseChoice(text, modes, Cli::tr("--time takes natural or periodic, not “%1”"));
}

int runSet(const Invocation& in)
{
    // Every option is parsed before the file is opened: a usage error changes nothing.
    const ProjectSettings settings = readProjectSettings(in);
    const QString path = in.argument(0);
    auto doc = openProject(path);
    applyProjectSettings(*doc, settings, path, printErr);
    doc->saveAs(path);
    return kExitOk;
}

/// The vector-line options of `celform render` (docs/lines.md, "Vector lines"): an .svg output
/// is the lines pass as strokes, --svg-tones adds the tone regions to it, --strokes writes the
/// strokes' JSON of the lines pass. job.output and job.pass are read already.
void readVectorLineOptions(const Invocation& in, model::RenderJob& job)
{
    if (job.writesVectorLines()) {
        if (!in.isSet("pass"))
            job.pass = QStringLiteral("lines");
        if (job.pass != QLatin1String("lines"))
            throw UsageError{Cli::tr("an .svg output holds the lines pass; give --pass lines, not “%1”").arg(job.pass)};
        const QList<algo::StereoOutput> eyes = {algo::StereoOutput::Off, algo::StereoOutput::SideBySide,
            algo::StereoOutput::TopBottom, algo::StereoOutput::Anaglyph};
        if (!eyes.contains(job.stereo))
            throw UsageError{Cli::tr("an .svg output takes --stereo off, sbs, tb or anaglyph")};
    }
    job.svgTones = in.isSet("svg-tones");
    if (job.svgTones && !job.writesVectorLines())
        throw UsageError{Cli::tr("--svg-tones needs an .svg output")};
    job.strokesOutput = in.value("strokes");
    if (in.isSet("strokes")) {
        if (job.pass != QLatin1String("lines"))
            throw UsageError{Cli::tr("--strokes needs the lines pass (--pass lines)")};
        if (QFileInfo(job.strokesOutput).suffix().toLower() != QLatin1String("json"))
            throw UsageError{Cli::tr("--strokes must end in .json, not “%1”").arg(job.strokesOutput)};
        if (job.stereo != algo::StereoOutput::Off && !job.writesVectorLines())
            throw UsageError{Cli::tr("a stereo render writes its strokes beside an .svg output only")};
    }
}

int runRender(const Invocation& in)
{
    // Every option is checked before any work: a usage error renders nothing.
    model::RenderJob job = readRenderJob(in);
    const QString path = in.argument(0);
    job.output = in.isSet("out")
        ? in.value("out")
        : QFileInfo(path).dir().filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".png"));
    readRenderOutputs(in, job);
    const QString size = QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height());
    const int wanted = std::min(job.threads, job.frameCount());
    const qint64 available = model::availableRenderMemory();
    job.threads = model::concurrentFrames(job, available);
    if (job.threads < wanted)
        printErr(Cli::tr("warning: rendering %1 frames at a time, not %2: each needs about %3 GB of memory at %4, "
                         "and %5 GB are available")
                     .arg(job.threads)
                     .arg(wanted)
                     .arg(double(job.bytesNeeded() + model::kRenderThreadOverheadBytes) / 1e9, 0, 'f', 2)
                     .arg(size)
                     .arg(double(available) / 1e9, 0, 'f', 2));

    // One line per frame on standard error as it is done; the listener is told one at a time.
    const int count = job.frameCount();
    struct FrameLines : model::RenderFrameListener {
        int count = 0;
        int done = 0;
        QJsonArray written, skipped;
        void frameDone(int frame, const QString& file, bool skip) override
        {
            ++done;
            if (skip)
                printErr(Cli::tr("frame %1 (%2/%3) skipped: %4 exists").arg(frame).arg(done).arg(count).arg(file));
            else
                printErr(Cli::tr("frame %1 (%2/%3) -> %4").arg(frame).arg(done).arg(count).arg(file));
            (skip ? skipped : written).append(QJsonObject{{"frame", frame}, {"file", file}});
        }
    } lines;
    lines.count = count;
    // A render reads the project and writes pictures; the overrides apply to this render only. The
    // drawings are not in the picture: their pixels are not decoded (nor OpenImageIO loaded for them,
    // issue 29), but a drawing that opening the project would refuse is refused here too, as by info.
    const model::ProjectData data = model::loadProject(path, model::DrawingImages::Skip);
    for (const auto& d : data.drawings)
        model::decodedImageSize(d.imageData, d.imageFormat, QStringLiteral("%1 (%2)").arg(path, d.name));
    try {
        model::renderFrames(data, path, job, nullptr, &lines);
    } catch (const model::RenderFrameError& e) {
        printErr(QStringLiteral("celform: ") + Cli::tr("frame %1: %2").arg(e.frame()).arg(e.message()));
        return kExitBadInput;
    }
    if (in.isSet("json"))
        printJson(renderJobJson(job, lines.written, lines.skipped));
    return kExitOk;
}

} // namespace

StereoOutput parseStereo(const QString& text)
{
    const std::pair<const char*, algo::StereoOutput> modes[]
        = {{"off", algo::StereoOutput::Off}, {"anaglyph", algo::StereoOutput::Anaglyph},
            {"dubois", algo::StereoOutput::Dubois}, {"halfcolor", algo::StereoOutput::HalfColor},
            {"sbs", algo::StereoOutput::SideBySide}, {"tb", algo::StereoOutput::TopBottom}};
    return parseChoice(text, modes, Cli::tr("--stereo takes off, anaglyph, dubois, halfcolor, sbs or tb, not “%1”"));
}

ProjectSettings readProjectSettings(const Invocation& in)
{
    if (in.countSet({"sharpness", "unspecified", "time", "light", "style", "render-view", "subdivision",
            "viewport-subdivision"})
        == 0)
        throw UsageError{Cli::tr("nothing to set")};
    ProjectSettings settings;
    if (in.isSet("sharpness")) {
        settings.sharpness = parseNumber("sharpness", in.value("sharpness"));
        if (!(*settings.sharpness > 0 && *settings.sharpness <= model::kMaxSharpness))
            throw UsageError{Cli::tr("--sharpness must be above 0 and at most %1").arg(model::kMaxSharpness)};
    }
    settings.unspecified = optionalValue(in, "unspecified", parseUnspecified);
    settings.time = optionalValue(in, "time", parseTime);
    settings.light = optionalValue(in, "light", [](const QString& v) { return parseLight("light", v); });
    settings.style = optionalValue(in, "style", [](const QString& v) { return parseStyle("style", v); });
    settings.removeRenderCamera = in.value("render-view") == QLatin1String("none");
    settings.renderView = settings.removeRenderCamera
        ? std::nullopt
        : optionalValue(in, "render-view", [](const QString& v) { return parseDirection("render-view", v); });

    settings.subdivision
        = optionalValue(in, "subdivision", [](const QString& v) { return parseSubdivision("subdivision", v); });
    settings.viewportSubdivision = optionalValue(
        in, "viewport-subdivision", [](const QString& v) { return parseSubdivision("viewport-subdivision", v, true); });
    return settings;
}

void applyProjectSettings(model::Document& doc, const ProjectSettings& settings, const QString& path,
    const std::function<void(const QString&)>& warn)
{
    // One document operation per property, as the editor's panels make them.
    if (settings.subdivision || settings.viewportSubdivision) {
        model::SubdivisionLook s = doc.data().look.subdivision;
        s.level = settings.subdivision.value_or(s.level);
        s.viewportLevel = settings.viewportSubdivision.value_or(s.viewportLevel);
        if (s.viewportLevel > s.level)
            warn(Cli::tr("warning: the viewport's subdivision level %1 is above the render level %2; the "
                         "viewport shows level %2")
                     .arg(s.viewportLevel)
                     .arg(s.level));
        doc.look().setSubdivision(s);
    }
    if (settings.sharpness)
        doc.look().setSharpness(*settings.sharpness);
    if (settings.unspecified)
        doc.look().setUnspecifiedMode(*settings.unspecified);
    if (settings.time)
        doc.look().setTimeInterpolation(*settings.time);
    if (settings.light)
        doc.look().setLight(*settings.light);
    if (settings.style)
        doc.look().setShadingStyle(*settings.style);
    if (settings.removeRenderCamera) {
        doc.look().setRenderCamera(std::nullopt);
    } else if (settings.renderView) {
        if (!doc.hasMesh())
            throw model::IoError(path, Cli::tr("has no base model to frame a render camera on"));
        // Framed for the widest 16:9 shot; narrower ones fit too with the vertical fit.
        doc.look().setRenderCamera(model::cameraFromView(doc.data(), *settings.renderView, 16.0 / 9.0));
    }
}

RenderJob readRenderJob(const Invocation& in)
{
    if (in.isSet("frame") && in.isSet("frames"))
        throw UsageError{Cli::tr("give either --frame or --frames")};
    model::RenderJob job;
    readPictureOptions(in, job);
    if (in.isSet("frames")) {
        const FrameRange range = parseFrameRange("frames", in.value("frames"));
        job.firstFrame = range.first;
        job.lastFrame = range.last;
        job.step = range.step;
    }
    job.threads = QThread::idealThreadCount();
    if (in.isSet("threads")) {
        job.threads = parseInt("threads", in.value("threads"));
        if (job.threads < 1)
            throw UsageError{
                Cli::tr("--threads takes a whole number of at least 1, not “%1”").arg(in.value("threads"))};
    }
    job.skipExisting = in.isSet("skip-existing");
    job.stereo = in.isSet("stereo") ? parseStereo(in.value("stereo")) : algo::StereoOutput::Off;
    job.pass = in.value("pass");
    if (in.isSet("pass") && !model::renderPassNames().contains(job.pass))
        throw UsageError{Cli::tr("--pass takes one of %1, not “%2”")
                             .arg(model::renderPassNames().join(QStringLiteral(", ")), job.pass)};
    return job;
}

void readRenderOutputs(const Invocation& in, model::RenderJob& job)
{
    readVectorLineOptions(in, job);
    if (job.stereo != algo::StereoOutput::Off && in.isSet("pass") && job.pass != QLatin1String("beauty")
        && !job.writesVectorLines())
        throw UsageError{Cli::tr("a stereo render writes the beauty pass only")};
    if (!model::renderSuffixes().contains(QFileInfo(job.output).suffix().toLower()) && !job.writesVectorLines())
        throw UsageError{Cli::tr("--out must end in .png, .exr, .tif, .jpg or .svg, not “%1”").arg(job.output)};
    // A farm's chunk of one frame (--frames 100-100) is named as the same frame of a longer range.
    auto numbered = [&](const QString& pattern) {
        if (!in.isSet("frames") || pattern.isEmpty() || pattern.contains(QLatin1Char('#')))
            return pattern;
        const QFileInfo out(pattern);
        return out.dir().filePath(out.completeBaseName() + QStringLiteral("_####.") + out.suffix());
    };
    job.output = numbered(job.output);
    job.strokesOutput = numbered(job.strokesOutput);
    const QString size = QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height());
    checkRenderMemory("size", size, job.bytesNeeded());
}

QJsonObject renderJobJson(const model::RenderJob& job, const QJsonArray& written, const QJsonArray& skipped)
{
    // In frame order, whichever thread finished first.
    auto byFrame = [](QJsonArray frames) {
        std::vector<QJsonValue> sorted(frames.begin(), frames.end());
        std::sort(sorted.begin(), sorted.end(),
            [](const QJsonValue& a, const QJsonValue& b) { return a["frame"].toInt() < b["frame"].toInt(); });
        QJsonArray out;
        for (const QJsonValue& v : sorted)
            out.append(v);
        return out;
    };
    return {{"first", job.firstFrame}, {"last", job.lastFrame}, {"step", job.step}, {"count", job.frameCount()},
        {"size", QJsonArray{job.size.width(), job.size.height()}}, {"threads", job.threads},
        {"written", byFrame(written)}, {"skipped", byFrame(skipped)}};
}

std::vector<SubCommand> lookCommands()
{
    const char* const lightDescription
        = QT_TRANSLATE_NOOP("celform::app::Cli", "Key light: a point position or a direction towards the light.");
    std::vector<OptionSpec> renderOptions = camera_options::specs();
    const std::vector<OptionSpec> more
        = {{"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame to render (default 0).")},
            {"frames", "A-B[:STEP]",
                QT_TRANSLATE_NOOP("celform::app::Cli",
                    "Frames to render, A-B inclusive, every STEP-th from A (default 1); each to a file of its own "
                    "(a # in --out, or _####, is the frame number).")},
            {"size", "WxH", QT_TRANSLATE_NOOP("celform::app::Cli", "Image size (default 1280x720).")}};
    const std::vector<OptionSpec> look = lookOverrideSpecs();
    const std::vector<OptionSpec> rest = {{"stereo", "MODE", QT_TRANSLATE_NOOP("celform::app::Cli", "Stereo output.")},
        {"pass", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "Write one render pass.")},
        {"out", "FILE",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Output image (default: the project's name with .png); an .svg holds the lines pass as vector "
                "strokes.")},
        {"svg-tones", nullptr,
            QT_TRANSLATE_NOOP("celform::app::Cli", "With an .svg output: the tone regions as filled layers too.")},
        {"strokes", "FILE.json",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "With --pass lines: each stroke's points, widths, kind and depth as JSON too (a # is the frame "
                "number, as in --out).")},
        {"threads", "N",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Frames rendered at once (default: one per processor; fewer when memory is short). The "
                "files are the same for any N.")},
        {"skip-existing", nullptr,
            QT_TRANSLATE_NOOP(
                "celform::app::Cli", "Leave frames whose file exists as they are (to resume an interrupted render).")},
        {"json", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Print the frames written and skipped as JSON.")}};
    for (const auto* part : {&more, &look, &rest})
        renderOptions.insert(renderOptions.end(), part->begin(), part->end());
    return {
        {"set",
            {"celform set P [--sharpness A] [--unspecified dummy|cosine|cosine2] [--time natural|periodic] "
             "[--light point:X,Y,Z|directional:X,Y,Z] [--style toon|gooch|comic|lambert] [--render-view X,Y,Z|none] "
             "[--subdivision N] [--viewport-subdivision N]"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Changes project settings."), {{"P", kProjectArgument}},
            {{"sharpness", "A",
                 QT_TRANSLATE_NOOP("celform::app::Cli", "Blend sharpness alpha (above 0, at most 100).")},
                {"unspecified", "MODE", QT_TRANSLATE_NOOP("celform::app::Cli", "Unspecified-region mode.")},
                {"time", "natural|periodic",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Interpolation of key deformations over frames: natural (cubic spline, held outside the "
                        "keyed frames) or periodic (a looping cycle).")},
                {"light", "TYPE:X,Y,Z", lightDescription},
                {"style", "STYLE", QT_TRANSLATE_NOOP("celform::app::Cli", "Shading style.")},
                {"render-view", "X,Y,Z|none",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "The render camera: looking at the model's centroid from this direction, framed; none "
                        "removes it.")},
                {"subdivision", "N",
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Loop subdivision level that renders use, 0 (the control mesh) to 3.")},
                {"viewport-subdivision", "N",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "The viewport's subdivision level: -1 follows the render level; a lower level is a "
                        "speed setting.")}},
            runSet},
        {"render",
            {"celform render P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F | --frames "
             "A-B[:STEP]] [--size WxH] [--style toon|gooch|comic|lambert] [--lines on|off|KIND,...] "
             "[--ridge-threshold T] [--ridges snakes|raw] [--ridge-depth K] [--light point:X,Y,Z|directional:X,Y,Z] "
             "[--subdivision N] "
             "[--stereo off|anaglyph|dubois|halfcolor|sbs|tb] "
             "[--pass beauty|lines|tone|highlights|depth|normal|id|segments|curvature|depth-error] [--out "
             "FILE.png|.exr|.tif|.jpg|.svg] [--svg-tones] [--strokes FILE.json] [--threads N] [--skip-existing] "
             "[--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Renders the project's look without a display (CPU renderer)."),
            {{"P", kProjectArgument}}, renderOptions, runRender},
    };
}

} // namespace celform::app
