// Rendering a project's frames to files (render_job.h).
#include "celform/model/render/render_job.h"

#include "celform/model/render/frame_evaluator.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/render/frame_schedule.h"
#include "celform/model/render/subdivided_surface.h"
#include "celform/model/data/io_error.h"
#include "celform/model/render/render_output.h"
#include "celform/model/render/strokes_json.h"
#include "celform/model/render/svg_lines.h"
#include "celform/model/render/vector_lines.h"
#include "celform/model/data/shading_layers.h"
#include "celform/model/data/blend_evaluator.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include <sys/resource.h>
#include <unistd.h>

namespace celform::model {
namespace {

struct RenderJobText {
    Q_DECLARE_TR_FUNCTIONS(celform::model::RenderJob)
};

} // namespace

bool RenderJob::writesAllPasses() const
{
    return QFileInfo(output).suffix().toLower() == QLatin1String("exr") && pass.isEmpty()
        && stereo == algo::StereoOutput::Off;
}

namespace {

/// A run of # in pattern is the zero-padded frame number; without one, a sequence's files have
/// "_FFFF" before the suffix.
QString patternPath(const QString& output, int frame, bool isSequence)
{
    const int first = int(output.indexOf(QLatin1Char('#')));
    if (first >= 0) {
        int last = first;
        while (last + 1 < output.size() && output[last + 1] == QLatin1Char('#'))
            ++last;
        return output.left(first) + QStringLiteral("%1").arg(frame, last - first + 1, 10, QLatin1Char('0'))
            + output.mid(last + 1);
    }
    if (!isSequence)
        return output;
    const QFileInfo info(output);
    return info.dir().filePath(
        QStringLiteral("%1_%2.%3").arg(info.completeBaseName()).arg(frame, 4, 10, QLatin1Char('0')).arg(info.suffix()));
}

} // namespace

QString RenderJob::framePath(int frame) const
{
    return patternPath(output, frame, isSequence());
}

QString RenderJob::strokesPath(int frame) const
{
    return strokesOutput.isEmpty() ? QString() : patternPath(strokesOutput, frame, isSequence());
}

bool RenderJob::writesVectorLines() const
{
    return QFileInfo(output).suffix().toLower() == QLatin1String("svg");
}

qint64 RenderJob::bytesNeeded() const
{
    // What the writer holds while the next frame renders: for an EXR of every pass, a second set
    // of passes (48 bytes a pixel) and the file made from it (at most its 12 float channels
    // uncompressed, 48; about 4 for a render); for one pass, the second of the two RGBA float
    // images it takes in turn (16).
    const qint64 perPixel = kRenderBytesPerPixel * (stereo == algo::StereoOutput::Off ? 1 : 2)
        + (writesAllPasses() ? 96 : 16) + (analysisPictureFromName(pass) ? kAnalysisBytesPerPixel : 0);
    return qint64(size.width()) * size.height() * perPixel;
}

QStringList renderSuffixes()
{
    return {QStringLiteral("png"), QStringLiteral("exr"), QStringLiteral("tif"), QStringLiteral("tiff"),
        QStringLiteral("jpg"), QStringLiteral("jpeg")};
}

qint64 availableRenderMemory()
{
    qint64 available = std::numeric_limits<qint64>::max();
    QFile meminfo(QStringLiteral("/proc/meminfo"));
    if (meminfo.open(QIODevice::ReadOnly)) {
        for (const QByteArray& line : meminfo.readAll().split('\n'))
            if (line.startsWith("MemAvailable:"))
                available = line.mid(13).trimmed().split(' ').value(0).toLongLong() * 1024;
    }
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        QFile statm(QStringLiteral("/proc/self/statm"));
        const qint64 used = statm.open(QIODevice::ReadOnly)
            ? statm.readAll().split(' ').value(0).toLongLong() * ::sysconf(_SC_PAGESIZE)
            : 0;
        available = std::min(available, qint64(limit.rlim_cur) - used);
    }
    return available;
}

