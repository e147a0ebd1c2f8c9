// Meshes the tests generate when they need a known shape (and when ../shared is absent).
#pragma once

#include "celform/algorithms/tri_mesh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace celform::test {

/// A unit octahedron around the origin (vertices ±x, ±y, ±z, faces counter-clockwise seen from
/// outside): its centroid is 0, so view directions are eye directions.
inline std::shared_ptr<algo::TriMesh> octahedron()
{
    auto m = std::make_shared<algo::TriMesh>();
    m->vertices.resize(6, 3);
    m->vertices << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
    m->faces.resize(8, 3);
    m->faces << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
    return m;
}

/// A tetrahedron at the origin's corner (vertices 0, x, y, z), faces counter-clockwise from outside.
inline algo::TriMesh tetrahedronMesh()
{
    algo::TriMesh m;
    m.vertices.resize(4, 3);
    m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    m.faces.resize(4, 3);
    m.faces << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
    return m;
}

/// The mesh with every triangle split in four at its edges' midpoints (corner triangles first, the
/// middle one last); onSphere puts the new vertices on the unit sphere (for icosphere).
inline std::shared_ptr<algo::TriMesh> subdivided(const algo::TriMesh& mesh, bool onSphere = false)
{
    std::vector<Eigen::Vector3f> v;
    v.reserve(std::size_t(mesh.vertices.rows()) * 4);
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
        v.emplace_back(mesh.vertices.row(i).transpose());
    std::map<std::pair<int, int>, int> middle;
    auto split = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        const auto found = middle.find(key);
        if (found != middle.end())
            return found->second;
        const Eigen::Vector3f sum = v[std::size_t(a)] + v[std::size_t(b)];
        v.push_back(onSphere ? Eigen::Vector3f(sum.normalized()) : Eigen::Vector3f(0.5f * sum));
        return middle[key] = int(v.size()) - 1;
    };
    auto out = std::make_shared<algo::TriMesh>();
    out->faces.resize(mesh.faces.rows() * 4, 3);
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
        const int t0 = mesh.faces(f, 0), t1 = mesh.faces(f, 1), t2 = mesh.faces(f, 2);
        const int a = split(t0, t1), b = split(t1, t2), c = split(t2, t0);
        out->faces.row(4 * f + 0) << t0, a, c;
        out->faces.row(4 * f + 1) << t1, b, a;
        out->faces.row(4 * f + 2) << t2, c, b;
        out->faces.row(4 * f + 3) << a, b, c;
    }
    out->vertices.resize(Eigen::Index(v.size()), 3);
    for (std::size_t i = 0; i < v.size(); ++i)
        out->vertices.row(Eigen::Index(i)) = v[i].transpose();
    return out;
}

/// A unit icosphere with 10 * 4^s + 2 vertices (2562 for s = 4).
inline std::shared_ptr<algo::TriMesh> icosphere(int subdivisions)
{
    const float t = (1.f + std::sqrt(5.f)) / 2.f;
    const std::array<Eigen::Vector3f, 12> v = {{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
        {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}}};
    const int f[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2},
        {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10},
        {8, 6, 7}, {9, 8, 1}};
    auto mesh = std::make_shared<algo::TriMesh>();
    mesh->vertices.resize(12, 3);
    for (std::size_t i = 0; i < v.size(); ++i)
        mesh->vertices.row(Eigen::Index(i)) = v[i].normalized().transpose();
    mesh->faces.resize(20, 3);
    for (int i = 0; i < 20; ++i)
        mesh->faces.row(i) << f[i][0], f[i][1], f[i][2];
    for (int s = 0; s < subdivisions; ++s)
        mesh = subdivided(*mesh, true);
    return mesh;
}

