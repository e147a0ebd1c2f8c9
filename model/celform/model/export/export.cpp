// The export entry point (export.h): the job's checks, the walk over its frames that every format
// shares, and the dispatch to the format's writer.
#include "celform/model/export/export.h"

#include "celform/model/data/io_error.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/subdivided_surface.h"

#include <QCoreApplication>

namespace celform::model {

namespace {

struct Names {
    ExportFormat format;
    const char* name;
};
constexpr Names kNames[] = {{ExportFormat::Gltf, "gltf"}, {ExportFormat::Glb, "glb"}, {ExportFormat::Pc2, "pc2"},
    {ExportFormat::ObjSequence, "obj-seq"}, {ExportFormat::Usda, "usda"}};

} // namespace

QString exportFormatName(ExportFormat format)
{
    for (const Names& n : kNames)
        if (n.format == format)
            return QLatin1String(n.name);
    return {};
}

std::optional<ExportFormat> exportFormatFromName(const QString& name)
{
    for (const Names& n : kNames)
        if (name == QLatin1String(n.name))
            return n.format;
    return std::nullopt;
}

std::vector<ExportFormat> exportFormats()
{
    std::vector<ExportFormat> all;
    for (const Names& n : kNames)
        all.push_back(n.format);
    return all;
}

QString ExportJob::framePath(int frame) const
{
    if (format != ExportFormat::ObjSequence)
        return output;
    // The same naming as a rendered sequence (RenderJob::framePath): one rule for both.
    RenderJob pattern;
    pattern.firstFrame = firstFrame;
    pattern.lastFrame = lastFrame;
    pattern.output = output;
    return pattern.framePath(frame);
}

QString exportJobProblem(const ExportJob& job)
{
    if (job.firstFrame < -kMaxFrame || job.lastFrame > kMaxFrame)
        return QCoreApplication::translate("celform::model::Export", "frames must be within ±%1").arg(kMaxFrame);
    if (job.firstFrame > job.lastFrame)
        return QCoreApplication::translate("celform::model::Export", "the first frame %1 is after the last frame %2")
            .arg(job.firstFrame)
            .arg(job.lastFrame);
    if (job.output.isEmpty())
        return QCoreApplication::translate("celform::model::Export", "no output file");
    if (!(job.aspect > 0.0))
        return QCoreApplication::translate("celform::model::Export", "the aspect ratio must be positive");
    if (const QString problem = subdivisionProblem({job.subdivision, -1}); !problem.isEmpty())
        return problem;
    if (job.subdivision > 0 && (job.format == ExportFormat::Gltf || job.format == ExportFormat::Glb))
        return QCoreApplication::translate("celform::model::Export",
            "glTF exports hold the keys as morph targets of the base model and take no subdivision; export "
            "pc2 or obj-seq with --subdivision");
    if (job.blendShapes && job.format != ExportFormat::Usda)
        return QCoreApplication::translate("celform::model::Export", "blend shapes are written by usda exports only");
    if (job.blendShapes && job.subdivision > 0)
        return QCoreApplication::translate("celform::model::Export",
            "blend shapes hold the keys on the base model's vertices and take no subdivision");
    return {};
}

namespace exporting {

FrameWalk::FrameWalk(const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress)
    : m_data(data)
    , m_job(job)
    , m_progress(progress)
    , m_frame(job.firstFrame - 1)
{
    QString error;
    if (!m_evaluator.prepare(data, &error))
        throw IoError(source, error);
    if (const QString problem = subdivisionMemoryProblem(*data.baseMesh, job.subdivision); !problem.isEmpty())
        throw IoError(source, problem);
    m_surface = subdividedSurface(data, job.subdivision);
}

const algo::Faces& FrameWalk::faces() const
{
    return mesh().faces;
}

const algo::TriMesh& FrameWalk::mesh() const
{
    return m_surface ? *m_surface->display.baseMesh : *m_data.baseMesh;
}

Eigen::Index FrameWalk::vertexCount() const
{
    return m_surface ? m_surface->stencil->vertexCount() : m_data.baseMesh->vertexCount();
}

bool FrameWalk::next()
{
    if (m_cancelled || m_frame >= m_job.lastFrame)
        return false;
    if (algo::cancelRequested(m_progress)) {
        m_cancelled = true;
        return false;
    }
    ++m_frame;
    m_camera = cameraAtFrame(m_data, m_data.look, m_frame, m_job.aspect);
    m_evaluator.evaluate(m_data, m_frame, m_camera.eye);
    // The smooth surface after the blend, the animation and the key deformations (issue 25).
    if (m_surface)
        m_surface->apply(m_evaluator.shape(), m_subdivided);
    ++m_done;
    algo::report(m_progress, m_done, m_job.frameCount());
    return true;
}

void finishFile(OutputFile& file, bool cancelled, ExportResult& result)
{
    if (cancelled) {
        file.cancel();
        result.cancelled = true;
        return;
    }
    file.commit(); // an IoError naming the file and the system's reason
    result.files << file.path();
}

} // namespace exporting

ExportResult exportProject(
    const ProjectData& data, const QString& source, const ExportJob& job, algo::Progress* progress)
{
    if (!data.baseMesh)
        throw IoError(source, QCoreApplication::translate("celform::model::Export", "has no base model"));
    if (const QString problem = exportJobProblem(job); !problem.isEmpty())
        throw IoError(source, problem);
    ExportResult result;
    switch (job.format) {
    case ExportFormat::Pc2:
        exporting::writePc2(data, source, job, progress, result);
        break;
    case ExportFormat::ObjSequence:
        exporting::writeObjSequence(data, source, job, progress, result);
        break;
    case ExportFormat::Gltf:
    case ExportFormat::Glb:
        exporting::writeGltf(data, source, job, progress, result);
        break;
    case ExportFormat::Usda:
        exporting::writeUsda(data, source, job, progress, result);
        break;
    }
    return result;
}

} // namespace celform::model
