// Loop subdivision stencils (subdivision.h).
#include "celform/algorithms/subdivision.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace celform::algo {
namespace {

using Sparse = Eigen::SparseMatrix<double, Eigen::RowMajor, std::int32_t>;
using Triplet = Eigen::Triplet<double, std::int32_t>;

constexpr double kPi = 3.14159265358979323846;

/// One round of Loop subdivision on a topology: the matrix from the vertices of this level to
/// those of the next (vertex points first, then one edge point per edge) and the next faces.
struct Step {
    Sparse matrix;
    Faces faces;
    std::vector<std::int32_t> faceEdge; ///< per face corner k, the edge (c_k, c_k+1)
    std::int32_t vertexCount = 0; ///< of the next level
    std::int64_t creaseEdges = 0;
    std::int64_t nonManifoldEdges = 0;
};

/// Loop's vertex weight beta for an interior vertex of valence n (Loop 1987, section 3.2; the
/// formula of CGAL's Loop_mask_3, which gives 1/16 at n = 6).
double loopBeta(int n)
{
    const double c = 3.0 / 8.0 + std::cos(2.0 * kPi / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
}

Step loopStep(const Faces& faces, std::int32_t vertexCount)
{
    Step step;
    const std::int32_t nf = std::int32_t(faces.rows());
    // Edges by sorting the (smaller, larger) keys of every face corner's edge.
    std::vector<std::int64_t> keys(std::size_t(nf) * 3);
    for (std::int32_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
            const std::int64_t a = faces(f, k), b = faces(f, (k + 1) % 3);
            keys[std::size_t(f) * 3 + std::size_t(k)] = (std::min(a, b) << 32) | std::max(a, b);
        }
    std::vector<std::int32_t> order(keys.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::int32_t x, std::int32_t y) {
        return keys[std::size_t(x)] != keys[std::size_t(y)] ? keys[std::size_t(x)] < keys[std::size_t(y)] : x < y;
    });
    step.faceEdge.assign(keys.size(), 0);
    std::vector<std::int32_t> edgeStart; // into order, per edge
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i == 0 || keys[std::size_t(order[i])] != keys[std::size_t(order[i - 1])])
            edgeStart.push_back(std::int32_t(i));
        step.faceEdge[std::size_t(order[i])] = std::int32_t(edgeStart.size()) - 1;
    }
    const std::int32_t ne = std::int32_t(edgeStart.size());
    edgeStart.push_back(std::int32_t(order.size()));
    step.vertexCount = vertexCount + ne;

    std::vector<Triplet> triplets;
    triplets.reserve(std::size_t(vertexCount) * 8 + std::size_t(ne) * 4);
    std::vector<std::int32_t> valence(std::size_t(vertexCount), 0), creases(std::size_t(vertexCount), 0);
    std::vector<std::array<std::int32_t, 2>> creaseNeighbours(std::size_t(vertexCount), {-1, -1});
    for (std::int32_t e = 0; e < ne; ++e) {
        const std::int32_t first = edgeStart[std::size_t(e)], count = edgeStart[std::size_t(e) + 1] - first;
        const std::int64_t key = keys[std::size_t(order[std::size_t(first)])];
        const auto a = std::int32_t(key >> 32), b = std::int32_t(key & 0xffffffff);
        const std::int32_t row = vertexCount + e;
        if (count == 2 && a != b) {
            // Loop's edge mask: 3/8 of each end, 1/8 of each opposite vertex.
            triplets.emplace_back(row, a, 3.0 / 8.0);
            triplets.emplace_back(row, b, 3.0 / 8.0);
            for (int j = 0; j < 2; ++j) {
                const std::int32_t corner = order[std::size_t(first + j)];
                triplets.emplace_back(row, faces(corner / 3, (corner % 3 + 2) % 3), 1.0 / 8.0);
            }
        } else {
            // A border or non-manifold edge is a crease: its midpoint.
            triplets.emplace_back(row, a, 0.5);
            triplets.emplace_back(row, b, 0.5);
        }
        if (a == b)
            continue;
        ++valence[std::size_t(a)];
        ++valence[std::size_t(b)];
        if (count != 2) {
            ++step.creaseEdges;
            step.nonManifoldEdges += count > 2 ? 1 : 0;
            for (const auto& [v, w] : {std::pair{a, b}, std::pair{b, a}}) {
                auto& c = creases[std::size_t(v)];
                if (c < 2)
                    creaseNeighbours[std::size_t(v)][std::size_t(c)] = w;
                ++c;
            }
        }
    }
    // Vertex points: interior vertices take Loop's beta rule over their neighbours, border
    // vertices the cubic B-spline rule along the border, corners stay.
    for (std::int32_t v = 0; v < vertexCount; ++v) {
        const std::int32_t n = valence[std::size_t(v)], c = creases[std::size_t(v)];
        if (n > 0 && c == 0)
            triplets.emplace_back(v, v, 1.0 - n * loopBeta(n));
        else if (n > 0 && c == 2) {
            triplets.emplace_back(v, v, 6.0 / 8.0);
            triplets.emplace_back(v, creaseNeighbours[std::size_t(v)][0], 1.0 / 8.0);
            triplets.emplace_back(v, creaseNeighbours[std::size_t(v)][1], 1.0 / 8.0);
        } else {
            triplets.emplace_back(v, v, 1.0);
        }
    }
    for (std::int32_t e = 0; e < ne; ++e) {
        const std::int64_t key = keys[std::size_t(order[std::size_t(edgeStart[std::size_t(e)])])];
        const auto a = std::int32_t(key >> 32), b = std::int32_t(key & 0xffffffff);
        if (a == b)
            continue;
        for (const auto& [v, w] : {std::pair{a, b}, std::pair{b, a}})
            if (creases[std::size_t(v)] == 0)
                triplets.emplace_back(v, w, loopBeta(valence[std::size_t(v)]));
    }
    step.matrix.resize(step.vertexCount, vertexCount);
    step.matrix.setFromTriplets(triplets.begin(), triplets.end());

    // Four children per face, corner children first, the middle one last.
    step.faces.resize(Eigen::Index(nf) * 4, 3);
    for (std::int32_t f = 0; f < nf; ++f) {
        const std::int32_t a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
        const std::int32_t ab = vertexCount + step.faceEdge[std::size_t(f) * 3];
        const std::int32_t bc = vertexCount + step.faceEdge[std::size_t(f) * 3 + 1];
        const std::int32_t ca = vertexCount + step.faceEdge[std::size_t(f) * 3 + 2];
        step.faces.row(Eigen::Index(f) * 4) << a, ab, ca;
        step.faces.row(Eigen::Index(f) * 4 + 1) << ab, b, bc;
        step.faces.row(Eigen::Index(f) * 4 + 2) << ca, bc, c;
        step.faces.row(Eigen::Index(f) * 4 + 3) << ab, bc, ca;
    }
    return step;
}

