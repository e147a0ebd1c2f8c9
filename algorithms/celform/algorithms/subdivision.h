// Loop subdivision as a precomputed stencil (Loop, "Smooth Subdivision Surfaces Based on
// Triangles", 1987): for one topology and a level L in 0..3 the subdivided positions are one sparse
// product V_L = S * V of the control positions, and the limit normals two more (the limit tangent
// masks of Loop 1987 and Hoppe et al., "Piecewise Smooth Surface Reconstruction", 1994, section
// 3.2). The masks are those of CGAL's Loop_mask_3 (CGAL 5.5, Subdivision_method_3):
// - edge point: 3/8 of each end, 1/8 of each opposite vertex; a border edge takes its midpoint;
// - interior vertex of valence n: (1 - n beta) of itself, beta of each neighbour, with Loop's own
//   beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n (not Warren's simplification);
// - border vertex: 6/8 of itself, 1/8 of each of its two border neighbours.
// Input CGAL cannot take stays well defined: an edge with more than two faces is a crease (its
// midpoint), a vertex with one or more than two crease edges is a corner (kept), a vertex without
// a face keeps its position. Children of face (a, b, c) with edge points ab, bc, ca are
// (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca), in that order, so each child knows its
// control face.
#pragma once

#include "celform/algorithms/mesh_types.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace celform::algo {

/// The highest level: 64 children per control face.
constexpr int kMaxSubdivisionLevel = 3;

/// A sparse matrix in compressed rows: row r is sum of weights[k] * x[cols[k]] over
/// k in [start[r], start[r + 1]).
struct SparseRows {
    std::vector<std::int32_t> start; ///< rows + 1 entries
    std::vector<std::int32_t> cols;
    std::vector<double> weights;
    std::int32_t columns = 0;
    [[nodiscard]] std::int32_t rows() const { return start.empty() ? 0 : std::int32_t(start.size()) - 1; }
    [[nodiscard]] std::size_t nonZeros() const { return cols.size(); }
};

/// Everything a topology needs at one level; built once, applied every frame.
struct SubdivisionStencil {
    int level = 0;
    std::int32_t controlVertices = 0;
    std::int32_t controlFaces = 0;
    SparseRows positions; ///< S: #V_L by #V
    /// The limit tangent masks of each level-L vertex over the level-L positions (its ring); its
    /// normal is tangentU x tangentV (outward for counter-clockwise faces). Applied to the level-L
    /// positions rather than composed with S: a ring of weights per row instead of a ring of rings.
    SparseRows tangentU, tangentV;
    /// Level-L vertices whose ring is not a disc or a half-disc (non-manifold input): their
    /// normals are the area-weighted normals of their faces, faces listed in fallbackFaces
    /// (compressed rows: fallbackStart has fallbackVertices.size() + 1 entries).
    std::vector<std::int32_t> fallbackVertices, fallbackStart, fallbackFaces;
    Faces faces; ///< the level-L triangles
    std::vector<std::int32_t> parentFace; ///< per level-L face, its control face
    /// For partial updates, in compressed rows: per control vertex, the level-L rows whose position
    /// reads it (positionReach); per level-L vertex, the rows whose tangents read it (tangentReach).
    std::vector<std::int32_t> positionReachStart, positionReach, tangentReachStart, tangentReach;
    std::int64_t creaseEdges = 0; ///< border and non-manifold edges of the control mesh
    std::int64_t nonManifoldEdges = 0;

    [[nodiscard]] std::int32_t vertexCount() const { return positions.rows(); }
    [[nodiscard]] Eigen::Index faceCount() const { return faces.rows(); }
    /// The bytes the stencil holds.
    [[nodiscard]] std::size_t bytes() const;
};

/// The level-L triangle count of a control mesh (4^L per face) and an upper bound of its vertex
/// count (V + E + ... for a closed mesh), to refuse a level before building it.
std::int64_t subdividedFaceCount(std::int64_t controlFaces, int level);
std::int64_t subdividedVertexBound(std::int64_t controlVertices, std::int64_t controlFaces, int level);

/// Builds the stencil of faces (corners in [0, vertexCount)) at level (clamped to 0..3). Corners
/// out of range are rejected by the caller (TriMesh validation); degenerate faces do not crash.
SubdivisionStencil buildSubdivisionStencil(const Faces& faces, std::int32_t vertexCount, int level);

/// out = S * control, out resized once (#V_L by 3); accumulates in double.
void applySubdivision(const SubdivisionStencil& s, const Positions& control, Positions& out);
void applySubdivision(const SubdivisionStencil& s, const Eigen::MatrixX3d& control, Eigen::MatrixX3d& out);
/// Per-vertex scalars (shading offsets) through the same stencil; out resized once.
void applySubdivision(const SubdivisionStencil& s, const std::vector<float>& control, std::vector<float>& out);

/// Unit limit normals of the level-L vertices (#V_L by 3) from their positions (applySubdivision's
/// result); out resized once.
void limitNormals(const SubdivisionStencil& s, const Positions& positions, Positions& out);

/// Working memory of partial updates, kept by the caller: sized on first use, then no allocation.
struct SubdivisionScratch {
    std::vector<std::uint32_t> positionStamp, tangentStamp;
    std::vector<std::int32_t> positionRows, tangentRows;
    std::uint32_t stamp = 0;
};

/// After the control vertices `changed` moved: recomputes only the level-L positions and normals
/// that read them (positions and normals hold the previous full result of the same stencil).
/// Returns the number of position rows recomputed.
std::size_t updateSubdivision(const SubdivisionStencil& s, const Positions& control,
    const std::vector<std::uint32_t>& changed, Positions& positions, Positions& normals, SubdivisionScratch& scratch);

/// The barycentric coordinates of corner (0-2) of a level-L face in its control face.
Eigen::RowVector3d cornerBarycentric(const SubdivisionStencil& s, Eigen::Index face, int corner);

/// Per level-L face corner, texture coordinates interpolated in the control face (uvFaces:
/// the control mesh's per-corner UV indices): a #F_L*3 by 2 table whose corner k of face f is row
/// 3 f + k.
TexCoords subdividedCornerUvs(const SubdivisionStencil& s, const TexCoords& uvs, const Faces& uvFaces);

/// The level-L faces whose control face is in controlFaces (ascending, no repeats); ascending.
std::vector<std::int32_t> subdividedFaceSet(const SubdivisionStencil& s, const std::vector<std::int32_t>& controlFaces);

/// CGAL's Loop_subdivision (Subdivision_method_3) of a closed or bordered 2-manifold, the reference
/// of the tests: positions and faces after `level` rounds, in CGAL's vertex order (the control
/// vertices first). False when CGAL cannot take the mesh (not a 2-manifold).
bool cgalLoopSubdivision(
    const Eigen::MatrixX3d& positions, const Faces& faces, int level, Eigen::MatrixX3d& outPositions, Faces& outFaces);

} // namespace celform::algo
