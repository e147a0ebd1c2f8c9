// Per-vertex principal curvatures, principal directions and curvature derivatives of a triangle
// mesh (Rusinkiewicz 2004), plus the smoothed Gaussian curvature that paper 3 segments on.
#pragma once

#include "celform/algorithms/mesh_types.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace celform::algo {

/// Curvature of every vertex. Sign convention: curvature is the derivative of the unit normal
/// (II(u, v) = (D_u n) . v), so a sphere whose normals point outwards has k1 = k2 = +1/r, the inside
/// of a bowl seen along its normals is negative, and a saddle has k1 > 0 > k2. Flipping every
/// normal (or every face's winding, when the normals are computed) negates k1, k2 and dcurv and
/// swaps which direction is dir1; the Gaussian curvature does not change.
/// Where curvature is undefined (isolated vertices, vertices whose faces are all degenerate)
/// every value is 0 and dir1, dir2 are still a unit tangent frame.
struct Curvatures {
    std::vector<float> k1, k2; ///< per vertex, k1 >= k2 (signed)
    /// #V by 3 unit principal directions in the tangent plane of the vertex normal: dir1 goes with
    /// k1, dir2 = normal x dir1, so (dir1, dir2, normal) is right-handed. Each is defined up to sign.
    Positions dir1, dir2;
    /// Per vertex, the 4 distinct entries of the symmetric curvature derivative tensor C (the
    /// derivative of the second fundamental form) in the frame (dir1, dir2), Rusinkiewicz section 4:
    /// (C111, C112, C122, C222) = (dk1/de1, dk1/de2, dk2/de1, dk2/de2), where de1, de2 are steps
    /// along dir1, dir2 (C112 = d II12 / de1 and C122 = d II12 / de2 as well). Units 1/length^2.
    /// Flipping dir1 (dir2) negates the entries with an odd number of 1s (2s).
    std::vector<Eigen::Vector4f> dcurv;
    /// Mixed Voronoi area of each vertex (Meyer et al. 2003): the weights of every average here.
    /// Sums to the surface area over non-degenerate faces.
    std::vector<float> pointArea;
    /// k1 * k2 smoothed once (paper 3, section 4.5.1): each vertex gets the pointArea-weighted mean
    /// of gaussianRaw over itself and its one-ring neighbours (each neighbour counted once).
    std::vector<float> gaussian;
    std::vector<float> gaussianRaw; ///< k1 * k2 before smoothing

    /// Scratch buffers kept between calls so that a call on a mesh of unchanged size allocates
    /// nothing. Not part of the result.
    struct Workspace {
        Positions normals; ///< the unit vertex normals used (given or Max-weighted)
        std::vector<Eigen::Vector3f> cornerAreas; ///< per face, mixed area of each corner
        std::vector<Eigen::Vector3f> fundamental; ///< per vertex (II11, II12, II22) while accumulating
        std::vector<std::int32_t> ringStart, ring, ringMark; ///< one-ring lists for the smoothing
    } workspace;
};

/// Fills out for the mesh (#V by 3 vertices, #F by 3 faces with indices in [0, #V)).
/// vertexNormals: #V by 3 (normalised here), or an empty matrix to let the function compute Max's
/// (1999) normals, as Rusinkiewicz and trimesh2 do. Prefer that: the area-weighted normals of
/// algo::vertexNormals (TriMesh::normals()) are only first-order accurate on irregular meshes, and
/// curvature taken from them is several percent off everywhere (7% on an icosphere). Degenerate faces (repeated
/// indices, zero area), faces with an index out of range, open boundaries and non-manifold edges are tolerated: results
/// stay finite. Reuses out's buffers (no allocation when sizes are unchanged: hot path, called per shape).
/// Single-threaded; O(#V + #F).
void computeCurvatures(const Positions& vertices, const Faces& faces, const Positions& vertexNormals, Curvatures& out);

/// Same with the normals computed inside (Max's weights).
void computeCurvatures(const Positions& vertices, const Faces& faces, Curvatures& out);

} // namespace celform::algo
