// Hidden-line removal of styled strokes as geometry (issue 28, "Vector lines"): the parts of each
// stroke the renderer's lines pass shows, for writers that keep strokes as paths (SVG, JSON).
#pragma once

#include "celform/algorithms/lines.h"

#include <cstdint>
#include <vector>

namespace celform::algo {

/// The visible runs of strokes seen against a depth buffer (width x height, +infinity and id -1
/// off the model), by the test drawStrokes applies per pixel (raster.h): a point is visible where
/// the pixel under it is off the model or its depth is not farther than the buffer's depth there
/// times (1 + depthBias) plus 1e-6. Each segment is sampled at most every half pixel; a stroke
/// is cut where visibility changes, at the midpoint of the two samples, with width and depth
/// interpolated there. Runs keep their stroke's kinds; a closed stroke seen whole stays closed.
/// Points outside the image count as visible (the renderer clips them with the image). Where
/// one side of a run is hidden (the pass hides pixel by pixel, so a silhouette on a rounded body
/// loses its inner side), the width there shrinks to the side that shows, in quarters of the
/// half width, and the point moves to the middle of what is left.
std::vector<StyledStroke> visibleStrokeParts(const std::vector<StyledStroke>& strokes, const std::vector<float>& depth,
    const std::vector<std::int32_t>& faceId, int width, int height, float depthBias = 0.01f);

} // namespace celform::algo
