// Basic measures of a triangle mesh.
#include "celform/algorithms/tri_mesh.h"

#include <cmath>

namespace celform::algo {

bool TriMesh::operator==(const TriMesh& o) const
{
    return vertices.rows() == o.vertices.rows() && vertices == o.vertices && faces.rows() == o.faces.rows()
        && faces == o.faces && uvs.rows() == o.uvs.rows() && uvs == o.uvs && uvFaces.rows() == o.uvFaces.rows()
        && uvFaces == o.uvFaces && faceMaterials == o.faceMaterials && materials == o.materials;
}

Eigen::Vector3d centroid(const Positions& vertices)
{
    if (vertices.rows() == 0)
        return Eigen::Vector3d::Zero();
    // Accumulate in double: a float sum over a million vertices loses several digits.
    return vertices.cast<double>().colwise().sum().transpose() / double(vertices.rows());
}

Eigen::AlignedBox3d boundingBox(const Positions& vertices)
{
    Eigen::AlignedBox3d box;
    for (Eigen::Index i = 0; i < vertices.rows(); ++i)
        box.extend(vertices.row(i).transpose().cast<double>());
    return box;
}

Positions vertexNormals(const Positions& vertices, const Faces& faces)
{
    Positions normals = Positions::Zero(vertices.rows(), 3);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const Eigen::Vector3f a = vertices.row(faces(f, 0));
        const Eigen::Vector3f b = vertices.row(faces(f, 1));
        const Eigen::Vector3f c = vertices.row(faces(f, 2));
        const Eigen::Vector3f n = (b - a).cross(c - a); // length = 2 * area: area weighting for free
        for (int k = 0; k < 3; ++k)
            normals.row(faces(f, k)) += n.transpose();
    }
    for (Eigen::Index i = 0; i < normals.rows(); ++i) {
        const float len = normals.row(i).norm();
        if (len > 0.f && std::isfinite(len))
            normals.row(i) /= len;
        else
            normals.row(i) << 0.f, 0.f, 1.f;
    }
    return normals;
}

} // namespace celform::algo
