// Connectivity derived from a triangle list: the edge adjacency the line extraction walks and the
// faces around each vertex that brushes, patch painting and partial normal updates need. Both are
// computed once per mesh (TriMesh keeps them; see tri_mesh.h) and never change with positions.
#pragma once

#include "celform/algorithms/mesh_types.h"

#include <cstdint>
#include <vector>

namespace celform::algo {

/// Edge adjacency of a triangle mesh: each undirected edge once, with up to two faces. Built by
/// sorting edge keys (not the comic paper's quadratic temp list); edges with more than two faces
/// keep their first two and are flagged.
struct EdgeTopology {
    /// #E by 2 vertex indices, v0 < v1.
    Eigen::Matrix<std::int32_t, Eigen::Dynamic, 2, Eigen::RowMajor> edges;
    /// #E by 2 face indices; second is -1 on a border (open) edge.
    Eigen::Matrix<std::int32_t, Eigen::Dynamic, 2, Eigen::RowMajor> faces;
    std::vector<std::uint8_t> nonManifold; ///< 1 where the edge has more than two faces
    std::int64_t borderEdges = 0;
    std::int64_t nonManifoldEdges = 0;
};

EdgeTopology buildEdgeTopology(const Faces& faces, std::int32_t vertexCount);

/// The faces around each vertex in compressed rows: the faces of vertex v are
/// faces[start[v]] .. faces[start[v + 1] - 1], ascending. start has #V + 1 entries.
struct VertexFaces {
    std::vector<std::int32_t> start;
    std::vector<std::int32_t> faces;
    [[nodiscard]] bool empty() const { return start.empty(); }
};

/// One counting pass and one filling pass over the faces. Corners outside [0, vertexCount) are
/// skipped.
VertexFaces buildVertexFaces(const Faces& faces, std::int32_t vertexCount);

/// Recomputes, in normals (#V by 3, as algo::vertexNormals gives them), the normals of every
/// vertex that shares a face with a moved vertex, and nothing else: after a brush step moves k
/// vertices this costs O(k * valence^2) instead of O(#F). scratch is working memory kept by the
/// caller so that repeated calls do not allocate.
void updateVertexNormals(const Positions& shape, const Faces& faces, const VertexFaces& around,
    const std::vector<std::uint32_t>& moved, Positions& normals, std::vector<std::int32_t>& scratch);

} // namespace celform::algo
