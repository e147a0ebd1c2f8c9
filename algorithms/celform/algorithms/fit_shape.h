// Fit Shape to Drawing: the key deformation of paper 1, section 3.1.2 (the model deformed
// parallel to the image plane until it matches the drawing, "the majority of the deformations in
// 2D") found automatically, the paper's first future work ("semi-automatic alignment and
// deformation based on feature correspondence"). The correspondence is between the contour
// generator of the current shape and the drawing's outline; the rest of the mesh follows as
// rigidly as possible (arap.h).
#pragma once

#include "celform/algorithms/fit_metrics.h"
#include "celform/algorithms/mesh_topology.h"
#include "celform/algorithms/outline.h"
#include "celform/algorithms/progress.h"
#include "celform/algorithms/raster.h"

#include <cstdint>
#include <string>
#include <vector>

namespace celform::algo {

struct FitShapeOptions {
    /// Faces that may move (a painted face set, ascending or not); empty: the whole model.
    std::vector<std::int32_t> regionFaces;
    /// Vertices that stay where they are (painted pins).
    std::vector<std::int32_t> pinnedVertices;
    /// The brush's mirror: per vertex its mirror's index or -1 (TriMesh::mirrorTwins(), mirrorMap());
    /// empty: no mirror. Each handle gets a mirrored twin and the result is made symmetric.
    std::vector<std::int32_t> mirror;
    /// Normal of the mirror plane (only its direction matters: displacements are reflected).
    Eigen::Vector3d mirrorNormal{1.0, 0.0, 0.0};
    /// The fraction of the fitted deformation applied, in [0, 1].
    double strength = 1.0;
    /// Rounds of match-and-deform at most; the fit stops earlier when the chamfer distance stops
    /// falling (by less than minImprovement, relative).
    int maxRounds = 10;
    double minImprovement = 0.01;
    /// How far (pixels) along its projected normal a silhouette vertex looks for the outline; 0:
    /// 8 % of the diagonal of the outline's bounding box, at least 6 pixels.
    double searchRadiusPx = 0.0;
    /// Largest angle between a silhouette vertex's normal and the outline's normal at its match;
    /// beyond it the match folds over and is rejected.
    double maxNormalAngleDegrees = 60.0;
    /// Local-global iterations of the as-rigid-as-possible solve per round.
    int arapIterations = 6;
    /// Stiffness of a matched vertex relative to its spokes (arap.h), before its robust weight.
    double handleStiffness = 100.0;
};

struct FitShapeResult {
    bool ok = false;
    bool cancelled = false;
    std::string error; ///< English, when not ok and not cancelled
    /// Per-vertex displacements relative to the input shape (model units), sparse: the vertices
    /// that move, ascending, and their offsets (#indices by 3).
    std::vector<std::uint32_t> indices;
    Positions displacements;
    FitMetrics before; ///< full resolution, the input shape
    FitMetrics after; ///< the input shape plus the displacements
    int rounds = 0; ///< rounds whose result was kept
    std::int64_t matchedVertices = 0; ///< silhouette vertices with a target in the last kept round
};

/// Deforms shape (the key's current shape) so that its silhouette seen through camera (image size
/// from the outline) meets outline. Each round (at most options.maxRounds):
///  1. the contour generator of the current shape: the silhouette edges (lines.h) chained into
///     strokes, keeping the vertices on the outer boundary of the projected silhouette;
///  2. each such vertex looks for the outline along its projected outward normal within the
///     search radius; matches whose path crosses another part of the silhouette, or whose outline
///     normal faces away (a fold), are rejected; the rest are weighted by a Tukey weight of their
///     distance;
///  3. matched vertices are pulled to their targets parallel to the image plane at their depth
///     (the brush's drag, paper 1, section 3.1.2), mirrored when asked, and the rest of the region
///     follows by as-rigid-as-possible deformation from the input shape.
/// The round that lowers the chamfer distance least ends the fit (a round that raises it is
/// undone). topology: faces' edge adjacency (TriMesh::edgeTopology()).
FitShapeResult fitShape(const Positions& shape, const Faces& faces, const EdgeTopology& topology,
    const RasterCamera& camera, const Outline& outline, const FitShapeOptions& options = {},
    Progress* progress = nullptr);

} // namespace celform::algo
