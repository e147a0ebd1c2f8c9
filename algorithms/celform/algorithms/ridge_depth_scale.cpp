// Paper 3, section 4.4: the apparent-ridge threshold as a function of the depth error.
#include "celform/algorithms/ridge_depth_scale.h"

#include <cmath>

namespace celform::algo {

void depthErrorRidgeScale(const DepthAnalysis& analysis, const GBuffer& gbuffer, const Faces& faces,
    Eigen::Index vertexCount, float strength, std::vector<float>& scale, std::vector<float>& weight)
{
    const auto n = std::size_t(vertexCount);
    scale.assign(n, 0.f); // the error sums first
    weight.assign(n, 0.f);
    const double rms = std::sqrt(analysis.meanSquaredError);
    const std::size_t pixels = analysis.depthError.size();
    if (strength > 0.f && rms > 0.0 && gbuffer.faceId.size() == pixels && gbuffer.barycentric.size() == pixels) {
        for (std::size_t p = 0; p < pixels; ++p) {
            const std::int32_t f = gbuffer.faceId[p];
            if (f < 0 || f >= faces.rows())
                continue;
            const float error = std::abs(analysis.depthError[p]);
            const Eigen::Vector3f& b = gbuffer.barycentric[p];
            for (int k = 0; k < 3; ++k) {
                const auto v = std::size_t(faces(f, k));
                if (v >= n)
                    continue;
                scale[v] += b[k] * error;
                weight[v] += b[k];
            }
        }
    }
    const float k = strength / float(rms > 0.0 ? rms : 1.0);
    for (std::size_t v = 0; v < n; ++v)
        scale[v] = weight[v] > 0.f && strength > 0.f && rms > 0.0 ? 1.f / (1.f + k * (scale[v] / weight[v])) : 1.f;
}

} // namespace celform::algo