/// The limit tangent masks of each vertex of a topology (rows: vertices, columns: the same
/// vertices). Interior vertex of valence n with its ring c_0 .. c_n-1 counter-clockwise (Loop
/// 1987; Hoppe et al. 1994, section 3.2): t_u = sum cos(2 pi i / n) c_i, t_v = sum sin(2 pi i / n)
/// c_i. Border vertex with k faces and ring c_0 .. c_k (Hoppe et al. 1994, table of boundary
/// tangents, with theta = pi / k): t_u = c_0 - c_k along the border; t_v across it into the
/// surface, c_0 + c_1 - 2 v for k = 1, c_1 - v for k = 2, and for k >= 3
/// -(sin(theta) (c_0 + c_k) + (2 cos(theta) - 2) sum_{i=1}^{k-1} sin(i theta) c_i).
/// Other vertices (not a disc or half-disc) are listed as fallbacks.
void tangentMasks(const Faces& faces, std::int32_t vertexCount, Sparse& tu, Sparse& tv,
    std::vector<std::int32_t>& fallbacks, std::vector<std::int32_t>& fallbackStart,
    std::vector<std::int32_t>& fallbackFaces)
{
    // Per vertex, its corners (face * 3 + k), compressed.
    const std::int32_t nf = std::int32_t(faces.rows());
    std::vector<std::int32_t> start(std::size_t(vertexCount) + 1, 0), corners(std::size_t(nf) * 3);
    for (std::int32_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k)
            ++start[std::size_t(faces(f, k)) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    {
        std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
        for (std::int32_t f = 0; f < nf; ++f)
            for (int k = 0; k < 3; ++k)
                corners[std::size_t(fill[std::size_t(faces(f, k))]++)] = f * 3 + k;
    }
    std::vector<Triplet> u, v;
    u.reserve(std::size_t(vertexCount) * 7);
    v.reserve(std::size_t(vertexCount) * 7);
    std::vector<std::pair<std::int32_t, std::int32_t>> pairs; // (x, y): face (vertex, x, y)
    std::vector<std::int32_t> ring;
    fallbackStart.assign(1, 0);
    for (std::int32_t p = 0; p < vertexCount; ++p) {
        pairs.clear();
        for (std::int32_t i = start[std::size_t(p)]; i < start[std::size_t(p) + 1]; ++i) {
            const std::int32_t f = corners[std::size_t(i)] / 3, k = corners[std::size_t(i)] % 3;
            pairs.emplace_back(faces(f, (k + 1) % 3), faces(f, (k + 2) % 3));
        }
        if (pairs.empty())
            continue; // no face: no normal (zero tangents)
        std::sort(pairs.begin(), pairs.end());
        bool manifold = true;
        for (std::size_t i = 0; i < pairs.size(); ++i)
            if (pairs[i].first == p || pairs[i].second == p || pairs[i].first == pairs[i].second
                || (i > 0 && pairs[i].first == pairs[i - 1].first))
                manifold = false;
        auto next = [&](std::int32_t x) -> std::int32_t {
            const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::pair{x, std::int32_t(-1)});
            return it != pairs.end() && it->first == x ? it->second : -1;
        };
        // A chain starts at an x that no face reaches; a disc has none.
        std::int32_t first = pairs.front().first;
        int starts = 0;
        if (manifold) {
            for (const auto& pr : pairs) {
                const bool reached = std::any_of(
                    pairs.begin(), pairs.end(), [&](const auto& other) { return other.second == pr.first; });
                if (!reached) {
                    first = pr.first;
                    ++starts;
                }
            }
        }
        ring.clear();
        if (manifold && starts <= 1) {
            std::int32_t x = first;
            for (std::size_t i = 0; i <= pairs.size() && x >= 0; ++i) {
                ring.push_back(x);
                x = next(x);
                if (x == first)
                    break;
            }
            const bool closed = starts == 0 && x == first && ring.size() == pairs.size();
            const bool open = starts == 1 && x < 0 && ring.size() == pairs.size() + 1;
            manifold = closed || open;
        }
        if (!manifold || starts > 1) {
            fallbacks.push_back(p);
            for (std::int32_t i = start[std::size_t(p)]; i < start[std::size_t(p) + 1]; ++i)
                fallbackFaces.push_back(corners[std::size_t(i)] / 3);
            fallbackStart.push_back(std::int32_t(fallbackFaces.size()));
            continue;
        }
        if (starts == 0) {
            const int n = int(ring.size());
            for (int i = 0; i < n; ++i) {
                const double angle = 2.0 * kPi * i / n;
                u.emplace_back(p, ring[std::size_t(i)], std::cos(angle));
                v.emplace_back(p, ring[std::size_t(i)], std::sin(angle));
            }
            continue;
        }
        const int k = int(ring.size()) - 1;
        u.emplace_back(p, ring.front(), 1.0);
        u.emplace_back(p, ring.back(), -1.0);
        if (k == 1) {
            v.emplace_back(p, ring[0], 1.0);
            v.emplace_back(p, ring[1], 1.0);
            v.emplace_back(p, p, -2.0);
        } else if (k == 2) {
            v.emplace_back(p, ring[1], 1.0);
            v.emplace_back(p, p, -1.0);
        } else {
            const double theta = kPi / k;
            v.emplace_back(p, ring.front(), -std::sin(theta));
            v.emplace_back(p, ring.back(), -std::sin(theta));
            for (int i = 1; i < k; ++i)
                v.emplace_back(p, ring[std::size_t(i)], -(2.0 * std::cos(theta) - 2.0) * std::sin(i * theta));
        }
    }
    tu.resize(vertexCount, vertexCount);
    tu.setFromTriplets(u.begin(), u.end());
    tv.resize(vertexCount, vertexCount);
    tv.setFromTriplets(v.begin(), v.end());
}

