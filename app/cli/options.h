// Option values of the sub-commands: numbers, vectors, directions, frames, sizes, the light and
// style, and the camera options. Each parser throws UsageError (exit 2) naming the option, so a
// value the project file would refuse never reaches the document.
#pragma once

#include "cli/command.h"

#include "celform/model/data/camera.h"
#include "celform/model/data/camera_path.h"
#include "celform/model/data/mirror_plane.h"
#include "celform/model/data/project_data.h"
#include "celform/model/document/brush_stroke.h"
#include "celform/model/render/render_job.h"

#include <Eigen/Core>

#include <QJsonArray>
#include <QSize>
#include <QString>

#include <cstddef>
#include <functional>
#include <optional>
#include <utility>

namespace celform::model {
struct ExportJob;
}

namespace celform::app {

// The render limits are the renderer's (celform/model/render/render_job.h), shared with the editor's render dialog.
/// The most frames one `render --frames` run writes.
constexpr int kMaxFramesPerRun = model::kMaxFramesPerRender;
using model::kMaxRenderPixels;
using model::kMaxRenderSide;
using model::kRenderBytesPerPixel;

/// count comma-separated finite numbers ("X,Y,Z", "DX,DY", "X,Y,Z,R").
Eigen::VectorXd parseNumbers(const char* option, const QString& text, int count);
/// The same for values the document stores as floats (highlight parameters, brush amounts): each
/// must also be finite as a float.
Eigen::VectorXd parseFloats(const char* option, const QString& text, int count);
double parseNumber(const char* option, const QString& text);
/// A number the document stores as a float: finite as a float too.
double parseFloat(const char* option, const QString& text);
int parseInt(const char* option, const QString& text);
/// A Loop subdivision level, 0 to algo::kMaxSubdivisionLevel (with allowSame, also -1: "the render
/// level"); UsageError otherwise.
int parseSubdivision(const char* option, const QString& text, bool allowSame = false);
/// A frame number within +-model::kMaxFrame.
int parseFrame(const char* option, const QString& text);
/// The frames of `--frames A-B[:STEP]`: first, first + step, ... up to last.
struct FrameRange {
    int first = 0;
    int last = 0;
    int step = 1;
};
/// "A-B" or "A-B:STEP" (A and B may be negative, STEP >= 1), A <= B, both within
/// +-model::kMaxFrame, at most kMaxFramesPerRun frames.
FrameRange parseFrameRange(const char* option, const QString& text);
/// "WxH", each between 1 and kMaxRenderSide, at most kMaxRenderPixels in all.
QSize parseSize(const char* option, const QString& text);
/// A usage error when a render of bytes cannot fit in the memory available now (the system's
/// available memory, and the address-space limit if one is set): refused before the project is
/// read rather than ending in "out of memory" or the kernel's OOM killer.
void checkRenderMemory(const char* option, const QString& text, qint64 bytes);
bool parseOnOff(const char* option, const QString& text);
/// `--mirror auto|x|y|z|off`: the plane, or none for auto (the project's detected plane).
std::optional<model::MirrorPlane> parseMirror(const char* option, const QString& text);
/// A comma-separated list of line kinds (silhouette, crease, border, material, ridge) as
/// algo::LineKind bits; at least one, no repeats needed.
std::uint8_t parseLineKinds(const char* option, const QString& text);

/// A position: three finite numbers.
Eigen::Vector3d parsePoint(const char* option, const QString& text);
/// A direction: three finite numbers whose length is finite and not zero (so it normalises);
/// returned as given, not normalised.
Eigen::Vector3d parseDirection(const char* option, const QString& text);
/// A direction stored as floats (a highlight's guide): a direction in float precision too.
Eigen::Vector3f parseFloatDirection(const char* option, const QString& text);

/// "point:X,Y,Z" or "directional:X,Y,Z" (normalised).
model::Light parseLight(const char* option, const QString& text);
/// toon, gooch, comic or lambert.
model::ShadingStyle parseStyle(const char* option, const QString& text);

/// Whether two paths name the same existing file (through links too).
bool sameFile(const QString& a, const QString& b);

/// One word of a fixed set (an enum's names on the command line): the value named by text, or a
/// UsageError of message (a Cli::tr() text whose %1 is what was given).
template <typename T, std::size_t N>
T parseChoice(const QString& text, const std::pair<const char*, T> (&choices)[N], const QString& message)
{
    for (const auto& [name, value] : choices)
        if (text == QLatin1String(name))
            return value;
    throw UsageError{message.arg(text)};
}

/// An option's parsed value, or none when it is not given.
template <typename Parse>
auto optionalValue(const Invocation& in, const char* option, Parse parse) -> std::optional<decltype(parse(QString()))>
{
    std::optional<decltype(parse(QString()))> value;
    if (in.isSet(option))
        value.emplace(parse(in.value(option)));
    return value;
}

/// The camera options of `key add` and `render`: --view, or --eye, --target and --up together.
namespace camera_options {
/// Their entries for a sub-command's option list.
std::vector<OptionSpec> specs();
[[nodiscard]] bool byView(const Invocation& in);
[[nodiscard]] bool byCamera(const Invocation& in);
/// Usage errors for --view together with the others, or an incomplete --eye/--target/--up.
void checkCombination(const Invocation& in, bool required);
/// The camera of --eye, --target and --up; a usage error when they make none.
[[nodiscard]] model::Camera explicitCamera(const Invocation& in);
/// The --view direction.
[[nodiscard]] Eigen::Vector3d view(const Invocation& in);
} // namespace camera_options

/// The look overrides readPictureOptions reads, --style, --lines, --light and --ridge-threshold:
/// their entries for the option lists of `render` and `analyze`.
std::vector<OptionSpec> lookOverrideSpecs();

/// The camera (--view, or --eye, --target and --up), --frame and --size, read into job.
void readCameraOptions(const Invocation& in, model::RenderJob& job);
/// The picture options `render` and `analyze` share, read into job: the camera (--view, or --eye,
/// --target and --up), --frame, --size, and the look overrides --style, --lines, --light and
/// --ridge-threshold.
void readPictureOptions(const Invocation& in, model::RenderJob& job);

/// `--stereo off|anaglyph|dubois|halfcolor|sbs|tb`.
algo::StereoOutput parseStereo(const QString& text);

// The sub-commands' readers and builders, shared with the Python module (python/) so that both
// check the same options with the same words.

/// The options of `celform render` up to its output, read into a job with their checks (look.cpp):
/// readPictureOptions, --frames, --threads, --skip-existing, --stereo and --pass.
model::RenderJob readRenderJob(const Invocation& in);
/// The output options of `celform render` read into job, whose output is set already (look.cpp):
/// the vector lines (.svg, --svg-tones, --strokes), the pass, stereo and suffix checks, a frame
/// range's numbered file names and the memory check.
void readRenderOutputs(const Invocation& in, model::RenderJob& job);

/// What `celform render --json` prints for job: its frames, size and threads, and the frames
/// written and skipped ({"frame", "file"} objects in any order) listed in frame order.
QJsonObject renderJobJson(const model::RenderJob& job, const QJsonArray& written, const QJsonArray& skipped);

/// The options of `celform export` read into a job with their checks (export.cpp), --format and
/// --out given: the format, the output's suffix, --subdivision and --blend-shapes. frames is
/// --frames when given; the job's frames are the project's otherwise, set once it is read.
model::ExportJob readExportJob(const Invocation& in, std::optional<FrameRange>& frames);

/// What `celform info --json` prints for a project read from path (project.cpp); path names it
/// in errors (a drawing whose image header cannot be read) and, absolute, as "file".
QJsonObject projectInfoJson(const model::ProjectData& data, const QString& path);

/// The settings `celform set` changes (look.cpp), each none when not given.
struct ProjectSettings {
    std::optional<double> sharpness;
    std::optional<model::UnspecifiedMode> unspecified;
    std::optional<model::TimeInterpolation> time;
    std::optional<model::Light> light;
    std::optional<model::ShadingStyle> style;
    bool removeRenderCamera = false; ///< --render-view none
    std::optional<Eigen::Vector3d> renderView;
    std::optional<int> subdivision;
    std::optional<int> viewportSubdivision;
};
/// The options of `celform set`, every one parsed and checked before a file is opened: a usage
/// error changes nothing ("nothing to set" when none is given).
ProjectSettings readProjectSettings(const Invocation& in);
/// Applies the settings to doc, one document operation per property as the editor's panels make
/// them; warn is told of a viewport subdivision level above the render level. A render view on a
/// document without a base model is an IoError naming path.
void applyProjectSettings(model::Document& doc, const ProjectSettings& settings, const QString& path,
    const std::function<void(const QString&)>& warn);

/// The options of `celform key add` (keys.cpp), read and checked before a file is opened.
struct KeyAddOptions {
    QString name;
    bool byView = false; ///< --view, else --eye, --target and --up
    Eigen::Vector3d view = Eigen::Vector3d::Zero();
    model::Camera camera; ///< without --view: the camera given
    int frame = 0;
};
KeyAddOptions readKeyAddOptions(const Invocation& in);
/// Adds the key to doc, which has a base model: its camera (--view framed on the model), the
/// --drawing aligned to it, the --mesh's deformation at the frame (its import's warnings in
/// meshWarnings). Returns the new key's id.
model::ObjectId addKeyViewpoint(
    model::Document& doc, const Invocation& in, const KeyAddOptions& key, QStringList& meshWarnings);

/// The options of `celform brush` (keys.cpp), read and checked before a file is opened.
struct BrushOptions {
    QString key; ///< the key's name
    int picked = 0; ///< the vertex
    double radius = 0.0;
    model::BrushStep step;
    int frame = 0;
    algo::BrushProfile profile;
    std::optional<model::MirrorPlane> mirror; ///< none: the project's plane (auto)
};
BrushOptions readBrushOptions(const Invocation& in);
/// The key a stroke deforms: an IoError naming path when doc has no such key, or no such vertex.
const model::KeyViewpoint& brushKey(const model::Document& doc, const BrushOptions& brush, const QString& path);
/// One stroke of one step on key (brushKey's), seen through its camera as the editor's brush tool
/// runs it; warn is told of a vertex without a mirror twin. Returns what `brush --json` prints.
QJsonObject brushStroke(model::Document& doc, const model::KeyViewpoint& key, const BrushOptions& brush,
    const std::function<void(const QString&)>& warn);

/// `celform camera`'s edit (camera.cpp): --turntable or --key with their values.
struct CameraPathEdit {
    model::Turntable turntable; ///< with --turntable
    int keyFrame = 0; ///< with --key
    model::RenderJob job; ///< with --key: its camera, or its view direction
};
/// Usage errors for turntable options without --turntable, camera options without --key.
void checkCameraPathOptions(const Invocation& in);
/// The values of --turntable and its options, or of --key and the camera options, checked.
CameraPathEdit readCameraPathEdit(const Invocation& in);
/// Makes the turntable, keys the camera or (neither given: --clear) clears the path of doc, which
/// has a base model.
void applyCameraPathEdit(model::Document& doc, const Invocation& in, const CameraPathEdit& edit);

} // namespace celform::app
