// One frame of the view-dependent model: the one evaluation the renderer, the viewport,
// `celform eval` and every exporter share. At a frame: the animated base there (paper 1, section
// 4.1), the view direction from that base's centroid towards the camera eye (DESIGN.md, "View
// direction"), the blend weights on the viewing sphere (section 3.2) and the keys' offsets
// interpolated over time (section 4.2) added to the base.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/data/blend_evaluator.h"

#include <QString>

namespace celform::model {

/// The camera a frame is seen through when the caller names none (DESIGN.md: "without camera
/// options, eval and render use the camera path, or the render camera, at the frame"): the
/// look's camera path at the frame, else its render camera, else a camera framed from
/// defaultRenderView() for an image of the given aspect ratio. Needs a base mesh.
[[nodiscard]] Camera cameraAtFrame(const ProjectData& data, const Look& look, int frame, double aspect);

/// Evaluates frames of one project. Keeps its buffers between calls: once sized, evaluating a
/// frame allocates nothing (the keys' offsets between keyed frames aside).
class FrameEvaluator {
public:
    /// Builds the viewing sphere of the project's enabled keys. False (with a message) when they
    /// cannot be hulled; frames then give the base model.
    bool prepare(const ProjectData& data, QString* error = nullptr);

    /// Evaluates a frame seen from an eye point. data must be the prepared project, alive and
    /// unchanged while the results are read.
    void evaluate(const ProjectData& data, int frame, const Eigen::Vector3d& eye);
    /// The same for a view direction given directly (from the base centroid, unit).
    void evaluateDirection(const ProjectData& data, int frame, const Eigen::Vector3d& direction);

    /// The base model's vertices at the frame.
    [[nodiscard]] const algo::Positions& base() const { return *m_base; }
    /// The blended shape at the frame (#V by 3).
    [[nodiscard]] const algo::Positions& shape() const { return m_shape; }
    /// The view direction used (unit, model space).
    [[nodiscard]] const Eigen::Vector3d& direction() const { return m_direction; }
    /// The keys' shares at the view.
    [[nodiscard]] const BlendResult& blend() const { return m_blend; }
    [[nodiscard]] const BlendEvaluator& blender() const { return m_blender; }
    [[nodiscard]] int frame() const { return m_frame; }

private:
    void evaluateAt(const ProjectData& data, int frame, const Eigen::Vector3d& direction);

    BlendEvaluator m_blender;
    BlendScratch m_blendScratch;
    algo::Positions m_baseScratch;
    const algo::Positions* m_base = &m_baseScratch;
    algo::Positions m_shape;
    Eigen::Vector3d m_direction = Eigen::Vector3d::UnitZ();
    BlendResult m_blend;
    int m_frame = 0;
};

} // namespace celform::model