SparseRows toRows(const Sparse& m)
{
    SparseRows r;
    r.columns = std::int32_t(m.cols());
    r.start.assign(std::size_t(m.rows()) + 1, 0);
    r.cols.reserve(std::size_t(m.nonZeros()));
    r.weights.reserve(std::size_t(m.nonZeros()));
    for (Eigen::Index row = 0; row < m.outerSize(); ++row) {
        for (Sparse::InnerIterator it(m, row); it; ++it)
            if (it.value() != 0.0) {
                r.cols.push_back(std::int32_t(it.col()));
                r.weights.push_back(it.value());
            }
        r.start[std::size_t(row) + 1] = std::int32_t(r.cols.size());
    }
    return r;
}

/// The rows reading each column, over the union of the patterns of a and (optionally) b.
void reachOf(
    const SparseRows& a, const SparseRows* b, std::vector<std::int32_t>& start, std::vector<std::int32_t>& rows)
{
    const std::int32_t columns = a.columns;
    std::vector<std::int32_t> lastRow(std::size_t(columns), -1);
    start.assign(std::size_t(columns) + 1, 0);
    auto forEach = [&](auto&& visit) {
        std::fill(lastRow.begin(), lastRow.end(), -1);
        for (std::int32_t r = 0; r < a.rows(); ++r)
            for (const SparseRows* m : {&a, b}) {
                if (!m)
                    continue;
                for (std::int32_t k = m->start[std::size_t(r)]; k < m->start[std::size_t(r) + 1]; ++k) {
                    const std::int32_t c = m->cols[std::size_t(k)];
                    if (lastRow[std::size_t(c)] != r) {
                        lastRow[std::size_t(c)] = r;
                        visit(r, c);
                    }
                }
            }
    };
    forEach([&](std::int32_t, std::int32_t c) { ++start[std::size_t(c) + 1]; });
    std::partial_sum(start.begin(), start.end(), start.begin());
    rows.resize(std::size_t(start.back()));
    std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
    forEach([&](std::int32_t r, std::int32_t c) { rows[std::size_t(fill[std::size_t(c)]++)] = r; });
}