/// The thesis's dented sphere (paper 3, figures 4.4, 4.5 and 5.6): a unit icosphere pushed in
/// smoothly around axis, by depth at the centre of the dent and a Gaussian fall-off of angular
/// width sigma (radians): r = 1 - depth * exp(-(angle / sigma)^2). The bowl of the dent has
/// positive Gaussian curvature, the ring where it meets the sphere negative.
inline std::shared_ptr<algo::TriMesh> dentedSphere(
    int subdivisions, Eigen::Vector3f axis, float depth = 0.25f, float sigma = 0.35f)
{
    auto mesh = icosphere(subdivisions);
    axis.normalize();
    for (Eigen::Index i = 0; i < mesh->vertices.rows(); ++i) {
        const Eigen::Vector3f p = mesh->vertices.row(i).transpose().normalized();
        const float angle = std::acos(std::clamp(p.dot(axis), -1.f, 1.f));
        const float r = 1.f - depth * std::exp(-(angle / sigma) * (angle / sigma));
        mesh->vertices.row(i) = (r * p).transpose();
    }
    return mesh;
}

/// A copy of mesh with one material per colour, assigned face by face: the angle of the face's
/// centre about the Z axis (turned by 0.3 radians so no boundary follows a symmetry plane) picks
/// one of colors.size() equal sectors. The materials meet along zigzags of edges, where vertices
/// are shared by faces of different materials and triangles have corners on both sides; seen
/// from +Z, every material is in view.
inline std::shared_ptr<algo::TriMesh> withSectorMaterials(
    const algo::TriMesh& mesh, const std::vector<Eigen::Vector3f>& colors)
{
    auto out = std::make_shared<algo::TriMesh>(mesh);
    out->materials.clear();
    for (std::size_t m = 0; m < colors.size(); ++m) {
        algo::Material material;
        material.name = "sector" + std::to_string(m);
        material.baseColor = colors[m];
        out->materials.push_back(material);
    }
    const float pi = 3.14159265f;
    const auto sectors = int(std::max<std::size_t>(colors.size(), 1));
    out->faceMaterials.assign(std::size_t(mesh.faceCount()), 0);
    for (Eigen::Index f = 0; f < mesh.faceCount(); ++f) {
        const Eigen::Vector3f centre = (mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1))
                                           + mesh.vertices.row(mesh.faces(f, 2)))
            / 3.f;
        float angle = std::atan2(centre.y(), centre.x()) + 0.3f;
        angle = angle - 2.f * pi * std::floor(angle / (2.f * pi)); // [0, 2 pi)
        const int sector = std::min(sectors - 1, int(angle / (2.f * pi) * float(sectors)));
        out->faceMaterials[std::size_t(f)] = sector;
    }
    return out;
}

/// Torus around z: ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), nu by nv quads, outward normals.
inline algo::TriMesh torus(float R, float r, int nu, int nv)
{
    constexpr double pi = 3.14159265358979323846;
    algo::TriMesh m;
    m.vertices.resize(nu * nv, 3);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
            m.vertices.row(j * nu + i) << float((R + r * std::cos(v)) * std::cos(u)),
                float((R + r * std::cos(v)) * std::sin(u)), float(r * std::sin(v));
        }
    m.faces.resize(2 * nu * nv, 3);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const int a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + (i + 1) % nu,
                      d = ((j + 1) % nv) * nu + i;
            m.faces.row(2 * a) << a, b, c;
            m.faces.row(2 * a + 1) << a, c, d;
        }
    return m;
}

/// On the shared elephant (it faces +x, roughly symmetric across z): a hind-leg vertex, the lowest
/// in the back of the model, well on the +z side.
inline std::uint32_t elephantHindLegVertex(const algo::TriMesh& mesh)
{
    const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
    const Eigen::Vector3d c = box.center(), size = box.sizes();
    std::uint32_t picked = 0;
    double lowest = std::numeric_limits<double>::infinity();
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
        const Eigen::Vector3d p = mesh.vertices.row(v).transpose().cast<double>();
        if (p.x() < c.x() - 0.2 * size.x() && p.z() > c.z() + 0.2 * size.z() && p.y() < lowest) {
            lowest = p.y();
            picked = std::uint32_t(v);
        }
    }
    return picked;
}

} // namespace celform::test
