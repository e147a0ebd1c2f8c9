// The depth-error-driven apparent-ridge threshold in a picture (paper 3, section 4.4): a first
// picture through the centre eye with one threshold, its depth error (chapter 4.4's metric), and
// from it the per-vertex factor the final picture's ridges are extracted with.
#pragma once

#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/render.h"

#include <vector>

namespace celform::model {

/// What the prepass keeps between frames (a sequence allocates it once).
struct RidgeDepthPrepass {
    algo::RenderPasses passes;
    algo::GBuffer gbuffer;
    algo::DepthAnalysis analysis;
    std::vector<float> scale; ///< per vertex: the factor on the ridge threshold
    std::vector<float> weight;
    double firstMeanSquaredError = 0.0; ///< the first picture's depth error (model units squared)
    bool used = false; ///< whether the last call set a factor
};

/// When look draws apparent ridges with lineSettings.ridgeDepthStrength > 0: renders shape through
/// centre with look as it is, analyses the picture's depth error (the light, toon threshold and
/// shading offsets of look), fills prepass.scale (algo::depthErrorRidgeScale) and points
/// look.ridgeThresholdScale at it. Otherwise sets prepass.used to false and leaves look as it is.
void prepareDepthAdaptedRidges(const algo::TriMesh& mesh, const algo::Positions& shape,
    const algo::RasterCamera& centre, algo::RenderLook& look, algo::RenderCache& cache, RidgeDepthPrepass& prepass);

/// The calling thread's prepass storage: the renders and analyses of a thread share it, so a
/// sequence allocates its buffers once (one frame at a time per thread).
RidgeDepthPrepass& threadRidgeDepthPrepass();

} // namespace celform::model