Look renderJobLook(const ProjectData& data, const RenderJob& job)
{
    Look look = data.look;
    if (job.style) {
        look.style = *job.style;
        look.materialStyles.clear();
    }
    if (job.lines)
        look.showLines = *job.lines;
    if (job.lineKinds) {
        const std::uint8_t k = *job.lineKinds;
        look.showLines = true;
        look.lines.silhouettes = (k & algo::kSilhouette) != 0;
        look.lines.creases = (k & algo::kCrease) != 0;
        look.lines.borders = (k & algo::kBorder) != 0;
        look.lines.materialBoundaries = (k & algo::kMaterialBoundary) != 0;
        look.lines.ridges = (k & algo::kRidge) != 0;
    }
    if (job.ridgeThreshold)
        look.lines.ridgeThreshold = *job.ridgeThreshold;
    if (job.ridgeSnakes)
        look.lines.ridgeSnakes = *job.ridgeSnakes;
    if (job.ridgeDepthStrength)
        look.lines.ridgeDepthStrength = *job.ridgeDepthStrength;
    if (job.light) { // --light holds at every frame: it replaces the light track too
        look.light = *job.light;
        look.lightTrack = {};
    }
    if (job.subdivision)
        look.subdivision.level = *job.subdivision;
    return look;
}

Camera renderJobCamera(const ProjectData& data, const Look& look, const RenderJob& job, int frame)
{
    if (job.camera)
        return *job.camera;
    const double aspect = double(job.size.width()) / std::max(1, job.size.height());
    if (job.view)
        return cameraFromView(data, *job.view, aspect);
    return cameraAtFrame(data, look, frame, aspect);
}

ResolvedRenderJob resolveRenderJob(const ProjectData& data, const QString& source, const RenderJob& job)
{
    if (!data.baseMesh)
        throw IoError(source, RenderJobText::tr("has no base model"));
    ResolvedRenderJob resolved;
    // The overrides apply to this job only.
    resolved.look = renderJobLook(data, job);
    resolved.camera = renderJobCamera(data, resolved.look, job, job.firstFrame);
    QString error;
    if (!resolved.blender.update(data, &error))
        throw IoError(source, error);
    resolved.direction = BlendEvaluator::viewDirection(data, resolved.camera.eye, job.firstFrame);
    if (const QString problem = subdivisionProblem(resolved.look.subdivision); !problem.isEmpty())
        throw IoError(source, problem);
    if (const QString problem = subdivisionMemoryProblem(
            *data.baseMesh, resolved.look.subdivision.level, job.bytesNeeded() * std::max(1, job.threads));
        !problem.isEmpty())
        throw IoError(source, problem);
    resolved.surface = subdividedSurface(data, resolved.look.subdivision.level);
    return resolved;
}

namespace {

/// One thread's evaluation of a job's frames, its buffers and caches kept from frame to frame:
/// they only spare work whose result they hold exactly (the shape keeps its generation while
/// frames leave it still, so highlight geometry and the analyser's curvature are reused).
struct JobFrameState {
    explicit JobFrameState(const ProjectData& data)
    {
        // resolveRenderJob has built the same sphere already, and thrown if it could not.
        evaluator.prepare(data);
    }

    /// Evaluates frame f: camera, shape and offsets become the frame's. Returns the project the
    /// frame shows: the subdivided base model, face sets and offsets stand in for the control ones.
    const ProjectData& evaluate(const ProjectData& data, const RenderJob& job, const ResolvedRenderJob& resolved, int f)
    {
        // The one evaluation of a frame (frame_evaluator.h): the camera at the frame (the path's
        // when the project has one), the animated base there, the view direction and the shape.
        camera = renderJobCamera(data, resolved.look, job, f);
        evaluator.evaluate(data, f, camera.eye);
        const algo::Positions& next = evaluator.shape();
        const SubdividedSurface* surface = resolved.surface.get();
        if (shape.generation == 0 || next.rows() != control.rows() || next != control) {
            control = next;
            // The smooth surface comes after the blend, the animation and the key deformations.
            // Issue 25: the smooth surface is shaded with its limit normals (the stencil's tangents).
            if (surface) {
                surface->apply(control, shape.positions);
                algo::limitNormals(*surface->stencil, shape.positions, normals);
            } else {
                shape.positions = control;
                // Issue 29: the normals renderFrame would derive frame after frame, once per
                // shape (a turntable of a still model: about 12 ms of each dragon frame).
                algo::vertexNormals(shape.positions, data.baseMesh->faces, normals);
            }
            shape.touch();
        }
        effectiveShadingOffsets(data, evaluator.blender(), evaluator.direction(), f, offsets);
        if (surface) {
            surface->apply(offsets, subdividedOffsets);
            std::swap(offsets, subdividedOffsets);
        }
        return surface ? surface->display : data;
    }

