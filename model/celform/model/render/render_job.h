// Rendering a project's frames to files: the one code path of `celform render` and of the
// editor's File > Render Image and Render Sequence (DESIGN.md, "Rendering"). The settings are
// those of the command line; the camera, the view-dependent shape and the look are resolved here.
#pragma once

#include "celform/algorithms/progress.h"
#include "celform/algorithms/stereo.h"
#include "celform/model/data/camera.h"
#include "celform/model/data/io_error.h"
#include "celform/model/data/project_data.h"
#include "celform/model/data/blend_evaluator.h"
#include "celform/model/data/framed_camera.h"

#include <Eigen/Core>

#include <QSize>
#include <QString>

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>

namespace celform::algo {
struct RenderPasses;
}

namespace celform::model {

struct SubdividedSurface;

/// The most frames one render writes.
constexpr int kMaxFramesPerRender = 100'000;
/// The widest or tallest image.
constexpr int kMaxRenderSide = 16384;
/// The most pixels of one image: 8192 x 8192, about 5.9 GB for the renderer's passes.
constexpr qint64 kMaxRenderPixels = qint64(8192) * 8192;
/// What the renderer holds per pixel (G-buffer, passes and the beauty image, measured); a stereo
/// render holds two eyes.
constexpr qint64 kRenderBytesPerPixel = 88;
/// What the depth analysis adds per pixel (its G-buffer, labels, features, distance transform).
constexpr qint64 kAnalysisBytesPerPixel = 64;

/// What to render and where: the options of `celform render`.
struct RenderJob {
    /// The camera: this one when set, else one framed from view, else the look's camera path at
    /// each frame, else the look's render camera, else one framed from defaultRenderView().
    std::optional<Camera> camera;
    std::optional<Eigen::Vector3d> view; ///< from the centroid towards the eye; not zero
    int firstFrame = 0;
    int lastFrame = 0; ///< >= firstFrame; several frames make a sequence
    int step = 1; ///< >= 1: frames firstFrame, firstFrame + step, ... up to lastFrame
    QSize size{1280, 720};
    /// Overrides of the project's look for this render only.
    std::optional<ShadingStyle> style;
    std::optional<bool> lines;
    /// `--lines KIND,...`: lines on with exactly these algo::LineKind bits (ridges included).
    std::optional<std::uint8_t> lineKinds;
    std::optional<float> ridgeThreshold; ///< `--ridge-threshold T`, >= 0
    std::optional<bool> ridgeSnakes; ///< `--ridges snakes|raw` (paper 3, figures 4.11 and 4.8)
    std::optional<float> ridgeDepthStrength; ///< `--ridge-depth K`, in [0, 100] (paper 3, 4.4)
    std::optional<Light> light;
    /// `--subdivision N`: the Loop subdivision level (0-3) instead of the look's render level.
    std::optional<int> subdivision;
    algo::StereoOutput stereo = algo::StereoOutput::Off;
    /// One of renderPassNames(); empty: the beauty pass, or every pass as channels of an .exr.
    QString pass;
    /// The file, or for a sequence a pattern: a run of # is the zero-padded frame number;
    /// without one, "_FFFF" goes before the suffix.
    QString output;
    /// How many frames render at once, each on a thread of its own with its own buffers (>= 1).
    /// The files do not depend on it.
    int threads = 1;
    /// Frames whose file exists already are left as they are (a resubmitted farm job resumes).
    bool skipExisting = false;
    /// `--svg-tones`: an .svg output (the lines pass as vector strokes, svg_lines.h) also holds
    /// the tone regions as filled layers.
    bool svgTones = false;
    /// `--strokes F.json`: the lines pass's strokes also go to this file or pattern (as output,
    /// strokes_json.h); empty: none.
    QString strokesOutput;

