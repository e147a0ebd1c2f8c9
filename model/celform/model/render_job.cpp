// Rendering a project's frames to files (render_job.h).
#include "celform/model/render_job.h"

#include "celform/model/frame_evaluation.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/depth_analysis.h"
#include "celform/model/depth_analysis_output.h"
#include "celform/model/io_error.h"
#include "celform/model/render_output.h"
#include "celform/model/shading_layers.h"
#include "celform/model/view_blend.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <limits>

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

QString RenderJob::framePath(int frame) const
{
    const int first = int(output.indexOf(QLatin1Char('#')));
    if (first >= 0) {
        int last = first;
        while (last + 1 < output.size() && output[last + 1] == QLatin1Char('#'))
            ++last;
        return output.left(first) + QStringLiteral("%1").arg(frame, last - first + 1, 10, QLatin1Char('0'))
            + output.mid(last + 1);
    }
    if (!isSequence())
        return output;
    const QFileInfo info(output);
    return info.dir().filePath(
        QStringLiteral("%1_%2.%3").arg(info.completeBaseName()).arg(frame, 4, 10, QLatin1Char('0')).arg(info.suffix()));
}

qint64 RenderJob::bytesNeeded() const
{
    const qint64 perPixel = kRenderBytesPerPixel * (stereo == algo::StereoOutput::Off ? 1 : 2)
        + (writesAllPasses() ? 32 : 0) + (analysisPictureFromName(pass) ? kAnalysisBytesPerPixel : 0);
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

Camera cameraFromView(const ProjectData& data, const Eigen::Vector3d& view, double aspect)
{
    Camera camera;
    const Eigen::Vector3d centre = algo::centroid(data.baseMesh->vertices);
    // The sphere around the centroid holding every vertex fits the narrower field of view.
    const double radius = std::max(
        std::sqrt(
            (data.baseMesh->vertices.cast<double>().rowwise() - centre.transpose()).rowwise().squaredNorm().maxCoeff()),
        1e-6);
    const double halfY = camera.fovYDegrees * M_PI / 360.0;
    const double halfMin = std::min(halfY, std::atan(std::tan(halfY) * aspect));
    const Eigen::Vector3d direction = view.normalized();
    camera.target = centre;
    camera.eye = centre + direction * (1.05 * radius / std::sin(halfMin));
    camera.up = std::abs(direction.y()) > 0.99 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(0, 1, 0);
    return camera;
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
    if (job.light)
        look.light = *job.light;
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
    return resolved;
}

int renderFrames(const ProjectData& data, const QString& source, const RenderJob& job, const RenderCallbacks& callbacks)
{
    const ResolvedRenderJob resolved = resolveRenderJob(data, source, job);
    const Look& look = resolved.look;
    // The one evaluation of a frame (frame_evaluation.h): the camera at the frame (the path's when
    // the project has one), the animated base there, the view direction and the blended shape.
    FrameEvaluator evaluator;
    evaluator.prepare(data);
    const BlendEvaluator& blender = evaluator.blender();
    const bool allPasses = job.writesAllPasses();
    const bool floatFile = QFileInfo(job.output).suffix().toLower() == QLatin1String("exr");
    auto cancelled = [&callbacks] { return callbacks.cancelled && callbacks.cancelled(); };
    algo::RenderCache cache;
    // The analysis passes (segments, curvature, depth error) come from the depth analysis of the
    // centre eye's picture; the analyser keeps the curvature while the shape is still.
    const std::optional<AnalysisPicture> analysisPicture = analysisPictureFromName(job.pass);
    DepthAnalyzer analyzer;
    FrameAnalysis analysed;
    // The shape keeps its generation while frames leave it still, so highlight geometry is reused.
    algo::Shape shape;
    std::vector<float> offsets; // in effect at the camera's view and the frame (shading_layers.h)
    int written = 0;
    for (int f = job.firstFrame; f <= job.lastFrame && !cancelled(); ++f) {
        const Camera camera = renderJobCamera(data, look, job, f);
        evaluator.evaluate(data, f, camera.eye);
        const Eigen::Vector3d& direction = evaluator.direction();
        const algo::Positions& next = evaluator.shape();
        if (shape.generation == 0 || next.rows() != shape.positions.rows() || next != shape.positions) {
            shape.positions = next;
            shape.touch();
        }
        effectiveShadingOffsets(data, blender, direction, f, offsets);
        const QString target = job.framePath(f);
        if (analysisPicture) {
            analyzer.analyze(data, look, shape.positions, shape.generation, f, camera, job.size.width(),
                job.size.height(), AnalysisSettings{}, analysed, &offsets);
            if (cancelled())
                break;
            writeImage(analysisImage(analysed.analysis, *analysisPicture, floatFile), target);
            ++written;
            if (callbacks.written)
                callbacks.written(f, target, written);
            continue;
        }
        const algo::RenderPasses passes = renderShape(data, look, shape.positions, f, camera, job.size.width(),
            job.size.height(), job.stereo, cache, shape.generation, &offsets);
        if (cancelled())
            break;
        if (allPasses)
            writePassesExr(passes, target);
        else
            writeImage(passImage(passes, job.pass.isEmpty() ? QStringLiteral("beauty") : job.pass, floatFile), target);
        ++written;
        if (callbacks.written)
            callbacks.written(f, target, written);
    }
    return written;
}

} // namespace celform::model