    /// The evaluated frame f's passes; shown is what evaluate() returned.
    /// dataPasses false: the beauty alone is wanted (algo::RenderLook::dataPasses).
    void render(const ProjectData& shown, const RenderJob& job, const ResolvedRenderJob& resolved, int f,
        algo::RenderPasses& passes, bool dataPasses = true)
    {
        renderShape(shown, resolved.look, shape.positions, f, camera, job.size.width(), job.size.height(), job.stereo,
            cache, passes, shape.generation, &offsets, shadingNormals(), dataPasses);
    }

    /// The shape's vertex normals: the limit normals of the subdivided surface, or the control
    /// mesh's area-weighted ones (algo::vertexNormals, as renderFrame would make them).
    [[nodiscard]] const algo::Positions* shadingNormals() const { return &normals; }

    FrameEvaluator evaluator;
    algo::RenderCache cache;
    Camera camera; // the frame's
    algo::Positions control; // the frame's control shape (before subdivision)
    algo::Shape shape; // the shape rendered: control, or its subdivided surface
    algo::Positions normals; // the shape's vertex normals (shadingNormals)
    std::vector<float> offsets; // in effect at the camera's view and the frame (shading_layers.h)
    std::vector<float> subdividedOffsets;
};

/// One thread's renderer of a job's frames (a FrameRenderer): its own buffers and caches
/// (JobFrameState's, the analyser's, the encoded files').
class FrameWorker {
public:
    FrameWorker(const ProjectData& data, const RenderJob& job, const ResolvedRenderJob& resolved)
        : m_data(data)
        , m_job(job)
        , m_resolved(resolved)
        , m_allPasses(job.writesAllPasses())
        , m_floatFile(QFileInfo(job.output).suffix().toLower() == QLatin1String("exr"))
        , m_beautyAlone(!m_allPasses && (job.pass.isEmpty() || job.pass == QLatin1String("beauty")))
        , m_analysisPicture(analysisPictureFromName(job.pass))
        , m_frame(data)
    { }

