// The falloff brush of paper 1, section 3.1.2: pick a vertex, select every vertex within 3D
// distance r, and move them parallel to the image plane (or along the view axis) scaled by
// (1 - d/r)^2, keeping camera-space depth.
#pragma once

#include "celform/algorithms/mesh_topology.h"
#include "celform/algorithms/tri_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace celform::algo {

/// Paper 1, section 3.1.2: (1 - d/r)^2 for d < r, else 0.
inline double brushFalloff(double d, double r)
{
    return (r > 0.0 && d < r) ? (1.0 - d / r) * (1.0 - d / r) : 0.0;
}

/// The falloff curve of the brush. Paper: (1 - d/r)^2, the paper's and the default. Smooth:
/// Blender's smoothstep of t = 1 - d/r, 3t^2 - 2t^3 (flat at the centre, so a small radius does
/// not make a spike). Sphere: Blender's sqrt(1 - (d/r)^2), a dome.
enum class BrushFalloff { Paper, Smooth, Sphere };

inline double brushFalloff(double d, double r, BrushFalloff curve)
{
    if (!(r > 0.0 && d < r))
        return 0.0;
    const double t = 1.0 - d / r;
    switch (curve) {
    case BrushFalloff::Smooth:
        return t * t * (3.0 - 2.0 * t);
    case BrushFalloff::Sphere: {
        const double u = d / r;
        return std::sqrt(std::max(1.0 - u * u, 0.0));
    }
    case BrushFalloff::Paper:
        break;
    }
    return t * t;
}

/// How the brush weighs what it selects: the falloff curve times the strength (0, 1].
struct BrushProfile {
    BrushFalloff falloff = BrushFalloff::Paper;
    double strength = 1.0;
};

/// Uniform-grid spatial index over vertex positions for radius queries: occupied cells live in a
/// hash table, so memory follows the vertices and not the bounding box. With cellSize <= 0 the
/// cell size is chosen from the vertex density (about one vertex per cell if the vertices filled
/// their bounding box, then shrunk until a vertex shares its cell with ~16 others at most, which
/// suits surfaces and tolerates far outliers). Non-finite vertices are left out. Build once per
/// key shape; rebuild after large edits. Copies share the (immutable) index.
class VertexGrid {
public:
    VertexGrid() = default;
    explicit VertexGrid(const Positions& vertices, double cellSize = 0.0);
    /// Indices and distances of the vertices within radius of centre, distance <= radius
    /// (ascending index order). Visits only the cells overlapping the sphere.
    void radiusQuery(const Eigen::Vector3d& centre, double radius, std::vector<std::uint32_t>& indices,
        std::vector<float>& distances) const;
    /// Nearest vertex to a point within maxDistance (inclusive; ties go to the lower index), or -1
    /// when there is none or the grid is empty (used for X-mirror matching).
    [[nodiscard]] std::int64_t nearest(const Eigen::Vector3d& point, double maxDistance) const;
    [[nodiscard]] bool empty() const;

private:
    struct Data;
    std::shared_ptr<const Data> m;
};

/// The selection of one brush stroke: vertices within r of the picked vertex and their falloff.
struct BrushSelection {
    std::uint32_t picked = 0;
    double radius = 0.0;
    std::vector<std::uint32_t> indices; ///< ascending
    std::vector<float> weights; ///< (1 - d/r)^2, 1 at the picked vertex
};

/// Selects around vertex `picked` of `shape` (the key's current shape) with the grid built on it:
/// vertices with 3D distance d < radius, weight brushFalloff(d, radius); the picked vertex is always
/// selected with weight exactly 1 (also for radius <= 0).
/// The profile scales every weight by its strength and shapes them by its falloff curve.
BrushSelection selectForBrush(const Positions& shape, const VertexGrid& grid, std::uint32_t picked, double radius,
    const BrushProfile& profile = {});

/// An orthonormal camera frame: right, up (image plane) and forward (into the screen).
struct ImageFrame {
    Eigen::Vector3d right{1, 0, 0};
    Eigen::Vector3d up{0, 1, 0};
    Eigen::Vector3d forward{0, 0, -1};
};

/// Per selected vertex displacement (#selection by 3) for a drag of (dx, dy) world units along
/// right and up at the picked vertex: parallel to the image plane, so camera-space depth is kept
/// for perspective and orthographic cameras alike.
Positions brushDrag(const BrushSelection& selection, const ImageFrame& frame, double dx, double dy);
/// The same into out (resized; no allocation when it already has the selection's size).
void brushDrag(const BrushSelection& selection, const ImageFrame& frame, double dx, double dy, Positions& out);
/// Displacement for a push of dz world units along forward (positive = away from the camera).
Positions brushPush(const BrushSelection& selection, const ImageFrame& frame, double dz);
void brushPush(const BrushSelection& selection, const ImageFrame& frame, double dz, Positions& out);
/// Rotation by angle (radians, counter-clockwise on screen) about the axis through the picked
/// vertex along forward, scaled per vertex by its falloff weight (angle * weight). Sign: a positive
/// angle turns right toward up, so a vertex at pivot + right goes to pivot + up after +90 degrees
/// with weight 1; for a right-handed frame (forward = up x right) that is a right-hand rotation
/// about -forward (toward the viewer). Depth is kept.
Positions brushRotate(const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double angle);
void brushRotate(
    const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double angle, Positions& out);
/// Scaling by factor in the image plane about the picked vertex (depth kept), per-vertex
/// factor 1 + (factor - 1) * weight.
Positions brushScale(const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double factor);
void brushScale(
    const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double factor, Positions& out);
/// Laplacian smoothing step toward the one-ring average (distinct neighbours from faces),
/// strength in [0, 1] times the weight. Builds the adjacency of the selected vertices only, in
/// one pass over the faces without allocating per-mesh tables. Vertices without faces stay put.
Positions brushSmooth(const BrushSelection& selection, const Positions& shape, const Faces& faces, double strength);
/// The same with the mesh's faces-around-vertex table (TriMesh::vertexFaces()): O(selection)
/// instead of a pass over every face, the stroke's steps after the first allocate nothing.
/// scratch is working memory kept by the caller. With tangential (Blender's Relax), the step
/// keeps only its part in the vertex's tangent plane (normal: the area-weighted normals of its
/// faces): the vertices spread evenly over the surface and its shape, so the silhouette, stays.
void brushSmooth(const BrushSelection& selection, const Positions& shape, const Faces& faces, const VertexFaces& around,
    double strength, Positions& out, std::vector<std::int32_t>& scratch, bool tangential = false);

/// For X-mirror editing: for each vertex the index of its mirror across x = 0 in the base shape
/// (nearest vertex to (-x, y, z) within tolerance, world units), or -1. A vertex on the plane maps
/// to itself. Builds its own VertexGrid on base.
std::vector<std::int32_t> mirrorMap(const Positions& base, double tolerance);

} // namespace celform::algo
