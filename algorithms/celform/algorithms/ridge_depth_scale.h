// The depth-error-driven ridge threshold (paper 3, section 4.4: "By making this threshold a
// function of the depth error, areas with few disparities from shading are more likely to have
// lines making up for it"): a per-vertex factor on the apparent-ridge threshold
// (ApparentRidgeOptions::thresholdScale), lowered where a first picture's depth error is high.
#pragma once

#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/raster.h"
#include "celform/algorithms/tri_mesh.h"

#include <vector>

namespace celform::algo {

/// Per vertex of vertexCount: 1 / (1 + strength * e_v / e_rms), where e_v is the mean absolute
/// depth error of the pixels around the vertex (each covered pixel of analysis counts for the three
/// corners of its face, weighted by its barycentric coordinates) and e_rms the picture's root mean
/// squared error over the model's pixels. A vertex whose error is the picture's typical one has its
/// threshold divided by 1 + strength; vertices no pixel reaches, and every vertex when the picture
/// has no error or strength is 0, keep 1. gbuffer is the analysed picture's (its faceId and
/// barycentric). scale and the accumulator weight are resized only when their size differs.
void depthErrorRidgeScale(const DepthAnalysis& analysis, const GBuffer& gbuffer, const Faces& faces,
    Eigen::Index vertexCount, float strength, std::vector<float>& scale, std::vector<float>& weight);

} // namespace celform::algo
