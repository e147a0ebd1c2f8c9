// Mesh validation and topology statistics.
#include "celform/algorithms/mesh_analysis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

namespace celform::algo {
namespace {

/// Union-find with path halving; small and fast enough for a million elements.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n)
        : m_parent(n)
    {
        std::iota(m_parent.begin(), m_parent.end(), 0);
    }
    std::int32_t find(std::int32_t x)
    {
        while (m_parent[x] != x) {
            m_parent[x] = m_parent[m_parent[x]];
            x = m_parent[x];
        }
        return x;
    }
    void unite(std::int32_t a, std::int32_t b)
    {
        a = find(a);
        b = find(b);
        if (a != b)
            m_parent[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<std::int32_t> m_parent;
};

} // namespace

std::optional<std::string> findFatalDefect(const TriMesh& mesh)
{
    if (mesh.vertices.rows() == 0)
        return std::string("the mesh has no vertices");
    if (mesh.faces.rows() == 0)
        return std::string("the mesh has no faces");
    const Eigen::Index nv = mesh.vertices.rows();
    for (Eigen::Index i = 0; i < nv; ++i) {
        if (!mesh.vertices.row(i).allFinite()) {
            std::ostringstream s;
            s << "vertex " << i << " has a non-finite coordinate (NaN or infinity)";
            return s.str();
        }
    }
    for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const auto v = mesh.faces(f, k);
            if (v < 0 || v >= nv) {
                std::ostringstream s;
                s << "face " << f << " refers to vertex " << v << ", outside the " << nv << " vertices";
                return s.str();
            }
        }
    }
    return std::nullopt;
}

TopologyReport analyzeTopology(const TriMesh& mesh)
{
    TopologyReport r;
    const auto nv = static_cast<std::int32_t>(mesh.vertices.rows());
    const auto nf = static_cast<std::int32_t>(mesh.faces.rows());

    // Half-edges keyed by (min, max) vertex; the low bit of the payload records direction.
    struct HalfEdge {
        std::uint64_t key;
        std::int32_t face;
        bool forward; // true when the face walks min -> max
    };
    std::vector<HalfEdge> edges;
    edges.reserve(std::size_t(nf) * 3);
    std::vector<char> used(std::size_t(nv), 0);
    for (std::int32_t f = 0; f < nf; ++f) {
        const std::int32_t a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
        used[a] = used[b] = used[c] = 1;
        if (a == b || b == c || a == c) {
            ++r.degenerateFaces;
            continue;
        }
        const Eigen::Vector3f pa = mesh.vertices.row(a), pb = mesh.vertices.row(b), pc = mesh.vertices.row(c);
        if ((pb - pa).cross(pc - pa).squaredNorm() == 0.f)
            ++r.degenerateFaces;
        const std::int32_t tri[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
            const std::int32_t u = tri[k], v = tri[(k + 1) % 3];
            const auto lo = std::uint64_t(std::min(u, v)), hi = std::uint64_t(std::max(u, v));
            edges.push_back({(lo << 32) | hi, f, u < v});
        }
    }
    r.unreferencedVertices = std::count(used.begin(), used.end(), 0);
    std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });

    DisjointSets faceSets(std::size_t(std::max(nf, 1)));
    DisjointSets boundaryVerts(std::size_t(std::max(nv, 1)));
    std::vector<char> onBoundary(std::size_t(nv), 0);
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].key == edges[i].key)
            ++j;
        const std::size_t count = j - i;
        for (std::size_t k = i + 1; k < j; ++k)
            faceSets.unite(edges[i].face, edges[k].face);
        if (count == 1) {
            ++r.boundaryEdges;
            const auto lo = std::int32_t(edges[i].key >> 32), hi = std::int32_t(edges[i].key & 0xffffffffu);
            boundaryVerts.unite(lo, hi);
            onBoundary[lo] = onBoundary[hi] = 1;
        } else if (count == 2) {
            if (edges[i].forward == edges[i + 1].forward)
                ++r.inconsistentEdges;
        } else {
            ++r.nonManifoldEdges;
        }
        i = j;
    }
    // Faces joined only through a vertex count as one piece too: unite faces around each vertex.
    std::vector<std::int32_t> firstFace(std::size_t(nv), -1);
    for (std::int32_t f = 0; f < nf; ++f) {
        for (int k = 0; k < 3; ++k) {
            auto& ff = firstFace[mesh.faces(f, k)];
            if (ff < 0)
                ff = f;
            else
                faceSets.unite(ff, f);
        }
    }
    for (std::int32_t f = 0; f < nf; ++f)
        if (faceSets.find(f) == f)
            ++r.components;
    for (std::int32_t v = 0; v < nv; ++v)
        if (onBoundary[v] && boundaryVerts.find(v) == v)
            ++r.boundaryLoops;
    return r;
}

std::string TopologyReport::summary() const
{
    std::ostringstream s;
    const char* sep = "";
    auto item = [&](std::int64_t n, const char* one, const char* many) {
        if (n <= 0)
            return;
        s << sep << n << ' ' << (n == 1 ? one : many);
        sep = ", ";
    };
    item(boundaryLoops, "hole", "holes");
    if (components > 1)
        item(components, "component", "components");
    item(nonManifoldEdges, "non-manifold edge", "non-manifold edges");
    item(inconsistentEdges, "edge with inconsistent face orientation", "edges with inconsistent face orientation");
    item(degenerateFaces, "degenerate face", "degenerate faces");
    return s.str();
}

} // namespace celform::algo