template <typename In> inline Eigen::Vector3d row3(const SparseRows& m, std::int32_t r, const In* in)
{
    double x = 0, y = 0, z = 0;
    for (std::int32_t k = m.start[std::size_t(r)], end = m.start[std::size_t(r) + 1]; k < end; ++k) {
        const double w = m.weights[std::size_t(k)];
        const In* p = in + std::size_t(m.cols[std::size_t(k)]) * 3;
        x += w * double(p[0]);
        y += w * double(p[1]);
        z += w * double(p[2]);
    }
    return {x, y, z};
}

template <typename In, typename Out> void applyRows(const SparseRows& m, const In* in, Out* out)
{
    for (std::int32_t r = 0; r < m.rows(); ++r) {
        const Eigen::Vector3d v = row3(m, r, in);
        Out* o = out + std::size_t(r) * 3;
        o[0] = Out(v.x());
        o[1] = Out(v.y());
        o[2] = Out(v.z());
    }
}

/// Sum of a row's weights times float triples, in float: tangents only give a direction.
inline void tangentRow(const SparseRows& m, std::int32_t r, const float* in, float& x, float& y, float& z)
{
    x = y = z = 0.f;
    for (std::int32_t k = m.start[std::size_t(r)], end = m.start[std::size_t(r) + 1]; k < end; ++k) {
        const float w = float(m.weights[std::size_t(k)]);
        const float* p = in + std::size_t(m.cols[std::size_t(k)]) * 3;
        x += w * p[0];
        y += w * p[1];
        z += w * p[2];
    }
}

