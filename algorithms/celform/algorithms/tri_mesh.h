// The triangle mesh shared by every module: positions and faces in Eigen row-major storage,
// so a whole array can be handed to VTK or written to a file without reshuffling.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace celform::algo {

/// #V by 3 vertex positions (x, y, z), float as in every mesh file format.
using Positions = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #F by 3 vertex indices of counter-clockwise triangles.
using Faces = Eigen::Matrix<std::int32_t, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// #T by 2 texture coordinates.
using TexCoords = Eigen::Matrix<float, Eigen::Dynamic, 2, Eigen::RowMajor>;

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
};

/// Mean of the vertex positions: the origin of view directions (DESIGN.md conventions).
Eigen::Vector3d centroid(const Positions& vertices);

/// Axis-aligned bounding box of the vertices; empty box for an empty mesh.
Eigen::AlignedBox3d boundingBox(const Positions& vertices);

/// Per-vertex unit normals, area-weighted average of the incident face normals (#V by 3).
/// Vertices without a face get (0, 0, 1).
Positions vertexNormals(const Positions& vertices, const Faces& faces);

} // namespace celform::algo
