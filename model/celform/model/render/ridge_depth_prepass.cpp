// Paper 3, section 4.4: "By making this threshold a function of the depth error, areas with few
// disparities from shading are more likely to have lines making up for it."
#include "celform/model/render/ridge_depth_prepass.h"

#include "celform/algorithms/ridge_depth_scale.h"

namespace celform::model {

void prepareDepthAdaptedRidges(const algo::TriMesh& mesh, const algo::Positions& shape,
    const algo::RasterCamera& centre, algo::RenderLook& look, algo::RenderCache& cache, RidgeDepthPrepass& prepass)
{
    prepass.used = false;
    look.ridgeThresholdScale = nullptr;
    if (!look.lines || !look.lineSettings.ridges || !(look.lineSettings.ridgeDepthStrength > 0.f))
        return;
    algo::renderFrame(shape, mesh, centre, look, cache, prepass.passes, nullptr, &prepass.gbuffer);
    algo::DepthAnalysisSettings s;
    s.toonThreshold = look.toon.thresholds.empty() ? 0.f : look.toon.thresholds.front();
    s.pointLight = look.pointLight;
    s.light = look.light;
    s.shadingOffsets = look.shadingOffsets;
    const Eigen::AlignedBox3d box = algo::boundingBox(shape);
    s.depthThreshold = float(0.02 * (box.isEmpty() ? 1.0 : box.diagonal().norm()));
    static const std::vector<float> kNoCurvature; // the depth error does not read it
    algo::analyseDepth(
        prepass.gbuffer, prepass.passes.normal, prepass.passes.beauty, mesh.faces, kNoCurvature, s, prepass.analysis);
    prepass.firstMeanSquaredError = prepass.analysis.meanSquaredError;
    algo::depthErrorRidgeScale(prepass.analysis, prepass.gbuffer, mesh.faces, shape.rows(),
        look.lineSettings.ridgeDepthStrength, prepass.scale, prepass.weight);
    look.ridgeThresholdScale = &prepass.scale;
    prepass.used = true;
}

RidgeDepthPrepass& threadRidgeDepthPrepass()
{
    thread_local RidgeDepthPrepass prepass;
    return prepass;
}

} // namespace celform::model
