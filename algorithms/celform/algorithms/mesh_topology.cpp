// Edge adjacency and vertex-to-face tables of a triangle list, and the partial normal update that
// the faces-around-vertex table makes possible.
#include "celform/algorithms/mesh_topology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace celform::algo {
namespace {

bool isProperFace(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t vertexCount)
{
    // Unsigned compare folds "< 0" and ">= vertexCount" into one test.
    const auto n = std::uint32_t(vertexCount);
    return a != b && b != c && a != c && std::uint32_t(a) < n && std::uint32_t(b) < n && std::uint32_t(c) < n;
}

} // namespace

EdgeTopology buildEdgeTopology(const Faces& faces, std::int32_t vertexCount)
{
    // Not the comic paper's pairwise search through a temporary edge list: half-edges are
    // bucketed by their lower vertex (a counting sort, O(F)), and each small bucket is sorted by
    // (upper vertex, face). Equal edges end up adjacent with their faces in face order. Same
    // scheme as analyseTopology() in mesh_analysis.cpp, but it keeps face indices.
    EdgeTopology t;
    const auto nf = std::int32_t(faces.rows());
    const std::int32_t nv = std::max(vertexCount, 0);

    std::vector<std::int32_t> bucketStart(std::size_t(nv) + 1, 0);
    for (std::int32_t f = 0; f < nf; ++f) {
        const std::int32_t a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
        assert(a >= 0 && a < nv && b >= 0 && b < nv && c >= 0 && c < nv);
        if (!isProperFace(a, b, c, nv))
            continue; // degenerate faces have no edges
        ++bucketStart[std::size_t(std::min(a, b)) + 1];
        ++bucketStart[std::size_t(std::min(b, c)) + 1];
        ++bucketStart[std::size_t(std::min(c, a)) + 1];
    }
    for (std::int32_t v = 0; v < nv; ++v)
        bucketStart[std::size_t(v) + 1] += bucketStart[std::size_t(v)];

    // Key: upper vertex in the high 32 bits, face in the low 32 bits.
    std::vector<std::uint64_t> keys(static_cast<std::size_t>(bucketStart[std::size_t(nv)]));
    {
        std::vector<std::int32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
        for (std::int32_t f = 0; f < nf; ++f) {
            const std::int32_t tri[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
            if (!isProperFace(tri[0], tri[1], tri[2], nv))
                continue;
            for (int k = 0; k < 3; ++k) {
                const std::int32_t u = tri[k], w = tri[(k + 1) % 3];
                const std::int32_t lo = std::min(u, w), hi = std::max(u, w);
                keys[std::size_t(fill[std::size_t(lo)]++)] = (std::uint64_t(hi) << 32) | std::uint32_t(f);
            }
        }
    }

    // Sort each bucket and count the distinct edges.
    std::int64_t edgeCount = 0;
    for (std::int32_t lo = 0; lo < nv; ++lo) {
        std::uint64_t* first = keys.data() + bucketStart[std::size_t(lo)];
        std::uint64_t* last = keys.data() + bucketStart[std::size_t(lo) + 1];
        if (last - first > 24) {
            std::sort(first, last); // high-valence vertex (a fan centre)
        } else {
            // Buckets hold about six keys: insertion sort beats std::sort here.
            for (std::uint64_t* i = first + 1; i < last; ++i) {
                const std::uint64_t key = *i;
                std::uint64_t* j = i;
                for (; j > first && *(j - 1) > key; --j)
                    *j = *(j - 1);
                *j = key;
            }
        }
        for (std::uint64_t* i = first; i < last; ++i)
            edgeCount += (i == first || (*i >> 32) != (*(i - 1) >> 32)) ? 1 : 0;
    }

    t.edges.resize(Eigen::Index(edgeCount), 2);
    t.faces.resize(Eigen::Index(edgeCount), 2);
    t.nonManifold.assign(std::size_t(edgeCount), 0);
    Eigen::Index e = 0;
    for (std::int32_t lo = 0; lo < nv; ++lo) {
        const std::uint64_t* i = keys.data() + bucketStart[std::size_t(lo)];
        const std::uint64_t* last = keys.data() + bucketStart[std::size_t(lo) + 1];
        while (i < last) {
            const std::uint64_t hi = *i >> 32;
            const std::uint64_t* j = i + 1;
            while (j < last && (*j >> 32) == hi)
                ++j;
            t.edges(e, 0) = lo;
            t.edges(e, 1) = std::int32_t(hi);
            t.faces(e, 0) = std::int32_t(std::uint32_t(*i));
            t.faces(e, 1) = j - i >= 2 ? std::int32_t(std::uint32_t(*(i + 1))) : -1;
            if (j - i == 1) {
                ++t.borderEdges;
            } else if (j - i > 2) {
                t.nonManifold[std::size_t(e)] = 1;
                ++t.nonManifoldEdges;
            }
            ++e;
            i = j;
        }
    }
    return t;
}

VertexFaces buildVertexFaces(const Faces& faces, std::int32_t vertexCount)
{
    VertexFaces out;
    const auto nv = std::size_t(std::max(vertexCount, 0));
    out.start.assign(nv + 1, 0);
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            if (const auto v = std::uint32_t(faces(f, k)); v < nv)
                ++out.start[std::size_t(v) + 1];
    for (std::size_t v = 0; v < nv; ++v)
        out.start[v + 1] += out.start[v];
    out.faces.resize(std::size_t(out.start[nv]));
    std::vector<std::int32_t> fill(out.start.begin(), out.start.end() - 1);
    // Faces are visited in order, so every vertex's list comes out ascending.
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int k = 0; k < 3; ++k)
            if (const auto v = std::uint32_t(faces(f, k)); v < nv)
                out.faces[std::size_t(fill[v]++)] = std::int32_t(f);
    return out;
}

void updateVertexNormals(const Positions& shape, const Faces& faces, const VertexFaces& around,
    const std::vector<std::uint32_t>& moved, Positions& normals, std::vector<std::int32_t>& scratch)
{
    assert(normals.rows() == shape.rows() && around.start.size() == std::size_t(shape.rows()) + 1);
    // A moved vertex changes the normals of its faces, hence of every corner of those faces.
    scratch.clear();
    for (const std::uint32_t v : moved)
        for (auto i = around.start[v]; i < around.start[v + 1]; ++i) {
            const std::int32_t f = around.faces[std::size_t(i)];
            for (int k = 0; k < 3; ++k)
                scratch.push_back(faces(f, k));
        }
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    // Each affected normal is the area-weighted sum over its own faces, as vertexNormals() sums it.
    for (const std::int32_t v : scratch) {
        Eigen::Vector3f n = Eigen::Vector3f::Zero();
        for (auto i = around.start[std::size_t(v)]; i < around.start[std::size_t(v) + 1]; ++i) {
            const std::int32_t f = around.faces[std::size_t(i)];
            const Eigen::Vector3f a = shape.row(faces(f, 0));
            const Eigen::Vector3f b = shape.row(faces(f, 1));
            const Eigen::Vector3f c = shape.row(faces(f, 2));
            n += (b - a).cross(c - a);
        }
        const float length = n.norm();
        if (length > 0.f && std::isfinite(length))
            normals.row(v) = (n / length).transpose();
        else
            normals.row(v) << 0.f, 0.f, 1.f;
    }
}

} // namespace celform::algo
