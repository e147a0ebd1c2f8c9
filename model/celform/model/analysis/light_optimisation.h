// Optimise Light for Stereo on a project (paper 3, sections 4.1 and 5.0): the depth
// analysis of the picture, algo::optimiseLight over its segments, and the analysis again with
// the new light, so that the caller can show the depth error before and after. One code path
// for the editor's action and `celform optimize-light`; LookEdits::applyOptimisedLight stores
// the result as one undo step.
#pragma once

#include "celform/algorithms/light_optimisation.h"
#include "celform/algorithms/progress.h"
#include "celform/model/data/camera.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/data/project_data.h"
#include "celform/model/render/render_job.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace celform::model {

struct LightOptimisationRequest {
    /// Method, weight, iterations, seed and fall-off; the window, scale and centre are filled in
    /// from analysis and the shape.
    algo::LightOptimisationSettings optimiser;
    AnalysisSettings analysis; ///< its window is the one the segments are held to
};

struct LightOptimisationReport {
    Light before, after;
    algo::LightOptimisationResult run;
    /// The analyses of the picture with the light before and after (the segments are the same:
    /// they depend on the shape and the camera, not on the light).
    std::vector<algo::SegmentStats> segmentsBefore, segmentsAfter;
    double mseBefore = 0.0, mseAfter = 0.0;
    std::int64_t featuresBefore = 0, featuresAfter = 0;
    int frame = 0;
    int width = 0, height = 0;
    Camera camera;
    double optimiseMilliseconds = 0.0; ///< the iterations alone
    double milliseconds = 0.0; ///< both analyses and the iterations
    [[nodiscard]] bool cancelled() const { return run.cancelled; }
};

/// Analyses the picture of shape (#V by 3, the blend at frame for camera) at width x height with
/// look, moves look's light by the request's method, and analyses again with the new light. When
/// no light is better by the ratios, after == before.
/// progress counts request.optimiser.iterations + 2 steps (the analysis before, the iterations,
/// the analysis after) and is asked after each whether to stop: then the report is cancelled
/// and after == before. Reads data only: safe on a worker thread with a copy of the project. Throws
/// std::bad_alloc when the buffers do not fit. shadingOffsets: the offsets in effect for the shape
/// (shading_layers.h; null: the base layer alone).
LightOptimisationReport optimiseLight(const ProjectData& data, const Look& look, const algo::Positions& shape,
    std::uint64_t generation, int frame, const Camera& camera, int width, int height,
    const LightOptimisationRequest& request, DepthAnalyser& analyser, algo::Progress* progress = nullptr,
    const std::vector<float>* shadingOffsets = nullptr);

/// `celform optimize-light`: the job's camera, frame and size resolved as `celform analyze`
/// resolves them; the project's look (the job's look overrides do not apply: the light found
/// must be the project's). progress as for optimiseLight. Throws IoError naming source.
LightOptimisationReport optimiseLightForJob(const ProjectData& data, const QString& source, const RenderJob& job,
    const LightOptimisationRequest& request, algo::Progress* progress = nullptr);

/// Stable names for the command line and the editor's settings.
[[nodiscard]] QString lightMethodName(algo::LightMethod method);
[[nodiscard]] bool lightMethodFromName(const QString& name, algo::LightMethod& method);
[[nodiscard]] QString segmentWeightName(algo::SegmentWeight weight);
[[nodiscard]] bool segmentWeightFromName(const QString& name, algo::SegmentWeight& weight);

} // namespace celform::model
