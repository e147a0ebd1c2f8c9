// The stereo depth analysis of a project's picture (paper 3, chapter 4; DESIGN.md, "Depth
// analysis"): the shape at the frame and view, its curvature (cached per shape), the picture the
// look makes through the centre eye, and algo::analyseDepth over the two. One code path for the
// editor's Depth panel, `celform analyze` and `celform render --pass segments|curvature|depth-error`.
#pragma once

#include "celform/algorithms/curvature.h"
#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/progress.h"
#include "celform/algorithms/render.h"
#include "celform/model/data/camera.h"
#include "celform/model/data/project_data.h"
#include "celform/model/render/render_job.h"
#include "celform/model/data/blend_evaluator.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace celform::model {

/// What the analysis is asked for, beside the camera and the look.
struct AnalysisSettings {
    /// Neighbouring pixels join a segment only when their depths differ by less than this fraction
    /// of the diagonal of the shape's bounding box. The thesis gives no value: 2% keeps touching
    /// parts apart (the three spheres of figure 4.6 are 15% apart) and keeps a surface seen at a
    /// grazing angle together at 1280x720 (a pixel there spans well under 1% of the model).
    double depthThreshold = 0.02;
    int minSegmentPixels = algo::kMinSegmentPixels;
    algo::RatioWindow window; ///< 0.35-0.65 (DESIGN.md)
};

/// One analysed frame: the picture, its analysis and what it cost.
struct FrameAnalysis {
    algo::RenderPasses passes; ///< the centre eye's picture (mono, whatever the stereo output)
    algo::DepthAnalysis analysis;
    double depthThreshold = 0.0; ///< the absolute threshold used, model units
    double curvatureMilliseconds = 0.0; ///< 0 when the shape's curvature came from the cache
    double milliseconds = 0.0; ///< the whole analysis, curvature and picture included
    bool cancelled = false; ///< stopped through progress before the end: the rest is incomplete
};

/// Keeps what successive analyses of one model reuse: the curvature of the last shape (by its
/// generation, algo::Shape), the renderer's cache and the buffers. Not thread-safe: one per thread.
class DepthAnalyser {
public:
    /// The curvature of a shape of mesh's topology; computed when the generation differs from the
    /// last call's (or is 0, "unknown"), else the cached one.
    const algo::Curvatures& curvatures(
        const algo::TriMesh& mesh, const algo::Positions& shape, std::uint64_t generation);

    /// Analyses the picture of shape (#V by 3, the view-dependent blend at the frame) through camera
    /// at width x height with look (the project's, or one with a render's overrides).
    /// shadingOffsets: the offsets in effect (shading_layers.h; null: the base layer alone).
    /// progress counts three steps (curvature, picture, analysis) and may stop the analysis
    /// between them (out.cancelled). Throws std::bad_alloc when the buffers do not fit.
    void analyse(const ProjectData& data, const Look& look, const algo::Positions& shape, std::uint64_t generation,
        int frame, const Camera& camera, int width, int height, const AnalysisSettings& settings, FrameAnalysis& out,
        const std::vector<float>* shadingOffsets = nullptr, algo::Progress* progress = nullptr);

    /// The G-buffer of the last analysis (face ids, barycentric coordinates, depth, position).
    [[nodiscard]] const algo::GBuffer& gbuffer() const { return m_gbuffer; }

    /// The settings the last analysis was made with (light, toon threshold, offsets).
    [[nodiscard]] const algo::DepthAnalysisSettings& lastSettings() const { return m_settings; }

private:
    const algo::TriMesh* m_mesh = nullptr;
    std::uint64_t m_generation = 0;
    algo::Curvatures m_curvatures;
    float m_curvatureScale = 0.f; ///< of m_curvatures (DepthAnalysis::curvatureScale)
    std::vector<std::pair<float, float>> m_byMagnitude; ///< (|K|, area) working memory
    algo::RenderCache m_cache;
    algo::GBuffer m_gbuffer;
    algo::DepthAnalysisSettings m_settings;
};

/// `celform analyze`: the job's camera, frame and look overrides resolved as `celform render`
/// resolves them (stereo and pass ignored), the shape blended for that camera. Throws IoError
/// naming source (no base model, keys that cannot be blended).
/// baseFaces (optional): per pixel the base model's face seen there (a subdivided surface's child
/// face mapped to its control face), -1 off the model: what the segment brush votes with.
FrameAnalysis analyseProject(const ProjectData& data, const QString& source, const RenderJob& job,
    const AnalysisSettings& settings, std::vector<std::int32_t>* baseFaces = nullptr);

/// What analyseProject resolves before analysing: the look, camera, blended shape and the
/// shading offsets in effect there (shading_layers.h). Throws IoError as analyseProject does.
struct AnalysisView {
    Look look;
    Camera camera;
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
    BlendResult blend;
    algo::Positions shape;
    std::vector<float> offsets;
};
AnalysisView resolveAnalysisView(const ProjectData& data, const QString& source, const RenderJob& job);

/// `celform analyze --frames`: frames job.firstFrame to job.lastFrame every job.step, each resolved
/// and analysed as analyseProject does (the job's camera, or the shot camera at that frame),
/// through one analyser and one FrameAnalysis, so the sequence reuses its buffers, and the
/// curvature while the shape does not change. visit sees each frame's view and analysis before
/// the next overwrites them. Throws IoError as analyseProject does. progress counts a step per
/// frame and is asked after each whether to stop (then the frames after it are not analysed).
void analyseProjectFrames(const ProjectData& data, const QString& source, const RenderJob& job,
    const AnalysisSettings& settings,
    const std::function<void(int frame, const AnalysisView& view, const FrameAnalysis& analysis)>& visit,
    algo::Progress* progress = nullptr);

} // namespace celform::model
