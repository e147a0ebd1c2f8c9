// Optimise Light for Stereo on a project (paper 3, sections 4.1 and 5.0): the depth
// analysis of the picture, algo::optimiseLight over its segments, and the analysis again with
// the new light, so that the caller can show the depth error before and after. One code path
// for the editor's action and `celform optimize-light`; LookEdits::applyOptimisedLight stores
// the result as one undo step.
#pragma once

#include "celform/algorithms/light_optimisation.h"
#include "celform/algorithms/light_search.h"
#include "celform/algorithms/progress.h"
#include "celform/model/data/camera.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/data/project_data.h"
#include "celform/model/render/render_job.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace celform::model {

/// What the optimisation minimises (issue 26, "an objective that cannot make depth worse").
enum class LightObjective {
    Ratios, ///< the thesis's: the segments' distance from the window (4.1.3); may raise the MSE
    /// The depth error of 4.4 (MSE) directly: a compass search (algo::searchLight) over the
    /// light at reduced resolution, warm-started from the ratios' answer.
    DepthError,
    /// The thesis's answer when its MSE is not above the start's, else the best MSE among the
    /// lights visited (the default).
    Both,
};

/// Where the light starts.
enum class LightStart {
    Current, ///< the artist's light (5.0.3: "an artist can choose a starting light position")
    Camera, ///< at the camera, as the thesis starts (5.0.3): towards the eye, or at the eye
};

struct LightOptimisationRequest {
    /// Method, weight, iterations, seed and fall-off; the window, scale and centre are filled in
    /// from analysis and the shape.
    algo::LightOptimisationSettings optimiser;
    AnalysisSettings analysis; ///< its window is the one the segments are held to
    LightObjective objective = LightObjective::Both;
    LightStart start = LightStart::Current;
    /// The depth-error search: its budget and first step; it analyses at the picture's size
    /// divided by searchDivisor (at least 64 pixels a side).
    algo::LightSearchSettings search;
    int searchDivisor = 2;
};

struct LightOptimisationReport {
    Light before, after; ///< the project's light, and the light found
    Light start; ///< where the search started (before, or the camera's light)
    algo::LightOptimisationResult run; ///< the ratios' run (its objectives: the start's and the answer's)
    algo::LightSearchResult search; ///< the depth-error search (no visits when it did not run)
    double ratiosBefore = 0.0, ratiosAfter = 0.0; ///< the ratios' objective of start and after
    /// The analyses of the picture with the light before and after (the segments are the same:
    /// they depend on the shape and the camera, not on the light).
    std::vector<algo::SegmentStats> segmentsBefore, segmentsAfter;
    double mseBefore = 0.0, mseAfter = 0.0; ///< of start and after, at the analysed size
    std::int64_t featuresBefore = 0, featuresAfter = 0;
    int frame = 0;
    int width = 0, height = 0;
    Camera camera;
    double optimiseMilliseconds = 0.0; ///< the iterations alone
    double milliseconds = 0.0; ///< both analyses and the iterations
    [[nodiscard]] bool cancelled() const { return run.cancelled; }
};

/// Analyses the picture of shape (#V by 3, the blend at frame for camera) at width x height with
/// look and the start light, moves the light by the request's method and objective, and analyses
/// again with the new light. With LightObjective::Ratios, when no light is better by the ratios,
/// after == start; with DepthError and Both the MSE after is never above the start's (at this
/// size): at worst after == start.
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
[[nodiscard]] QString lightObjectiveName(LightObjective objective);
[[nodiscard]] bool lightObjectiveFromName(const QString& name, LightObjective& objective);

} // namespace celform::model
