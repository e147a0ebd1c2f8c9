// Moving the key light so that every segment of salient shape gets a shading line (paper 3,
// sections 4.1-4.1.3 and 5.0.2-5.0.3): the brute-force search of listing 4.1, the simulated
// annealing of listing 4.2 and the gradient method of listing 4.3 extended to segments, over the
// per-pixel samples of one analysis. Only the light moves, so the G-buffer, the normals and the
// segments of the analysis stay valid through every iteration: nothing is rasterised again.
#pragma once

#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/progress.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/segments.h"
#include "celform/algorithms/tri_mesh.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace celform::algo {

enum class LightMethod {
    Gradient, ///< listing 4.3 per segment (4.1.3), steps 1/8 shrinking by 31/32 (5.0.2)
    Annealing, ///< listing 4.2: random steps shrinking by 0.95, worse positions rejected
    Random, ///< listing 4.1: independent random positions, the best kept
};

/// How much each segment counts (5.0.3, figure 5.9).
enum class SegmentWeight {
    Constant, ///< every segment alike: small features (the dent) count as much as the body
    Area, ///< in proportion to its pixels
};

struct LightOptimisationSettings {
    LightMethod method = LightMethod::Gradient;
    SegmentWeight weight = SegmentWeight::Constant;
    RatioWindow window; ///< 0.35-0.65, the thesis's recommended compromise (5.0.3)
    int iterations = 64; ///< 5.0.2
    /// Gradient method: the first step and its factor per iteration (5.0.2: "an initial step size
    /// of 1/8 that gets multiplied by 31/32 each iteration for 64 iterations").
    double initialStep = 1.0 / 8.0;
    double stepFactor = 31.0 / 32.0;
    /// Figure 5.8's transfer function with fall-off: a segment's weight grows linearly from 0 at
    /// the window's edge to its full value this far (in ratio) outside it. Without it the weight
    /// jumps between 0 and full as a segment crosses the edge, and the light oscillates.
    double falloff = 0.1;
    /// Random and annealing: the seed of their generator (std::mt19937_64, the same numbers on
    /// every platform).
    std::uint64_t seed = 1;
    /// Point lights: the length a step of 1 moves the light (the thesis's models fit a sphere of
    /// radius 1, so its step sizes are in units of the model's radius), and the model's centre,
    /// around which the random method places lights.
    double scale = 1.0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// The per-pixel data that stays fixed while only the light moves: the pixels of the analysis's
/// segments, grouped by segment, as arrays of floats (the inner loops read them in order).
struct ShadingSamples {
    std::vector<float> nx, ny, nz; ///< the shading normal, turned towards the viewer
    std::vector<float> px, py, pz; ///< the surface point (point lights)
    /// The toon threshold minus the pixel's shading offset: the pixel is bright when N.L reaches
    /// it (DESIGN.md: "N.L plus the vertex's offset above the toon threshold").
    std::vector<float> threshold;
    std::vector<std::int32_t> segmentStart; ///< pixels of segment s: [start[s], start[s + 1])
    /// Per segment the sum of its normals. For a directional light eq. 4.2 is linear in n, so the
    /// segment's gradient needs no pass over its pixels.
    std::vector<Eigen::Vector3d> normalSum;
    /// Per segment the factor its weight is multiplied by: the mean importance of its faces
    /// (focal points, paper 3 6.2; SegmentStats::importance). gatherShadingSamples sets every
    /// segment's to 1; the caller copies the analysis's in. A segment of importance 0 does not count.
    std::vector<double> importance;
    std::vector<std::int32_t> cursor; ///< working memory of gatherShadingSamples
    [[nodiscard]] int segmentCount() const { return int(segmentStart.empty() ? 0 : segmentStart.size() - 1); }
    [[nodiscard]] std::int32_t pixels(int s) const
    {
        return segmentStart[std::size_t(s) + 1] - segmentStart[std::size_t(s)];
    }
};

/// Gathers the samples of an analysis (algo::analyseDepth's inputs and result): the G-buffer's
/// positions, the shading normals, the segments, and the shading offsets interpolated as the
/// analysis interpolates them (offsets may be null). Allocates only when sizes grow.
void gatherShadingSamples(const GBuffer& gbuffer, const std::vector<Eigen::Vector3f>& normals,
    const SegmentLabels& segments, const Faces& faces, const std::vector<float>* shadingOffsets, float toonThreshold,
    ShadingSamples& out);

/// The light as the optimisation moves it: a unit direction towards the light, or a position.
struct LightPose {
    bool point = false;
    Eigen::Vector3d vector{0.4, 0.6, 0.7};
};

/// One evaluation of a light over the samples.
struct LightEvaluation {
    std::vector<std::int32_t> bright; ///< per segment
    std::vector<Eigen::Vector3d> gradient; ///< per segment, eq. 4.2 summed (when asked for)
    double objective = 0.0;
};

/// Per segment the bright pixels (N.L at or above the threshold) and, with gradients, the sum of
/// eq. 4.2 over its pixels; then the objective: the sum over segments of their weight (the
/// settings' weight times the segment's importance) times the distance of their ratio from the
/// window (0 inside). Allocates only when sizes grow.
void evaluateLight(const ShadingSamples& samples, const LightPose& light, const LightOptimisationSettings& settings,
    bool gradients, LightEvaluation& out);

/// One iteration of a run, as the JSON of `celform optimize-light` reports it.
struct LightIteration {
    double tried = 0.0; ///< the objective of the light this iteration tried (0 when none was usable)
    double objective = 0.0; ///< the best objective so far (the accepted light's)
    Eigen::Vector3d light = Eigen::Vector3d::Zero(); ///< the best light so far
    double step = 0.0; ///< the step tried (gradient, annealing); 0 for random positions
    bool accepted = false; ///< the light tried became the answer
    /// Each segment's bright ratio under the light tried (empty when none was usable), so that
    /// figure 5.8's ratios over the iterations can be plotted.
    std::vector<float> ratios;
};

struct LightOptimisationResult {
    LightPose before, after;
    std::vector<float> ratioBefore, ratioAfter; ///< per segment
    double objectiveBefore = 0.0, objectiveAfter = 0.0;
    std::vector<LightIteration> iterations;
    bool cancelled = false; ///< the progress asked to stop: after == before
};

/// What a run keeps between calls so that it does not allocate.
struct LightOptimisationWorkspace {
    LightEvaluation current, candidate, best;
};

/// Runs the chosen method from start (the artist's light, 5.0.3: "an artist can choose a starting
/// light position to guide the optimization") and returns the best light it met: the gradient
/// method moves the light every iteration as the thesis does, annealing keeps positions that are
/// not worse, random keeps better ones. A directional light stays a unit vector. The objective
/// of the accepted lights never rises. Stops early when every segment is inside the window.
/// Deterministic for given samples, start and settings. progress counts the iterations (total:
/// settings.iterations) and is asked after each whether to stop.
LightOptimisationResult optimiseLight(const ShadingSamples& samples, const LightPose& start,
    const LightOptimisationSettings& settings, LightOptimisationWorkspace& workspace, Progress* progress = nullptr);

} // namespace celform::algo
