// CGAL's Loop subdivision as the reference of the stencils (subdivision.h): kept in a file of its
// own so that CGAL's heavy headers compile once.
#include "celform/algorithms/subdivision.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace celform::algo {

bool cgalLoopSubdivision(
    const Eigen::MatrixX3d& positions, const Faces& faces, int level, Eigen::MatrixX3d& outPositions, Faces& outFaces)
{
    using Kernel = CGAL::Simple_cartesian<double>;
    using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vertices;
    vertices.reserve(std::size_t(positions.rows()));
    for (Eigen::Index v = 0; v < positions.rows(); ++v)
        vertices.push_back(mesh.add_vertex(Kernel::Point_3(positions(v, 0), positions(v, 1), positions(v, 2))));
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const auto face = mesh.add_face(
            vertices[std::size_t(faces(f, 0))], vertices[std::size_t(faces(f, 1))], vertices[std::size_t(faces(f, 2))]);
        if (face == Mesh::null_face())
            return false;
    }
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(level));
    outPositions.resize(Eigen::Index(mesh.number_of_vertices()), 3);
    for (const auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        outPositions.row(Eigen::Index(v.idx())) << p.x(), p.y(), p.z();
    }
    outFaces.resize(Eigen::Index(mesh.number_of_faces()), 3);
    Eigen::Index row = 0;
    for (const auto f : mesh.faces()) {
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
            if (k < 3)
                outFaces(row, k++) = std::int32_t(v.idx());
        ++row;
    }
    return true;
}

} // namespace celform::algo