void normalRow(const SubdivisionStencil& s, std::int32_t r, const float* positions, float* out)
{
    float ux, uy, uz, vx, vy, vz;
    tangentRow(s.tangentU, r, positions, ux, uy, uz);
    tangentRow(s.tangentV, r, positions, vx, vy, vz);
    const float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const float len2 = nx * nx + ny * ny + nz * nz;
    float* o = out + std::size_t(r) * 3;
    if (len2 > 0.f) {
        const float inv = 1.f / std::sqrt(len2);
        o[0] = nx * inv;
        o[1] = ny * inv;
        o[2] = nz * inv;
    } else {
        o[0] = o[1] = 0.f;
        o[2] = 1.f;
    }
}

void fallbackNormals(const SubdivisionStencil& s, const Positions& positions, Positions& out)
{
    for (std::size_t i = 0; i < s.fallbackVertices.size(); ++i) {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        for (std::int32_t k = s.fallbackStart[i]; k < s.fallbackStart[i + 1]; ++k) {
            const std::int32_t f = s.fallbackFaces[std::size_t(k)];
            const Eigen::Vector3d a = positions.row(s.faces(f, 0)).cast<double>();
            const Eigen::Vector3d b = positions.row(s.faces(f, 1)).cast<double>();
            const Eigen::Vector3d c = positions.row(s.faces(f, 2)).cast<double>();
            n += (b - a).cross(c - a); // twice the area times the unit normal
        }
        const double len = n.norm();
        out.row(s.fallbackVertices[i]) = (len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::UnitZ()).cast<float>();
    }
}

} // namespace

std::size_t SubdivisionStencil::bytes() const
{
    auto rowsBytes = [](const SparseRows& m) {
        return m.start.size() * sizeof(std::int32_t) + m.cols.size() * (sizeof(std::int32_t) + sizeof(double));
    };
    return rowsBytes(positions) + rowsBytes(tangentU) + rowsBytes(tangentV)
        + std::size_t(faces.size()) * sizeof(std::int32_t) + parentFace.size() * sizeof(std::int32_t)
        + (positionReach.size() + tangentReach.size() + positionReachStart.size() + tangentReachStart.size())
        * sizeof(std::int32_t);
}

std::int64_t subdividedFaceCount(std::int64_t controlFaces, int level)
{
    return controlFaces << (2 * std::clamp(level, 0, kMaxSubdivisionLevel));
}

std::int64_t subdividedVertexBound(std::int64_t controlVertices, std::int64_t controlFaces, int level)
{
    // V' = V + E, E' = 2 E + 3 F, F' = 4 F, with E <= 3 F.
    std::int64_t v = controlVertices, e = 3 * controlFaces, f = controlFaces;
    for (int l = 0; l < std::clamp(level, 0, kMaxSubdivisionLevel); ++l) {
        v += e;
        e = 2 * e + 3 * f;
        f *= 4;
    }
    return v;
}