    [[nodiscard]] bool isSequence() const { return frameCount() > 1; }
    [[nodiscard]] int frameCount() const { return (lastFrame - firstFrame) / std::max(step, 1) + 1; }
    /// The index-th frame of the job (0 <= index < frameCount()).
    [[nodiscard]] int frameAt(int index) const { return firstFrame + index * std::max(step, 1); }
    /// An .exr without a pass, in mono: every pass as named channels.
    [[nodiscard]] bool writesAllPasses() const;
    /// The file frame f goes to.
    [[nodiscard]] QString framePath(int frame) const;
    /// The strokes file of frame f (strokesOutput as a pattern, as output is).
    [[nodiscard]] QString strokesPath(int frame) const;
    /// The output is an .svg: the lines pass as vector strokes.
    [[nodiscard]] bool writesVectorLines() const;
    /// About how many bytes the renderer holds for one frame (two eyes in stereo, a float copy of
    /// the passes for an EXR of every pass).
    [[nodiscard]] qint64 bytesNeeded() const;
};

/// The image suffixes a render writes (lower case): png, exr, tif, tiff, jpg, jpeg.
QStringList renderSuffixes();

/// The memory a render may use now: the system's available memory, and the address-space limit
/// (ulimit -v) less what this process uses, if one is set.
qint64 availableRenderMemory();

/// The project's look with the job's overrides (style, lines, light, subdivision) applied.
Look renderJobLook(const ProjectData& data, const RenderJob& job);

/// The camera a job looks through at a frame (see RenderJob::camera). Needs a base mesh.
Camera renderJobCamera(const ProjectData& data, const Look& look, const RenderJob& job, int frame);

/// What a job looks at and through, resolved once: the look with the job's overrides, the camera
/// at the first frame, and the blend evaluator built for the project's keys with that camera's
/// view direction. Later frames take their camera from renderJobCamera().
struct ResolvedRenderJob {
    Look look;
    Camera camera;
    BlendEvaluator blender;
    Eigen::Vector3d direction;
    /// The surface at the look's subdivision level (subdivided_surface.h); null at level 0.
    std::shared_ptr<const SubdividedSurface> surface;
};

/// Resolves a job for a project; throws IoError naming source when there is no base model, the
/// keys cannot be blended or the subdivision level does not fit in memory.
ResolvedRenderJob resolveRenderJob(const ProjectData& data, const QString& source, const RenderJob& job);

/// Renders one frame of a job into passes in memory, as renderFrames renders a frame before it
/// encodes it (the same evaluation, subdivided surface, shading offsets and renderShape): for a
/// picture wanted as pixels rather than a file. resolved is resolveRenderJob(data, ..., job).
void renderJobFrame(const ProjectData& data, const RenderJob& job, const ResolvedRenderJob& resolved, int frame,
    algo::RenderPasses& passes);

/// Told of each frame a render finishes, beside the progress that counts them: the command line
/// lists the files written and skipped, the editor keeps them. Called one at a time (never two at
/// once) from the thread that rendered the frame (with job.threads > 1 not always the same one),
/// just before the progress counts the frame.
class RenderFrameListener {
public:
    virtual ~RenderFrameListener() = default;
    /// frame's file was written, or left out because it exists (RenderJob::skipExisting).
    virtual void frameDone(int frame, const QString& file, bool skipped) = 0;
};

/// A frame that could not be rendered or written: the frame, and the file and problem as IoError
/// gives them. The frames finished before it (or beside it, on other threads) stay written.
class RenderFrameError : public IoError {
public:
    RenderFrameError(int frame, const QString& file, const QString& problem)
        : IoError(file, problem)
        , m_frame(frame)
    { }
    [[nodiscard]] int frame() const { return m_frame; }

private:
    int m_frame;
};

/// Renders the job's frames of a project and writes one file per frame (atomically), job.threads
/// frames at a time. source names the project in errors. progress counts the frames done
/// (written or skipped) and is asked before each frame and before each write whether to stop (a
/// frame rendered but not yet written is dropped; the files written so far stay); listener hears
/// of each frame done. Both are called one at a time, never two at once. Returns how many frames
/// were written (fewer when cancelled or skipped). Throws IoError naming the project (no base model, keys that
/// cannot be blended), RenderFrameError for the first frame (the lowest, when several threads
/// fail) that could not be rendered or written, once the frames already under way are finished.
int renderFrames(const ProjectData& data, const QString& source, const RenderJob& job,
    algo::Progress* progress = nullptr, RenderFrameListener* listener = nullptr);

} // namespace celform::model
