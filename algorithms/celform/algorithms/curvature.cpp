// Rusinkiewicz, "Estimating Curvatures and Their Derivatives on Triangle Meshes" (3DPVT 2004):
// each face fits a second fundamental form to the change of the vertex normals along its edges
// (section 3), every vertex averages the forms of its faces in its own tangent frame with mixed
// Voronoi weights (Meyer et al. 2003) and diagonalises; then the same fit and average one order up
// gives the curvature derivative tensor (section 4). Written from the paper.
#include "celform/algorithms/curvature.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace celform::algo {

namespace {

using Vec3 = Eigen::Vector3f;
using Vec2 = Eigen::Vector2f;

// Row access without Eigen's run-time checks (assertions stay on in release builds here): row-major,
// so a row is 3 consecutive floats.
inline Vec3 row(const Positions& p, std::int32_t i)
{
    const float* x = p.data() + 3 * std::ptrdiff_t(i);
    return Vec3(x[0], x[1], x[2]);
}

inline void setRow(Positions& p, std::int32_t i, const Vec3& v)
{
    float* x = p.data() + 3 * std::ptrdiff_t(i);
    x[0] = v.x();
    x[1] = v.y();
    x[2] = v.z();
}

/// A unit vector perpendicular to the unit vector n, a function of n alone: n crossed with the
/// coordinate axis least aligned with it (never shorter than sqrt(2/3) before normalising).
Vec3 anyTangent(const Vec3& n)
{
    const Vec3 a = n.cwiseAbs();
    Vec3 t;
    if (a.x() <= a.y() && a.x() <= a.z())
        t = Vec3(0.f, -n.z(), n.y()); // x axis cross n
    else if (a.y() <= a.z())
        t = Vec3(n.z(), 0.f, -n.x()); // y axis cross n
    else
        t = Vec3(-n.y(), n.x(), 0.f); // z axis cross n
    return t.normalized();
}

/// Solves the symmetric positive definite tridiagonal system with diagonal d and off-diagonal e
/// (both fits' normal equations have this shape) by LDL^T. False when it is not positive definite.
template <int N> bool solveTridiagonal(const float (&d)[N], const float (&e)[N - 1], const float (&r)[N], float (&x)[N])
{
    float diag[N], l[N], y[N];
    diag[0] = d[0];
    y[0] = r[0];
    l[0] = 0.f;
    for (int i = 1; i < N; ++i) {
        if (!(diag[i - 1] > 0.f))
            return false;
        l[i] = e[i - 1] / diag[i - 1];
        diag[i] = d[i] - l[i] * e[i - 1];
        y[i] = r[i] - l[i] * y[i - 1];
    }
    if (!(diag[N - 1] > 0.f))
        return false;
    x[N - 1] = y[N - 1] / diag[N - 1];
    for (int i = N - 2; i >= 0; --i)
        x[i] = y[i] / diag[i] - l[i + 1] * x[i + 1];
    for (int i = 0; i < N; ++i)
        if (!std::isfinite(x[i]))
            return false;
    return true;
}

/// A face's orthonormal frame (t, b, n) and its edges, or nothing usable when degenerate.
struct FaceFrame {
    std::int32_t v[3];
    Vec3 e[3]; ///< e[i] is the edge opposite corner i, running from corner i+1 to corner i+2
    Vec3 t, b, n;
    float doubleArea = 0.f;
};

/// Fills f for face `face`; false when an index is out of range or the face has (next to) no area
/// relative to its edge lengths, in which case the face takes no part in any average.
bool faceFrame(const Positions& vertices, const Faces& faces, Eigen::Index face, FaceFrame& f)
{
    const auto vertexCount = std::int32_t(vertices.rows());
    const std::int32_t* corners = faces.data() + 3 * face;
    for (int i = 0; i < 3; ++i) {
        f.v[i] = corners[i];
        if (f.v[i] < 0 || f.v[i] >= vertexCount)
            return false;
    }
    const Vec3 p0 = row(vertices, f.v[0]), p1 = row(vertices, f.v[1]), p2 = row(vertices, f.v[2]);
    f.e[0] = p2 - p1;
    f.e[1] = p0 - p2;
    f.e[2] = p1 - p0;
    const Vec3 normal = f.e[2].cross(f.e[0]);
    f.doubleArea = normal.norm();
    const float lengths2 = f.e[0].squaredNorm() + f.e[1].squaredNorm() + f.e[2].squaredNorm();
    // Below this the cross product is float round-off (also false for NaN and repeated indices).
    if (!(f.doubleArea > 1e-6f * lengths2) || !std::isfinite(lengths2))
        return false;
    f.n = (1.f / f.doubleArea) * normal;
    f.t = (1.f / f.e[0].norm()) * f.e[0];
    f.b = f.n.cross(f.t);
    return true;
}

/// Mixed Voronoi area of each corner (Meyer et al. 2003, section 3.3): the Voronoi region inside the
/// triangle where it is not obtuse, else half the area for the obtuse corner, a quarter for the others.
Vec3 cornerAreas(const FaceFrame& f)
{
    const float area = 0.5f * f.doubleArea;
    // Dot products of the two edges leaving each corner: negative at an obtuse corner.
    const float d0 = -f.e[1].dot(f.e[2]);
    const float d1 = -f.e[2].dot(f.e[0]);
    const float d2 = -f.e[0].dot(f.e[1]);
    if (d0 < 0.f)
        return Vec3(0.5f * area, 0.25f * area, 0.25f * area);
    if (d1 < 0.f)
        return Vec3(0.25f * area, 0.5f * area, 0.25f * area);
    if (d2 < 0.f)
        return Vec3(0.25f * area, 0.25f * area, 0.5f * area);
    // cot(angle at corner i) = d_i / doubleArea; the region of a corner is 1/8 of sum |edge|^2 cot
    // over its two edges, each with the cotangent of the angle opposite that edge.
    const float l0 = f.e[0].squaredNorm(), l1 = f.e[1].squaredNorm(), l2 = f.e[2].squaredNorm();
    const float s = 0.125f / f.doubleArea;
    return Vec3(s * (l2 * d2 + l1 * d1), s * (l2 * d2 + l0 * d0), s * (l0 * d0 + l1 * d1));
}

/// The face axes t, b carried into the tangent plane of the vertex normal nv by the smallest rotation
/// taking the face normal to nv: a vertex-frame vector x has face coordinates (x . tv, x . bv), which
/// is Rusinkiewicz's rotation of the vertex frame into the face plane, done on the face's side.
void faceAxesAtVertex(const FaceFrame& f, const Vec3& nv, Vec3& tv, Vec3& bv)
{
    const float c = f.n.dot(nv);
    if (c > -0.9999f) {
        // Rodrigues with k = n x nv (|k| = sin): R y = c y + k x y + (k . y) k / (1 + c).
        const Vec3 k = f.n.cross(nv);
        const float s = 1.f / (1.f + c);
        tv = c * f.t + k.cross(f.t) + (s * k.dot(f.t)) * k;
        bv = c * f.b + k.cross(f.b) + (s * k.dot(f.b)) * k;
    } else { // normal opposite the face: half a turn about t
        tv = f.t;
        bv = -f.b;
    }
}

/// Quadratic form (a, b, c) = [a b; b c] evaluated as x^T Q y.
float form(float a, float b, float c, const Vec2& x, const Vec2& y)
{
    return a * x.x() * y.x() + b * (x.x() * y.y() + x.y() * y.x()) + c * x.y() * y.y();
}

/// Symmetric cubic form with entries (C111, C112, C122, C222) evaluated as C(x, y, z).
float cubic(const Eigen::Vector4f& C, const Vec2& x, const Vec2& y, const Vec2& z)
{
    return C[0] * x.x() * y.x() * z.x() + C[1] * (x.x() * y.x() * z.y() + x.x() * y.y() * z.x() + x.y() * y.x() * z.x())
        + C[2] * (x.x() * y.y() * z.y() + x.y() * y.x() * z.y() + x.y() * y.y() * z.x()) + C[3] * x.y() * y.y() * z.y();
}

/// The unit normals the fit differentiates: the given ones, or else Max's weights (N. Max, "Weights
/// for computing vertex normals from facet normals", JGT 1999): each corner adds a x b / (|a|^2 |b|^2)
/// for its two edges a, b, which is exact for vertices on a sphere. Area-weighted normals are only
/// first-order accurate on irregular meshes, and differentiating them gives curvature errors that
/// do not shrink with refinement (7% on an icosphere, integral of K 77% off on the bunny).
void prepareNormals(const Positions& vertices, const Faces& faces, const Positions& given, Positions& normals)
{
    const Eigen::Index vertexCount = vertices.rows();
    normals.resize(vertexCount, 3);
    if (given.rows() == vertexCount) {
        normals = given;
    } else {
        normals.setZero();
        for (Eigen::Index f = 0; f < faces.rows(); ++f) {
            const std::int32_t v[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
            if (std::min({v[0], v[1], v[2]}) < 0 || std::max({v[0], v[1], v[2]}) >= vertexCount)
                continue;
            const Vec3 p[3] = {row(vertices, v[0]), row(vertices, v[1]), row(vertices, v[2])};
            const Vec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};
            const Vec3 n = e[2].cross(e[0]);
            const float l2[3] = {e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm()};
            for (int j = 0; j < 3; ++j) {
                // corner j lies between edges j+1 and j+2
                const float weight = 1.f / (l2[(j + 1) % 3] * l2[(j + 2) % 3]);
                if (std::isfinite(weight))
                    setRow(normals, v[j], row(normals, v[j]) + weight * n);
            }
        }
    }
    for (Eigen::Index i = 0; i < vertexCount; ++i) {
        const Vec3 n = row(normals, std::int32_t(i));
        const float len = n.norm();
        setRow(normals, std::int32_t(i), len > 0.f && std::isfinite(len) ? Vec3(n / len) : Vec3(0.f, 0.f, 1.f));
    }
}

/// One-ring lists (CSR, duplicates allowed) of every vertex, from the faces with valid indices.
void buildRings(const Faces& faces, std::int32_t vertexCount, Curvatures::Workspace& w)
{
    w.ringStart.assign(std::size_t(vertexCount) + 1, 0);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const std::int32_t i0 = faces(f, 0), i1 = faces(f, 1), i2 = faces(f, 2);
        if (std::min({i0, i1, i2}) < 0 || std::max({i0, i1, i2}) >= vertexCount)
            continue;
        w.ringStart[std::size_t(i0) + 1] += 2;
        w.ringStart[std::size_t(i1) + 1] += 2;
        w.ringStart[std::size_t(i2) + 1] += 2;
    }
    for (std::size_t v = 0; v < std::size_t(vertexCount); ++v)
        w.ringStart[v + 1] += w.ringStart[v];
    w.ring.resize(std::size_t(w.ringStart.back()));
    w.ringMark.assign(w.ringStart.begin(), w.ringStart.end() - 1); // fill cursors
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const std::int32_t v[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
        if (std::min({v[0], v[1], v[2]}) < 0 || std::max({v[0], v[1], v[2]}) >= vertexCount)
            continue;
        for (int j = 0; j < 3; ++j) {
            std::int32_t& cursor = w.ringMark[std::size_t(v[j])];
            w.ring[std::size_t(cursor++)] = v[(j + 1) % 3];
            w.ring[std::size_t(cursor++)] = v[(j + 2) % 3];
        }
    }
}

} // namespace