    FrameWrite render(int f, const QString& target, const std::function<bool()>& cancelled)
    {
        const ProjectData& shown = m_frame.evaluate(m_data, m_job, m_resolved, f);
        const Camera& camera = m_frame.camera;
        // An EXR's floats go to the writer as they are, in one of two images used in turn (the
        // writer may still be writing the other). An 8-bit file's pixels are quantised here, 1.8 ms
        // of a dragon frame, and the writer is given the bytes: one float image serves every frame
        // (issue 29: 33 MB less a render thread at 1920x1080, pages the first frame faults in).
        algo::ImageRGBA& image = m_images[m_floatFile ? m_nextImage : 0];
        const algo::ImageRGBA* picture = &image;
        if (m_analysisPicture) {
            // The analysis passes (segments, curvature, depth error) come from the depth analysis
            // of the centre eye's picture.
            m_analyser.analyse(shown, m_resolved.look, m_frame.shape.positions, m_frame.shape.generation, f, camera,
                m_job.size.width(), m_job.size.height(), AnalysisSettings{}, m_analysed, &m_frame.offsets);
            if (cancelled())
                return {};
            image = analysisImage(m_analysed.analysis, *m_analysisPicture, m_floatFile);
        } else if (m_job.writesVectorLines() || !m_job.strokesOutput.isEmpty()) {
            // Vector lines and the strokes' JSON are written here, on the render thread.
            if (!renderVectorLines(shown, f, camera, target, cancelled))
                return {};
            return [] {};
        } else {
            // The beauty alone renders straight into the EXR's image.
            const bool intoImage = m_beautyAlone && m_floatFile;
            if (intoImage)
                std::swap(image, m_passes[m_nextPasses].beauty);
            m_frame.render(shown, m_job, m_resolved, f, m_passes[m_nextPasses], !m_beautyAlone);
            if (intoImage)
                std::swap(image, m_passes[m_nextPasses].beauty);
            if (cancelled())
                return {};
            if (m_allPasses) {
                // Every pass to EXR: the passes themselves go to the writer, which reads their
                // channels and compresses them while this thread renders the next frame into the
                // other set (issue 29: the gather was 19 ms of the render thread's frame).
                const algo::RenderPasses& passes = m_passes[m_nextPasses];
                m_nextPasses ^= 1;
                return [&passes, target] { writePassesExr(passes, target); };
            }
            if (!m_beautyAlone)
                passImage(m_passes[m_nextPasses], m_job.pass, m_floatFile, image);
            else if (!m_floatFile)
                picture = &m_passes[m_nextPasses].beauty;
        }
        static const std::vector<std::string> rgba = {"R", "G", "B", "A"};
        if (!m_floatFile) {
            EncodedFrame& encoded = m_encoded[m_nextEncoded];
            m_nextEncoded ^= 1;
            encodeChannels(target, picture->width, picture->height, rgba, picture->pixels.data(),
                picture->pixels.size(), true, encoded);
            return [&encoded, target] { writeEncoded(encoded, target); };
        }
        m_nextImage ^= 1;
        return [&image, target] {
            writeChannelsFile(target, image.width, image.height, rgba, image.pixels.data(), image.pixels.size(), true);
        };
    }

private:
    /// The lines pass as vector strokes (an .svg output) or as an image, and the strokes' JSON
    /// when the job asks for it (vector_lines.h): each eye rendered once for both.
    bool renderVectorLines(const ProjectData& shown, int f, const Camera& camera, const QString& target,
        const std::function<bool()>& cancelled)
    {
        const std::vector<algo::RenderPasses> eyes = renderEyes(shown, m_resolved.look, m_frame.shape.positions, f,
            camera, m_job.size.width(), m_job.size.height(), m_job.stereo, m_frame.cache, m_frame.shape.generation,
            &m_frame.offsets, false, m_frame.shadingNormals());
        if (cancelled())
            return false;
        const VectorLines lines = vectorLinesOf(eyes, m_job.stereo, m_resolved.look, m_job.svgTones, f);
        if (!m_job.strokesOutput.isEmpty())
            writeStrokesJson(lines, m_job.strokesPath(f));
        if (m_job.writesVectorLines())
            writeLinesSvg(lines, target);
        else
            writeImage(passImage(eyes.front(), m_job.pass, m_floatFile), target);
        return true;
    }

    const ProjectData& m_data;
    const RenderJob& m_job;
    const ResolvedRenderJob& m_resolved;
    const bool m_allPasses;
    const bool m_floatFile;
    const bool m_beautyAlone; ///< one pass, the beauty: rendered without the data passes
    const std::optional<AnalysisPicture> m_analysisPicture;
    JobFrameState m_frame;
    DepthAnalyser m_analyser;
    FrameAnalysis m_analysed;
    /// The frame's passes, their storage kept from frame to frame; the second set only for an EXR
    /// of every pass, whose writer reads the passes of one frame while the next renders.
    std::array<algo::RenderPasses, 2> m_passes;
    int m_nextPasses = 0;
    /// The images of one pass: an EXR's, which the writer has or had, used in turn (the writer
    /// may still be writing the last one); the first alone for an 8-bit file.
    std::array<algo::ImageRGBA, 2> m_images;
    int m_nextImage = 0;
    /// An 8-bit file's bytes, quantised here, used in turn as m_images are.
    std::array<EncodedFrame, 2> m_encoded;
    int m_nextEncoded = 0;
};

} // namespace

void renderJobFrame(const ProjectData& data, const RenderJob& job, const ResolvedRenderJob& resolved, int frame,
    algo::RenderPasses& passes)
{
    JobFrameState state(data);
    state.render(state.evaluate(data, job, resolved, frame), job, resolved, frame, passes);
}

int renderFrames(const ProjectData& data, const QString& source, const RenderJob& job, algo::Progress* progress,
    RenderFrameListener* listener)
{
    const ResolvedRenderJob resolved = resolveRenderJob(data, source, job);
    return scheduleFrames(job, progress, listener, [&]() -> FrameRenderer {
        auto worker = std::make_shared<FrameWorker>(data, job, resolved);
        return [worker](int frame, const QString& file, const std::function<bool()>& cancelled) -> FrameWrite {
            FrameWrite write = worker->render(frame, file, cancelled);
            if (!write)
                return {};
            // The write keeps the worker (and the data it writes) alive until it has run.
            return [worker, write = std::move(write)] { write(); };
        };
    });
}

} // namespace celform::model
