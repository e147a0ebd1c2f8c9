// Mirror symmetry of a model for mirrored editing: a plane perpendicular to one model axis through
// the bounding-box centre, detected as the plane whose reflection brings the vertices closest to
// the model, and the map of each vertex to its nearest mirror image. Scanned and sculpted models
// are seldom vertex-exact symmetric, so both work with approximate symmetry.
#pragma once

#include "celform/algorithms/tri_mesh.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace celform::algo {

/// The plane p[axis] = offset (axis 0: x, 1: y, 2: z).
struct AxisPlane {
    int axis = 0;
    double offset = 0.0;
};

/// The mirror image of p across the plane.
[[nodiscard]] Eigen::Vector3d reflect(const AxisPlane& plane, const Eigen::Vector3d& p);
/// The plane perpendicular to axis through the centre of the vertices' bounding box.
[[nodiscard]] AxisPlane centrePlane(const Positions& vertices, int axis);

/// How well each axis plane through the bounding-box centre mirrors the model.
struct SymmetryEstimate {
    /// The best plane's axis, -1 when none is within maxRelativeError.
    int axis = -1;
    /// Per axis: the median distance from a reflected vertex to the nearest vertex, over a sample
    /// of the vertices, divided by the bounding-box diagonal (0: vertex-exact symmetry).
    std::array<double, 3> error{{1.0, 1.0, 1.0}};
};

/// Detects the symmetry plane: for each axis, reflects up to sampleCount vertices (evenly spread
/// over the index range) across the plane through the bounding-box centre and measures the median
/// distance to the nearest vertex (capped at a tenth of the diagonal: a posed limb does not hide
/// the symmetry of the rest); the smallest error wins when it is at most maxRelativeError.
[[nodiscard]] SymmetryEstimate detectSymmetry(
    const Positions& vertices, double maxRelativeError = 0.02, int sampleCount = 4000);

/// For mirrored editing: for each vertex the index of the vertex nearest to its mirror image
/// within tolerance (world units), or -1. Exact twins on a symmetric model; the nearest vertex
/// on an approximately symmetric one. A vertex on the plane maps to itself.
[[nodiscard]] std::vector<std::int32_t> mirrorMap(const Positions& base, const AxisPlane& plane, double tolerance);

} // namespace celform::algo
