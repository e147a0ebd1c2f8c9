// The shared per-frame evaluation of the view-dependent model.
#include "celform/model/render/frame_evaluator.h"

#include "celform/model/render/render_job.h"

namespace celform::model {

Camera cameraAtFrame(const ProjectData& data, const Look& look, int frame, double aspect)
{
    if (!look.cameraPath.empty())
        return look.cameraPath.at(double(frame));
    if (look.renderCamera)
        return *look.renderCamera;
    return cameraFromView(data, defaultRenderView(), aspect);
}

bool FrameEvaluator::prepare(const ProjectData& data, QString* error)
{
    return m_blender.update(data, error);
}

void FrameEvaluator::evaluate(const ProjectData& data, int frame, const Eigen::Vector3d& eye)
{
    Q_ASSERT(data.baseMesh);
    m_base = &data.basePositions(frame, m_baseScratch);
    const Eigen::Vector3d centre = data.animated() ? algo::centroid(*m_base) : data.baseMesh->centre();
    evaluateAt(data, frame, viewDirectionFromCentre(centre, eye));
}

void FrameEvaluator::evaluateDirection(const ProjectData& data, int frame, const Eigen::Vector3d& direction)
{
    Q_ASSERT(data.baseMesh);
    m_base = &data.basePositions(frame, m_baseScratch);
    evaluateAt(data, frame, direction);
}

void FrameEvaluator::evaluateAt(const ProjectData& data, int frame, const Eigen::Vector3d& direction)
{
    m_frame = frame;
    m_direction = direction;
    m_blender.weights(data, direction, m_blend);
    m_blender.shapeFor(data, m_blend, frame, *m_base, m_shape, &m_blendScratch);
}

} // namespace celform::model
