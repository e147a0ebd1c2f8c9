// Option values of the sub-commands. Bounds follow what the project file accepts when it reads
// the value back (finite numbers, unit directions, frames within kMaxFrame), so a usage error is
// raised here rather than a file written that cannot be opened.
#include "cli/options.h"

#include "celform/algorithms/lines.h"
#include "celform/algorithms/subdivision.h"

#include <QFile>
#include <QRegularExpression>

#include <algorithm>
#include <iterator>
#include <utility>
#include <cmath>
#include <limits>

#include <sys/stat.h>

namespace celform::app {

// Unqualified return types below: lupdate misreads a qualified one as the context of the
// function's Cli::tr() strings.
using VectorX = Eigen::VectorXd;
using Vector3 = Eigen::Vector3d;
using Vector3f = Eigen::Vector3f;
using model::Camera;
using model::Light;
using model::ShadingStyle;

namespace {

QString dashed(const char* option)
{
    return QStringLiteral("--") + QLatin1String(option);
}

bool finiteAsFloat(double v)
{
    return std::isfinite(v) && std::abs(v) <= double(std::numeric_limits<float>::max());
}

/// Whether a vector normalises: its length is a finite, non-zero number (1e308,1e308,0 overflows).
template <typename Vector> bool normalisable(const Vector& v)
{
    const auto length = v.norm();
    return v.allFinite() && std::isfinite(length) && length > 0 && (v / length).allFinite();
}

} // namespace

VectorX parseNumbers(const char* option, const QString& text, int count)
{
    const QStringList parts = text.split(QLatin1Char(','));
    Eigen::VectorXd v(count);
    bool ok = parts.size() == count;
    for (int i = 0; ok && i < count; ++i)
        v[i] = parts[i].trimmed().toDouble(&ok);
    if (!ok || !v.allFinite()) {
        const QString o = QLatin1String(option);
        throw UsageError{count == 3 ? Cli::tr("--%1 needs three numbers X,Y,Z, not “%2”").arg(o, text)
                : count == 4        ? Cli::tr("--%1 needs four numbers X,Y,Z,R, not “%2”").arg(o, text)
                                    : Cli::tr("--%1 needs two numbers A,B, not “%2”").arg(o, text)};
    }
    return v;
}

VectorX parseFloats(const char* option, const QString& text, int count)
{
    const Eigen::VectorXd v = parseNumbers(option, text, count);
    for (int i = 0; i < count; ++i)
        if (!finiteAsFloat(v[i]))
            throw UsageError{Cli::tr("%1: “%2” is too large").arg(dashed(option), text)};
    return v;
}

double parseNumber(const char* option, const QString& text)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        throw UsageError{Cli::tr("--%1 needs a number, not “%2”").arg(QLatin1String(option), text)};
    return v;
}

double parseFloat(const char* option, const QString& text)
{
    const double v = parseNumber(option, text);
    if (!finiteAsFloat(v))
        throw UsageError{Cli::tr("%1: “%2” is too large").arg(dashed(option), text)};
    return v;
}

int parseInt(const char* option, const QString& text)
{
    bool ok = false;
    const int v = text.trimmed().toInt(&ok);
    if (!ok)
        throw UsageError{Cli::tr("--%1 needs a whole number, not “%2”").arg(QLatin1String(option), text)};
    return v;
}

int parseSubdivision(const char* option, const QString& text, bool allowSame)
{
    bool ok = false;
    const int v = text.trimmed().toInt(&ok);
    if (!ok || v < (allowSame ? -1 : 0) || v > algo::kMaxSubdivisionLevel)
        throw UsageError{(allowSame ? Cli::tr("--%1 takes -1 (the render level) or a level from 0 to %2, not “%3”")
                                    : Cli::tr("--%1 takes a subdivision level from 0 to %2, not “%3”"))
                             .arg(QLatin1String(option))
                             .arg(algo::kMaxSubdivisionLevel)
                             .arg(text)};
    return v;
}

int parseFrame(const char* option, const QString& text)
{
    bool ok = false;
    const int v = text.trimmed().toInt(&ok);
    if (!ok || std::abs(qint64(v)) > model::kMaxFrame)
        throw UsageError{Cli::tr("%1 takes a frame number between -%2 and %2, not “%3”")
                             .arg(dashed(option))
                             .arg(model::kMaxFrame)
                             .arg(text)};
    return v;
}

