// The triangle mesh shared by every module: positions and faces in Eigen row-major storage,
// so a whole array can be handed to VTK or written to a file without reshuffling.
#pragma once

#include "celform/algorithms/mesh_topology.h"
#include "celform/algorithms/mesh_types.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace celform::algo {

struct SymmetryEstimate;

struct Material {
    std::string name;
    Eigen::Vector3f baseColor{0.8f, 0.8f, 0.8f}; ///< linear RGB in [0, 1]
    bool operator==(const Material& o) const { return name == o.name && baseColor == o.baseColor; }
};

/// A named set of faces (a highlight patch, a selection); faces ascending, no repeats.
struct FaceSet {
    std::string name;
    std::vector<std::int32_t> faces;
    bool operator==(const FaceSet& o) const { return name == o.name && faces == o.faces; }
};

struct TriMesh {
    TriMesh();
    ~TriMesh();
    /// Copies and moves carry the data, never the derived tables (a copy is usually edited).
    TriMesh(const TriMesh& other);
    TriMesh(TriMesh&& other) noexcept;
    TriMesh& operator=(const TriMesh& other);
    TriMesh& operator=(TriMesh&& other) noexcept;

    Positions vertices;
    Faces faces;
    /// Optional texture coordinates with their own per-corner indices (#F by 3 into uvs), as in
    /// OBJ files: keeps the vertex order of the file even where UV seams split a vertex.
    TexCoords uvs;
    Faces uvFaces;
    /// Per-face material index into materials; empty means every face uses material 0.
    std::vector<std::int32_t> faceMaterials;
    std::vector<Material> materials;

    [[nodiscard]] Eigen::Index vertexCount() const { return vertices.rows(); }
    [[nodiscard]] Eigen::Index faceCount() const { return faces.rows(); }
    [[nodiscard]] bool hasUvs() const { return uvs.rows() > 0 && uvFaces.rows() == faces.rows(); }
    bool operator==(const TriMesh& o) const;

    // --- derived data, computed on first use and kept with the mesh (trimesh2's need_* style) ---
    // A mesh shared as std::shared_ptr<const TriMesh> never changes, so each table is built at
    // most once per mesh, whoever asks first; safe to ask from several threads. Code that edits a
    // mesh's arrays after asking must call clearDerived().

    /// Edge adjacency (lines, silhouettes).
    [[nodiscard]] const EdgeTopology& edgeTopology() const;
    /// Whether edgeTopology() has been built already (it then returns at once).
    [[nodiscard]] bool hasEdgeTopology() const;
    /// Faces around each vertex (patch painting, brushes, partial normal updates).
    [[nodiscard]] const VertexFaces& vertexFaces() const;
    /// Area-weighted vertex normals of `vertices` (algo::vertexNormals).
    [[nodiscard]] const Positions& normals() const;
    /// Mean of the vertex positions (algo::centroid).
    [[nodiscard]] const Eigen::Vector3d& centre() const;
    /// For mirrored editing: each vertex's nearest mirror image across the plane perpendicular to
    /// axis (0-2) through the bounding-box centre (algo::mirrorMap with a tolerance of 5% of the
    /// diagonal, so approximate symmetry finds twins), -1 where there is none.
    [[nodiscard]] const std::vector<std::int32_t>& mirrorTwins(int axis) const;
    /// The model's symmetry plane (algo::detectSymmetry).
    [[nodiscard]] const SymmetryEstimate& symmetry() const;
    void clearDerived();

private:
    struct Derived;
    std::unique_ptr<Derived> m_derived;
};

/// Vertex positions of one topology at one moment (a key's shape, a blend) with a generation
/// number that changes whenever the positions do: caches of derived data (lines, highlight
/// frames) compare generations instead of hashing or copying the positions.
struct Shape {
    Positions positions;
    std::uint64_t generation = 0; ///< 0: never filled

    /// Call after changing positions.
    void touch();
};

/// A generation number not handed out before in this process (never 0).
std::uint64_t newShapeGeneration();

/// Mean of the vertex positions: the origin of view directions (DESIGN.md conventions).
Eigen::Vector3d centroid(const Positions& vertices);

/// Axis-aligned bounding box of the vertices; empty box for an empty mesh.
Eigen::AlignedBox3d boundingBox(const Positions& vertices);

/// Per-vertex unit normals, area-weighted average of the incident face normals (#V by 3).
/// Vertices without a face get (0, 0, 1).
Positions vertexNormals(const Positions& vertices, const Faces& faces);
/// The same into normals, whose storage is reused when it has the size already.
void vertexNormals(const Positions& vertices, const Faces& faces, Positions& normals);

} // namespace celform::algo