SubdivisionStencil buildSubdivisionStencil(const Faces& faces, std::int32_t vertexCount, int level)
{
    SubdivisionStencil s;
    s.level = std::clamp(level, 0, kMaxSubdivisionLevel);
    s.controlVertices = vertexCount;
    s.controlFaces = std::int32_t(faces.rows());
    Sparse stencil(vertexCount, vertexCount);
    stencil.setIdentity();
    s.faces = faces;
    std::int32_t count = vertexCount;
    for (int l = 0; l < s.level; ++l) {
        Step step = loopStep(s.faces, count);
        if (l == 0) {
            s.creaseEdges = step.creaseEdges;
            s.nonManifoldEdges = step.nonManifoldEdges;
            stencil = std::move(step.matrix);
        } else {
            stencil = Sparse(step.matrix * stencil);
        }
        s.faces = std::move(step.faces);
        count = step.vertexCount;
    }
    if (s.level == 0) {
        const Step step = loopStep(faces, vertexCount); // for the crease counts alone
        s.creaseEdges = step.creaseEdges;
        s.nonManifoldEdges = step.nonManifoldEdges;
    }
    // Children of a control face are its 4^L consecutive faces.
    s.parentFace.resize(std::size_t(s.faces.rows()));
    for (std::size_t f = 0; f < s.parentFace.size(); ++f)
        s.parentFace[f] = std::int32_t(f >> (2 * s.level));
    s.positions = toRows(stencil);
    Sparse tu, tv;
    tangentMasks(s.faces, count, tu, tv, s.fallbackVertices, s.fallbackStart, s.fallbackFaces);
    s.tangentU = toRows(tu);
    s.tangentV = toRows(tv);
    reachOf(s.positions, nullptr, s.positionReachStart, s.positionReach);
    reachOf(s.tangentU, &s.tangentV, s.tangentReachStart, s.tangentReach);
    return s;
}

void applySubdivision(const SubdivisionStencil& s, const Positions& control, Positions& out)
{
    if (out.rows() != s.vertexCount())
        out.resize(s.vertexCount(), 3);
    applyRows(s.positions, control.data(), out.data());
}

void applySubdivision(const SubdivisionStencil& s, const Eigen::MatrixX3d& control, Eigen::MatrixX3d& out)
{
    // Column-major storage: one column at a time.
    out.resize(s.vertexCount(), 3);
    const SparseRows& m = s.positions;
    for (std::int32_t r = 0; r < m.rows(); ++r) {
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        for (std::int32_t k = m.start[std::size_t(r)]; k < m.start[std::size_t(r) + 1]; ++k)
            sum += m.weights[std::size_t(k)] * control.row(m.cols[std::size_t(k)]);
        out.row(r) = sum;
    }
}

void applySubdivision(const SubdivisionStencil& s, const std::vector<float>& control, std::vector<float>& out)
{
    const SparseRows& m = s.positions;
    out.resize(std::size_t(m.rows()));
    for (std::int32_t r = 0; r < m.rows(); ++r) {
        double sum = 0;
        for (std::int32_t k = m.start[std::size_t(r)]; k < m.start[std::size_t(r) + 1]; ++k)
            sum += m.weights[std::size_t(k)] * double(control[std::size_t(m.cols[std::size_t(k)])]);
        out[std::size_t(r)] = float(sum);
    }
}

void limitNormals(const SubdivisionStencil& s, const Positions& positions, Positions& out)
{
    if (out.rows() != s.vertexCount())
        out.resize(s.vertexCount(), 3);
    for (std::int32_t r = 0; r < s.vertexCount(); ++r)
        normalRow(s, r, positions.data(), out.data());
    fallbackNormals(s, positions, out);
}