FrameRange parseFrameRange(const char* option, const QString& text)
{
    static const QRegularExpression form(QStringLiteral("^\\s*(-?\\d+)\\s*-\\s*(-?\\d+)\\s*(?::\\s*(\\d+)\\s*)?$"));
    const QRegularExpressionMatch m = form.match(text);
    bool okA = false, okB = false, okStep = true;
    const qint64 first = m.hasMatch() ? m.captured(1).toLongLong(&okA) : 0;
    const qint64 last = m.hasMatch() ? m.captured(2).toLongLong(&okB) : 0;
    const qint64 step = m.hasMatch() && m.hasCaptured(3) ? m.captured(3).toLongLong(&okStep) : 1;
    if (!okA || !okB || !okStep || last < first || step < 1)
        throw UsageError{
            Cli::tr("%1 takes A-B or A-B:STEP with A <= B and STEP >= 1, not “%2”").arg(dashed(option), text)};
    if (std::abs(first) > model::kMaxFrame || std::abs(last) > model::kMaxFrame)
        throw UsageError{Cli::tr("%1 takes frame numbers between -%2 and %2, not “%3”")
                             .arg(dashed(option))
                             .arg(model::kMaxFrame)
                             .arg(text)};
    if ((last - first) / step + 1 > kMaxFramesPerRun)
        throw UsageError{Cli::tr("%1 takes at most %2 frames at a time, not “%3”")
                             .arg(dashed(option))
                             .arg(kMaxFramesPerRun)
                             .arg(text)};
    // A step beyond the range gives its first frame alone, as the range length does (and fits an int).
    return {int(first), int(last), int(std::min(step, last - first + 1))};
}

QSize parseSize(const char* option, const QString& text)
{
    static_assert(kMaxRenderSide == 16384, "the message below names the limit");
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = parts.size() == 2 ? parts[0].toInt(&okW) : 0;
    const int h = parts.size() == 2 ? parts[1].toInt(&okH) : 0;
    if (!okW || !okH || w < 1 || h < 1 || w > kMaxRenderSide || h > kMaxRenderSide)
        throw UsageError{Cli::tr("--size takes WIDTHxHEIGHT between 1 and 16384, not “%1”").arg(text)};
    // 16384 x 16384 needs about 24 GB: the sides alone do not bound what a render holds.
    if (qint64(w) * h > kMaxRenderPixels)
        throw UsageError{Cli::tr("%1 takes at most %2 pixels (8192x8192: the renderer holds %3 bytes a pixel), not "
                                 "“%4”")
                             .arg(dashed(option))
                             .arg(kMaxRenderPixels)
                             .arg(kRenderBytesPerPixel)
                             .arg(text)};
    return {w, h};
}

void checkRenderMemory(const char* option, const QString& text, qint64 bytes)
{
    const qint64 available = model::availableRenderMemory();
    if (bytes > available)
        throw UsageError{Cli::tr("%1 %2 needs about %3 GB of memory to render, and %4 GB are available")
                             .arg(dashed(option), text)
                             .arg(double(bytes) / 1e9, 0, 'f', 1)
                             .arg(double(std::max<qint64>(available, 0)) / 1e9, 0, 'f', 1)};
}

std::optional<model::MirrorPlane> parseMirror(const char* option, const QString& text)
{
    if (text == QLatin1String("auto"))
        return std::nullopt;
    const std::optional<model::MirrorPlane> chosen = model::mirrorPlaneFromName(text);
    if (!chosen || text != text.toLower())
        throw UsageError{Cli::tr("--%1 must be auto, x, y, z or off, not “%2”").arg(QLatin1String(option), text)};
    return chosen;
}

bool parseOnOff(const char* option, const QString& text)
{
    if (text != QLatin1String("on") && text != QLatin1String("off"))
        throw UsageError{Cli::tr("%1 takes on or off, not “%2”").arg(dashed(option), text)};
    return text == QLatin1String("on");
}

