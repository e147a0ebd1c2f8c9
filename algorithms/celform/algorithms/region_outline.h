// Outlines of pixel regions as polygons (issue 28, "Vector lines": the tone regions as filled
// layers of the SVG lines): the boundary between a mask's pixels and the rest, along pixel edges.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace celform::algo {

/// The closed outlines of the pixels where mask is non-zero (width x height, row-major, y down),
/// as loops of pixel-corner coordinates (corner (x, y) is the top-left of pixel (x, y)). Each
/// loop keeps its region on the same side (outer outlines clockwise on screen, holes
/// anticlockwise), so filled with either the non-zero or the even-odd rule they cover exactly
/// the mask. Corners where only the direction is kept are dropped; pixels that touch at a corner
/// only are separate loops.
std::vector<std::vector<Eigen::Vector2i>> traceRegionOutlines(const std::vector<char>& mask, int width, int height);

} // namespace celform::algo