std::size_t updateSubdivision(const SubdivisionStencil& s, const Positions& control,
    const std::vector<std::uint32_t>& changed, Positions& positions, Positions& normals, SubdivisionScratch& scratch)
{
    const std::size_t rows = std::size_t(s.vertexCount());
    if (scratch.positionStamp.size() != rows) {
        scratch.positionStamp.assign(rows, 0);
        scratch.tangentStamp.assign(rows, 0);
        scratch.positionRows.reserve(rows);
        scratch.tangentRows.reserve(rows);
        scratch.stamp = 0;
    }
    if (++scratch.stamp == 0) {
        std::fill(scratch.positionStamp.begin(), scratch.positionStamp.end(), 0);
        std::fill(scratch.tangentStamp.begin(), scratch.tangentStamp.end(), 0);
        scratch.stamp = 1;
    }
    scratch.positionRows.clear();
    scratch.tangentRows.clear();
    for (const std::uint32_t c : changed) {
        if (c >= std::uint32_t(s.controlVertices))
            continue;
        for (std::int32_t k = s.positionReachStart[c]; k < s.positionReachStart[c + 1]; ++k) {
            const std::int32_t r = s.positionReach[std::size_t(k)];
            if (scratch.positionStamp[std::size_t(r)] != scratch.stamp) {
                scratch.positionStamp[std::size_t(r)] = scratch.stamp;
                scratch.positionRows.push_back(r);
            }
        }
    }
    // The positions first, then the normals of every vertex whose ring holds a moved one.
    for (const std::int32_t r : scratch.positionRows) {
        const Eigen::Vector3d v = row3(s.positions, r, control.data());
        positions.row(r) = v.cast<float>();
        for (std::int32_t k = s.tangentReachStart[std::size_t(r)]; k < s.tangentReachStart[std::size_t(r) + 1]; ++k) {
            const std::int32_t t = s.tangentReach[std::size_t(k)];
            if (scratch.tangentStamp[std::size_t(t)] != scratch.stamp) {
                scratch.tangentStamp[std::size_t(t)] = scratch.stamp;
                scratch.tangentRows.push_back(t);
            }
        }
    }
    for (const std::int32_t r : scratch.tangentRows)
        normalRow(s, r, positions.data(), normals.data());
    if (!scratch.positionRows.empty())
        fallbackNormals(s, positions, normals);
    return scratch.positionRows.size();
}

Eigen::RowVector3d cornerBarycentric(const SubdivisionStencil& s, Eigen::Index face, int corner)
{
    // Walk down from the control face: at each level the child's digit (base 4, most significant
    // first) picks its corners among the parent's corners and edge midpoints (loopStep's order).
    std::array<Eigen::RowVector3d, 3> c{
        Eigen::RowVector3d(1, 0, 0), Eigen::RowVector3d(0, 1, 0), Eigen::RowVector3d(0, 0, 1)};
    for (int l = s.level - 1; l >= 0; --l) {
        const int child = int((face >> (2 * l)) & 3);
        const Eigen::RowVector3d ab = (c[0] + c[1]) / 2, bc = (c[1] + c[2]) / 2, ca = (c[2] + c[0]) / 2;
        switch (child) {
        case 0:
            c = {c[0], ab, ca};
            break;
        case 1:
            c = {ab, c[1], bc};
            break;
        case 2:
            c = {ca, bc, c[2]};
            break;
        default:
            c = {ab, bc, ca};
            break;
        }
    }
    return c[std::size_t(corner)];
}

TexCoords subdividedCornerUvs(const SubdivisionStencil& s, const TexCoords& uvs, const Faces& uvFaces)
{
    TexCoords out(s.faces.rows() * 3, 2);
    for (Eigen::Index f = 0; f < s.faces.rows(); ++f) {
        const std::int32_t parent = s.parentFace[std::size_t(f)];
        for (int k = 0; k < 3; ++k) {
            const Eigen::RowVector3f b = cornerBarycentric(s, f, k).cast<float>();
            out.row(f * 3 + k) = b(0) * uvs.row(uvFaces(parent, 0)) + b(1) * uvs.row(uvFaces(parent, 1))
                + b(2) * uvs.row(uvFaces(parent, 2));
        }
    }
    return out;
}

std::vector<std::int32_t> subdividedFaceSet(const SubdivisionStencil& s, const std::vector<std::int32_t>& controlFaces)
{
    // Children of one control face are 4^L consecutive faces starting at parent * 4^L.
    const std::int32_t children = std::int32_t(1) << (2 * s.level);
    std::vector<std::int32_t> out;
    out.reserve(controlFaces.size() * std::size_t(children));
    for (const std::int32_t f : controlFaces)
        if (f >= 0 && f < s.controlFaces)
            for (std::int32_t i = 0; i < children; ++i)
                out.push_back(f * children + i);
    return out;
}

} // namespace celform::algo