std::uint8_t parseLineKinds(const char* option, const QString& text)
{
    static const std::pair<const char*, std::uint8_t> kinds[]
        = {{"silhouette", algo::kSilhouette}, {"crease", algo::kCrease}, {"border", algo::kBorder},
            {"material", algo::kMaterialBoundary}, {"ridge", algo::kRidge}};
    std::uint8_t bits = 0;
    const QStringList words = text.split(QLatin1Char(','));
    for (const QString& word : words) {
        const auto hit = std::find_if(std::begin(kinds), std::end(kinds),
            [&](const auto& k) { return word.trimmed() == QLatin1String(k.first); });
        if (hit == std::end(kinds))
            throw UsageError{Cli::tr("%1 takes on, off or a comma-separated list of silhouette, crease, border, "
                                     "material and ridge, not “%2”")
                                 .arg(dashed(option), text)};
        bits |= hit->second;
    }
    return bits;
}

Vector3 parsePoint(const char* option, const QString& text)
{
    return parseNumbers(option, text, 3);
}

Vector3 parseDirection(const char* option, const QString& text)
{
    const Eigen::Vector3d v = parsePoint(option, text);
    if (!normalisable(v))
        throw UsageError{Cli::tr("%1 needs a direction: not zero, and short enough that its length is a number, "
                                 "not “%2”")
                             .arg(dashed(option), text)};
    return v;
}

Vector3f parseFloatDirection(const char* option, const QString& text)
{
    const Eigen::Vector3d v = parseDirection(option, text);
    const Eigen::Vector3f f = v.cast<float>();
    if (!finiteAsFloat(v.cwiseAbs().maxCoeff()) || !normalisable(f))
        throw UsageError{Cli::tr("%1 needs a direction: not zero, and short enough that its length is a number, "
                                 "not “%2”")
                             .arg(dashed(option), text)};
    return f;
}

Light parseLight(const char* option, const QString& text)
{
    const int colon = int(text.indexOf(QLatin1Char(':')));
    const QString type = text.left(colon);
    if (colon < 0 || (type != QLatin1String("point") && type != QLatin1String("directional")))
        throw UsageError{Cli::tr("--light takes point:X,Y,Z or directional:X,Y,Z, not “%1”").arg(text)};
    model::Light light;
    if (type == QLatin1String("point")) {
        light.type = model::LightType::Point;
        light.vector = parsePoint(option, text.mid(colon + 1));
    } else {
        light.type = model::LightType::Directional;
        light.vector = parseDirection(option, text.mid(colon + 1)).normalized();
    }
    return light;
}

ShadingStyle parseStyle(const char* option, const QString& text)
{
    Q_UNUSED(option);
    const std::pair<const char*, model::ShadingStyle> styles[]
        = {{"toon", model::ShadingStyle::Toon}, {"gooch", model::ShadingStyle::Gooch},
            {"comic", model::ShadingStyle::Comic}, {"lambert", model::ShadingStyle::Lambert}};
    return parseChoice(text, styles, Cli::tr("--style takes toon, gooch, comic or lambert, not “%1”"));
}

