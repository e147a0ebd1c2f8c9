// `celform set` and `celform render`: the project's blend settings and look, and the display-free
// CPU renderer that draws them (DESIGN.md, "Rendering").
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/model/project_file.h"
#include "celform/model/render_output.h"
#include "celform/model/view_blend.h"

#include <QDir>
#include <QFileInfo>

#include <optional>

namespace celform::app {
namespace {

// Unqualified return types: lupdate misreads a qualified one as the context of Cli::tr() strings.
using model::TimeInterpolation;
using model::UnspecifiedMode;
using StereoOutput = algo::StereoOutput;

UnspecifiedMode parseUnspecified(const QString& text)
{
    if (text == QLatin1String("dummy"))
        return model::UnspecifiedMode::Dummy;
    if (text == QLatin1String("cosine"))
        return model::UnspecifiedMode::Cosine;
    if (text == QLatin1String("cosine2"))
        return model::UnspecifiedMode::Cosine2;
    throw UsageError{Cli::tr("--unspecified takes dummy, cosine or cosine2, not “%1”").arg(text)};
}

TimeInterpolation parseTime(const QString& text)
{
    if (text == QLatin1String("natural"))
        return model::TimeInterpolation::NaturalSpline;
    if (text == QLatin1String("periodic"))
        return model::TimeInterpolation::PeriodicSpline;
    throw UsageError{Cli::tr("--time takes natural or periodic, not “%1”").arg(text)};
}

StereoOutput parseStereo(const QString& text)
{
    const std::pair<const char*, algo::StereoOutput> modes[]
        = {{"off", algo::StereoOutput::Off}, {"anaglyph", algo::StereoOutput::Anaglyph},
            {"dubois", algo::StereoOutput::Dubois}, {"halfcolor", algo::StereoOutput::HalfColor},
            {"sbs", algo::StereoOutput::SideBySide}, {"tb", algo::StereoOutput::TopBottom}};
    for (const auto& [name, mode] : modes)
        if (text == QLatin1String(name))
            return mode;
    throw UsageError{Cli::tr("--stereo takes off, anaglyph, dubois, halfcolor, sbs or tb, not “%1”").arg(text)};
}

int runSet(const Invocation& in)
{
    if (in.countSet({"sharpness", "unspecified", "time", "light", "style", "render-view"}) == 0)
        throw UsageError{Cli::tr("nothing to set")};
    // Every option is parsed before the file is opened: a usage error changes nothing.
    std::optional<double> sharpness;
    if (in.isSet("sharpness")) {
        sharpness = parseNumber("sharpness", in.value("sharpness"));
        if (*sharpness <= 0)
            throw UsageError{Cli::tr("--sharpness must be positive")};
    }
    const auto unspecified = optionalValue(in, "unspecified", parseUnspecified);
    const auto time = optionalValue(in, "time", parseTime);
    const auto light = optionalValue(in, "light", [](const QString& v) { return parseLight("light", v); });
    const auto style = optionalValue(in, "style", [](const QString& v) { return parseStyle("style", v); });
    const bool removeRenderCamera = in.value("render-view") == QLatin1String("none");
    const auto renderView = removeRenderCamera
        ? std::nullopt
        : optionalValue(in, "render-view", [](const QString& v) { return parseDirection("render-view", v); });

    const QString path = in.argument(0);
    auto doc = openProject(path);
    // One document operation per property, as the editor's panels make them.
    if (sharpness)
        doc->setSharpness(*sharpness);
    if (unspecified)
        doc->setUnspecifiedMode(*unspecified);
    if (time)
        doc->setTimeInterpolation(*time);
    if (light)
        doc->setLight(*light);
    if (style)
        doc->setShadingStyle(*style);
    if (removeRenderCamera) {
        doc->setRenderCamera(std::nullopt);
    } else if (renderView) {
        if (!doc->hasMesh())
            throw model::IoError(path, Cli::tr("has no base model to frame a render camera on"));
        // Framed for the widest 16:9 shot; narrower ones fit too with the vertical fit.
        doc->setRenderCamera(cameraFromView(doc->data(), *renderView, 16.0 / 9.0));
    }
    doc->saveAs(path);
    return kExitOk;
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

int runRender(const Invocation& in)
{
    // Every option is checked before any work: a usage error renders nothing.
    camera_options::checkCombination(in, false);
    const bool byCamera = camera_options::byCamera(in);
    std::optional<model::Camera> explicitCamera;
    if (byCamera)
        explicitCamera = camera_options::explicitCamera(in);
    std::optional<Eigen::Vector3d> view;
    if (camera_options::byView(in))
        view = camera_options::view(in);
    if (in.isSet("frame") && in.isSet("frames"))
        throw UsageError{Cli::tr("give either --frame or --frames")};
    int firstFrame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    int lastFrame = firstFrame;
    if (in.isSet("frames"))
        std::tie(firstFrame, lastFrame) = parseFrameRange("frames", in.value("frames"));
    const QSize imageSize = in.isSet("size") ? parseSize("size", in.value("size")) : QSize(1280, 720);
    const auto style = optionalValue(in, "style", [](const QString& v) { return parseStyle("style", v); });
    const auto lines = optionalValue(in, "lines", [](const QString& v) { return parseOnOff("lines", v); });
    const auto light = optionalValue(in, "light", [](const QString& v) { return parseLight("light", v); });
    const algo::StereoOutput stereo = in.isSet("stereo") ? parseStereo(in.value("stereo")) : algo::StereoOutput::Off;
    const QString pass = in.value("pass");
    if (in.isSet("pass") && !model::renderPassNames().contains(pass))
        throw UsageError{
            Cli::tr("--pass takes one of %1, not “%2”").arg(model::renderPassNames().join(QStringLiteral(", ")), pass)};
    if (stereo != algo::StereoOutput::Off && in.isSet("pass") && pass != QLatin1String("beauty"))
        throw UsageError{Cli::tr("a stereo render writes the beauty pass only")};
    const QString path = in.argument(0);
    const QString outPattern = in.isSet("out")
        ? in.value("out")
        : QFileInfo(path).dir().filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".png"));
    const QString suffix = QFileInfo(outPattern).suffix().toLower();
    if (!QStringList{QStringLiteral("png"), QStringLiteral("exr"), QStringLiteral("tif"), QStringLiteral("tiff"),
            QStringLiteral("jpg"), QStringLiteral("jpeg")}
             .contains(suffix))
        throw UsageError{Cli::tr("--out must end in .png, .exr, .tif or .jpg, not “%1”").arg(outPattern)};
    // Two eyes in stereo; an EXR of every pass adds a float copy of the passes (measured).
    const bool allPasses = suffix == QLatin1String("exr") && !in.isSet("pass") && stereo == algo::StereoOutput::Off;
    const qint64 bytesPerPixel
        = kRenderBytesPerPixel * (stereo == algo::StereoOutput::Off ? 1 : 2) + (allPasses ? 32 : 0);
    checkRenderMemory("size", QStringLiteral("%1x%2").arg(imageSize.width()).arg(imageSize.height()),
        qint64(imageSize.width()) * imageSize.height() * bytesPerPixel);