void computeCurvatures(const Positions& vertices, const Faces& faces, const Positions& vertexNormals, Curvatures& out)
{
    const auto vertexCount = std::int32_t(vertices.rows());
    const auto faceCount = std::size_t(faces.rows());
    const auto nv = std::size_t(vertexCount);
    Curvatures::Workspace& w = out.workspace;

    prepareNormals(vertices, faces, vertexNormals, w.normals);
    out.k1.assign(nv, 0.f);
    out.k2.assign(nv, 0.f);
    out.dir1.resize(vertexCount, 3);
    out.dir2.resize(vertexCount, 3);
    out.dcurv.assign(nv, Eigen::Vector4f::Zero());
    out.pointArea.assign(nv, 0.f);
    out.gaussian.assign(nv, 0.f);
    out.gaussianRaw.assign(nv, 0.f);
    w.cornerAreas.assign(faceCount, Vec3::Zero());
    w.fundamental.assign(nv, Vec3::Zero());

    // An arbitrary tangent frame per vertex (dir1, dir2, normal right-handed) to hold its form in.
    for (std::int32_t v = 0; v < vertexCount; ++v) {
        const Vec3 n = row(w.normals, v);
        const Vec3 u = anyTangent(n);
        setRow(out.dir1, v, u);
        setRow(out.dir2, v, n.cross(u));
    }

    // Section 3: per face, the second fundamental form II with II * (e . t, e . b) = (dn . t, dn . b)
    // for the normal change dn along each edge e, by least squares; added to each corner's vertex in
    // that vertex's frame, weighted by the corner's mixed area.
    FaceFrame f;
    for (std::size_t face = 0; face < faceCount; ++face) {
        if (!faceFrame(vertices, faces, Eigen::Index(face), f))
            continue;
        const Vec3 areas = cornerAreas(f);
        w.cornerAreas[face] = areas;
        for (int j = 0; j < 3; ++j)
            out.pointArea[std::size_t(f.v[j])] += areas[j];

        float d[3] = {0.f, 0.f, 0.f}, e[2] = {0.f, 0.f}, r[3] = {0.f, 0.f, 0.f}, x[3];
        for (int i = 0; i < 3; ++i) {
            const Vec3 dn = row(w.normals, f.v[(i + 2) % 3]) - row(w.normals, f.v[(i + 1) % 3]);
            const float u = f.e[i].dot(f.t), v = f.e[i].dot(f.b);
            const float dnu = dn.dot(f.t), dnv = dn.dot(f.b);
            // rows (u, v, 0) . (L, M, N) = dnu and (0, u, v) . (L, M, N) = dnv
            d[0] += u * u;
            d[1] += u * u + v * v;
            d[2] += v * v;
            e[0] += u * v;
            r[0] += u * dnu;
            r[1] += v * dnu + u * dnv;
            r[2] += v * dnv;
        }
        e[1] = e[0];
        if (!solveTridiagonal<3>(d, e, r, x))
            continue;
        for (int j = 0; j < 3; ++j) {
            const std::int32_t vj = f.v[j];
            Vec3 tv, bv;
            faceAxesAtVertex(f, row(w.normals, vj), tv, bv);
            const Vec3 a1 = row(out.dir1, vj), a2 = row(out.dir2, vj);
            const Vec2 p(a1.dot(tv), a1.dot(bv)), q(a2.dot(tv), a2.dot(bv));
            w.fundamental[std::size_t(vj)] += areas[j]
                * Vec3(form(x[0], x[1], x[2], p, p), form(x[0], x[1], x[2], p, q), form(x[0], x[1], x[2], q, q));
        }
    }

    // Diagonalise each vertex's averaged form: principal curvatures and directions.
    for (std::int32_t v = 0; v < vertexCount; ++v) {
        const float area = out.pointArea[std::size_t(v)];
        if (!(area > 0.f))
            continue; // no usable face: curvature 0, the arbitrary frame stays
        const Vec3 II = w.fundamental[std::size_t(v)] / area;
        const float mean = 0.5f * (II[0] + II[2]), half = 0.5f * (II[0] - II[2]);
        const float radius = std::sqrt(half * half + II[1] * II[1]);
        if (!std::isfinite(mean) || !std::isfinite(radius))
            continue; // overflow on a pathological neighbourhood: report 0 rather than inf or NaN
        // Eigenvector of mean + radius from whichever row of (II - k1 I) is better conditioned.
        Vec2 dir = half >= 0.f ? Vec2(half + radius, II[1]) : Vec2(II[1], radius - half);
        const float len = dir.norm();
        dir = len > 0.f ? Vec2(dir / len) : Vec2(1.f, 0.f); // umbilic: any direction
        const Vec3 a1 = row(out.dir1, v), a2 = row(out.dir2, v);
        setRow(out.dir1, v, dir.x() * a1 + dir.y() * a2);
        setRow(out.dir2, v, dir.x() * a2 - dir.y() * a1); // normal x dir1
        out.k1[std::size_t(v)] = mean + radius;
        out.k2[std::size_t(v)] = mean - radius;
        out.gaussianRaw[std::size_t(v)] = (mean + radius) * (mean - radius);
    }

    // Section 4: per face, the derivative tensor C of II from the change of the vertices' forms along
    // the edges (each form expressed in the face frame), by least squares; projected on each corner
    // vertex's principal frame and averaged with the same weights.
    for (std::size_t face = 0; face < faceCount; ++face) {
        const Vec3 areas = w.cornerAreas[face];
        if (areas.isZero() || !faceFrame(vertices, faces, Eigen::Index(face), f))
            continue;
        Vec2 p[3], q[3]; // principal directions of the corners in face coordinates
        Vec3 II[3]; // the corners' forms in face coordinates
        for (int j = 0; j < 3; ++j) {
            const std::int32_t vj = f.v[j];
            Vec3 tv, bv;
            faceAxesAtVertex(f, row(w.normals, vj), tv, bv);
            const Vec3 a1 = row(out.dir1, vj), a2 = row(out.dir2, vj);
            p[j] = Vec2(a1.dot(tv), a1.dot(bv));
            q[j] = Vec2(a2.dot(tv), a2.dot(bv));
            const float k1 = out.k1[std::size_t(vj)], k2 = out.k2[std::size_t(vj)];
            II[j] = Vec3(k1 * p[j].x() * p[j].x() + k2 * q[j].x() * q[j].x(),
                k1 * p[j].x() * p[j].y() + k2 * q[j].x() * q[j].y(),
                k1 * p[j].y() * p[j].y() + k2 * q[j].y() * q[j].y());
        }
        float d[4] = {0.f, 0.f, 0.f, 0.f}, e[3] = {0.f, 0.f, 0.f}, r[4] = {0.f, 0.f, 0.f, 0.f}, x[4];
        for (int i = 0; i < 3; ++i) {
            const Vec3 dII = II[(i + 2) % 3] - II[(i + 1) % 3];
            const float u = f.e[i].dot(f.t), v = f.e[i].dot(f.b);
            // rows (u, v, 0, 0), (0, u, v, 0), (0, 0, u, v) . (C111, C112, C122, C222) = dII, the middle
            // one counted twice: the residual is the Frobenius norm of the 2x2 change of II, in which
            // II12 appears twice, and so the fit does not depend on which edge the face frame starts from.
            d[0] += u * u;
            d[1] += 2.f * u * u + v * v;
            d[2] += u * u + 2.f * v * v;
            d[3] += v * v;
            e[0] += u * v;
            r[0] += u * dII[0];
            r[1] += v * dII[0] + 2.f * u * dII[1];
            r[2] += 2.f * v * dII[1] + u * dII[2];
            r[3] += v * dII[2];
        }
        e[1] = 2.f * e[0];
        e[2] = e[0];
        if (!solveTridiagonal<4>(d, e, r, x))
            continue;
        const Eigen::Vector4f C(x[0], x[1], x[2], x[3]);
        for (int j = 0; j < 3; ++j)
            out.dcurv[std::size_t(f.v[j])] += areas[j]
                * Eigen::Vector4f(cubic(C, p[j], p[j], p[j]), cubic(C, p[j], p[j], q[j]), cubic(C, p[j], q[j], q[j]),
                    cubic(C, q[j], q[j], q[j]));
    }
    for (std::size_t v = 0; v < nv; ++v)
        if (out.pointArea[v] > 0.f && out.dcurv[v].allFinite())
            out.dcurv[v] /= out.pointArea[v];
        else
            out.dcurv[v].setZero();

    // Paper 3, section 4.5.1: one pass of area-weighted averaging over the closed one-ring, against
    // the noise of the discrete Gaussian curvature. ringMark stamps the neighbours already counted.
    buildRings(faces, vertexCount, w);
    w.ringMark.assign(nv, -1);
    for (std::int32_t v = 0; v < vertexCount; ++v) {
        const std::size_t sv = std::size_t(v);
        w.ringMark[sv] = v;
        double weight = out.pointArea[sv], sum = double(out.pointArea[sv]) * out.gaussianRaw[sv];
        for (std::int32_t k = w.ringStart[sv]; k < w.ringStart[sv + 1]; ++k) {
            const std::size_t u = std::size_t(w.ring[std::size_t(k)]);
            if (w.ringMark[u] == v)
                continue;
            w.ringMark[u] = v;
            weight += out.pointArea[u];
            sum += double(out.pointArea[u]) * out.gaussianRaw[u];
        }
        out.gaussian[sv] = weight > 0.0 ? float(sum / weight) : 0.f;
    }
}

void computeCurvatures(const Positions& vertices, const Faces& faces, Curvatures& out)
{
    computeCurvatures(vertices, faces, Positions(), out);
}

} // namespace celform::algo