bool sameFile(const QString& a, const QString& b)
{
    struct stat sa {
    }, sb{};
    return ::stat(QFile::encodeName(a).constData(), &sa) == 0 && ::stat(QFile::encodeName(b).constData(), &sb) == 0
        && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

namespace camera_options {

std::vector<OptionSpec> specs()
{
    return {{"view", "X,Y,Z",
                QT_TRANSLATE_NOOP("celform::app::Cli", "View direction from the model's centroid towards the eye.")},
        {"eye", "X,Y,Z", QT_TRANSLATE_NOOP("celform::app::Cli", "Camera position.")},
        {"target", "X,Y,Z", QT_TRANSLATE_NOOP("celform::app::Cli", "Point the camera looks at.")},
        {"up", "X,Y,Z", QT_TRANSLATE_NOOP("celform::app::Cli", "Camera up vector.")}};
}

bool byView(const Invocation& in)
{
    return in.isSet("view");
}

bool byCamera(const Invocation& in)
{
    return in.countSet({"eye", "target", "up"}) > 0;
}

void checkCombination(const Invocation& in, bool required)
{
    const int explicitCount = in.countSet({"eye", "target", "up"});
    if (byView(in) && explicitCount > 0)
        throw UsageError{Cli::tr("give either --view or --eye, --target and --up")};
    if (explicitCount > 0 && explicitCount < 3)
        throw UsageError{Cli::tr("--eye, --target and --up go together")};
    if (required && !byView(in) && explicitCount == 0)
        throw UsageError{Cli::tr("give either --view or all of --eye, --target and --up")};
}

Camera explicitCamera(const Invocation& in)
{
    model::Camera camera;
    camera.eye = parsePoint("eye", in.value("eye"));
    camera.target = parsePoint("target", in.value("target"));
    camera.up = parseDirection("up", in.value("up"));
    // isValid() also refuses an eye so far from the target that their distance overflows.
    if (!camera.isValid())
        throw UsageError{Cli::tr("--eye, --target and --up do not make a camera (eye equals target, or up is "
                                 "parallel to the view)")};
    return camera;
}

Vector3 view(const Invocation& in)
{
    return parseDirection("view", in.value("view"));
}

} // namespace camera_options

std::vector<OptionSpec> lookOverrideSpecs()
{
    return {{"style", "STYLE",
                QT_TRANSLATE_NOOP("celform::app::Cli", "Shading style of this picture (default: the project's).")},
        {"lines", "on|off|KIND,...",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Draw the lines (on) or not (off), or only these kinds: silhouette, crease, border, material, "
                "ridge (apparent ridges), comma-separated.")},
        {"light", "TYPE:X,Y,Z",
            QT_TRANSLATE_NOOP("celform::app::Cli", "Key light of this picture (default: the project's).")},
        {"subdivision", "N",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Loop subdivision level of this picture, 0 (the control mesh) to 3 (default: the project's "
                "render level).")},
        {"ridge-threshold", "T",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Apparent-ridge threshold for this picture: view-dependent curvature times the median edge "
                "length (default: the project's, 0.3 in new projects; lower draws more).")},
        {"ridges", "snakes|raw",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Apparent ridges joined into smoothed snakes with short ones dropped (snakes), or as extracted "
                "(raw) (default: the project's, snakes in new projects).")},
        {"ridge-depth", "K",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Lowers the apparent-ridge threshold where the picture's stereo depth error is high, by 1 + K "
                "times the error over its root mean square (0 to 100; 0: one threshold everywhere; default: "
                "the project's).")}};
}

void readCameraOptions(const Invocation& in, model::RenderJob& job)
{
    camera_options::checkCombination(in, false);
    if (camera_options::byCamera(in))
        job.camera = camera_options::explicitCamera(in);
    if (camera_options::byView(in))
        job.view = camera_options::view(in);
    job.firstFrame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    job.lastFrame = job.firstFrame;
    if (in.isSet("size"))
        job.size = parseSize("size", in.value("size"));
}

void readPictureOptions(const Invocation& in, model::RenderJob& job)
{
    readCameraOptions(in, job);
    job.style = optionalValue(in, "style", [](const QString& v) { return parseStyle("style", v); });
    // --lines: on, off, or the kinds to draw (silhouette,crease,border,material,ridge).
    if (in.isSet("lines")) {
        const QString v = in.value("lines");
        if (v == QLatin1String("on") || v == QLatin1String("off"))
            job.lines = parseOnOff("lines", v);
        else
            job.lineKinds = parseLineKinds("lines", v);
    }
    job.light = optionalValue(in, "light", [](const QString& v) { return parseLight("light", v); });
    job.subdivision
        = optionalValue(in, "subdivision", [](const QString& v) { return parseSubdivision("subdivision", v); });
    if (in.isSet("ridge-threshold")) {
        const double t = parseFloat("ridge-threshold", in.value("ridge-threshold"));
        if (t < 0)
            throw UsageError{
                Cli::tr("--ridge-threshold takes a number >= 0, not “%1”").arg(in.value("ridge-threshold"))};
        job.ridgeThreshold = float(t);
    }
    if (in.isSet("ridges")) {
        const QString v = in.value("ridges");
        if (v != QLatin1String("snakes") && v != QLatin1String("raw"))
            throw UsageError{Cli::tr("--ridges takes snakes or raw, not “%1”").arg(v)};
        job.ridgeSnakes = v == QLatin1String("snakes");
    }
    if (in.isSet("ridge-depth")) {
        const double k = parseFloat("ridge-depth", in.value("ridge-depth"));
        if (!(k >= 0 && k <= 100))
            throw UsageError{
                Cli::tr("--ridge-depth takes a number from 0 to 100, not “%1”").arg(in.value("ridge-depth"))};
        job.ridgeDepthStrength = float(k);
    }
}

} // namespace celform::app