    // A render reads the project and writes pictures; the overrides apply to this render only.
    const model::ProjectData data = model::loadProject(path);
    if (!data.baseMesh)
        throw model::IoError(path, Cli::tr("has no base model"));
    model::Look look = data.look;
    if (style) {
        look.style = *style;
        look.materialStyles.clear();
    }
    if (lines)
        look.showLines = *lines;
    if (light)
        look.light = *light;
    // Without camera options: the project's render camera, else a framed view from (0.35, 0.25, 1).
    const model::Camera camera = explicitCamera ? *explicitCamera
        : !view && look.renderCamera            ? *look.renderCamera
                                                : cameraFromView(data, view.value_or(Eigen::Vector3d(0.35, 0.25, 1.0)),
                                                    double(imageSize.width()) / imageSize.height());

    model::BlendEvaluator blender;
    QString error;
    if (!blender.update(data, &error))
        throw model::IoError(path, error);
    const Eigen::Vector3d direction = blender.viewDirection(data, camera.eye);
    algo::RenderCache cache;
    const bool sequence = lastFrame > firstFrame;
    // The shape keeps its generation while frames leave it still, so highlight geometry is reused.
    algo::Shape shape;
    algo::Positions next;
    for (int f = firstFrame; f <= lastFrame; ++f) {
        blender.shape(data, direction, f, next);
        if (shape.generation == 0 || next.rows() != shape.positions.rows() || next != shape.positions) {
            shape.positions.swap(next);
            shape.touch();
        }
        const algo::RenderPasses passes = model::renderShape(data, look, shape.positions, f, camera, imageSize.width(),
            imageSize.height(), stereo, cache, shape.generation);
        const QString target = framePath(outPattern, f, sequence);
        if (allPasses)
            model::writePassesExr(passes, target);
        else
            model::writeImage(model::passImage(passes, in.isSet("pass") ? pass : QStringLiteral("beauty"),
                                  suffix == QLatin1String("exr")),
                target);
    }
    return kExitOk;
}

} // namespace

std::vector<SubCommand> lookCommands()
{
    const char* const lightDescription
        = QT_TRANSLATE_NOOP("celform::app::Cli", "Key light: a point position or a direction towards the light.");
    std::vector<OptionSpec> renderOptions = camera_options::specs();
    const std::vector<OptionSpec> more
        = {{"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame to render (default 0).")},
            {"frames", "A-B", QT_TRANSLATE_NOOP("celform::app::Cli", "Frames to render, A-B inclusive.")},
            {"size", "WxH", QT_TRANSLATE_NOOP("celform::app::Cli", "Image size (default 1280x720).")},
            {"style", "STYLE", QT_TRANSLATE_NOOP("celform::app::Cli", "Shading style for this render.")},
            {"lines", "on|off", QT_TRANSLATE_NOOP("celform::app::Cli", "Draw the lines (on) or not (off).")},
            {"light", "TYPE:X,Y,Z", QT_TRANSLATE_NOOP("celform::app::Cli", "Key light for this render.")},
            {"stereo", "MODE", QT_TRANSLATE_NOOP("celform::app::Cli", "Stereo output.")},
            {"pass", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "Write one render pass.")},
            {"out", "FILE",
                QT_TRANSLATE_NOOP("celform::app::Cli", "Output image (default: the project's name with .png).")}};
    renderOptions.insert(renderOptions.end(), more.begin(), more.end());
    return {
        {"set",
            {"celform set P [--sharpness A] [--unspecified dummy|cosine|cosine2] [--time natural|periodic] "
             "[--light point:X,Y,Z|directional:X,Y,Z] [--style toon|gooch|comic|lambert] [--render-view X,Y,Z|none]"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Changes project settings."), {{"P", kProjectArgument}},
            {{"sharpness", "A", QT_TRANSLATE_NOOP("celform::app::Cli", "Blend sharpness alpha (> 0).")},
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
                        "removes it.")}},
            runSet},
        {"render",
            {"celform render P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F | --frames A-B] "
             "[--size WxH] [--style toon|gooch|comic|lambert] [--lines on|off] "
             "[--light point:X,Y,Z|directional:X,Y,Z] [--stereo off|anaglyph|dubois|halfcolor|sbs|tb] "
             "[--pass beauty|lines|tone|highlights|depth|normal|id] [--out FILE.png|.exr|.tif|.jpg]"},
            QT_TRANSLATE_NOOP("celform::app::Cli", "Renders the project's look without a display (CPU renderer)."),
            {{"P", kProjectArgument}}, renderOptions, runRender},
    };
}

} // namespace celform::app
