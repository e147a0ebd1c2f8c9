// The viewing sphere (paper 1, sections 3.2 and 3.3): hull of the key directions, fast facet
// lookup for a view direction, and blend weights including the unspecified regions.
//
// Semantics (the contract tests and the rest of Celform rely on):
// - Points: the normalised key directions (index = key index), then, in Dummy mode only, dummies
//   at +X, -X, +Y, -Y, +Z, -Z, each left out when it is within 45 degrees (inclusive) of some key
//   (DESIGN.md). Dummies are base copies: their weight is the base model's share.
// - Refused sets: a key that is not finite or has zero length, and two keys closer than
//   kDuplicateAngleDegrees; build() then returns nothing and the error names the key indices.
// - Hull: >= 4 non-coplanar points go to CGAL::convex_hull_3 (exact predicates). Exactly coplanar
//   sets (and 3 points) are handled here: on a plane off the origin the points lie on a small
//   circle and are fan-triangulated; on a plane through the origin (a great circle), and for one
//   or two points, there is no facet.
// - Valid facets (those returned by facets()): hull triangles whose plane has the origin strictly
//   on its inner side, n . p0 > kPlaneEpsilon with n the unit outward normal. With the origin
//   inside the hull every facet is valid and every direction is covered; otherwise only the cap
//   facing away from the origin is valid, and its facets project to a spherical triangulation of
//   the covered region R = the cone spanned by the points (paper 1, section 3.2.1: a spherical
//   triangle is the projection of the planar hull triangle).
// - Covered view d: the valid facet whose cone contains d, barycentric coordinates w of the ray
//   hit in the planar triangle (tiny negatives clamped, renormalised; a value within 1e-12 of 1
//   snaps to exactly 1 and the others to 0, so a key's own direction gives that key bit-exactly),
//   sharpened w' = w^alpha / sum w^alpha (paper 1, section 3.2.2), dummies dropped.
// - Uncovered view d (paper 1, section 3.3; only possible when the origin is not strictly inside
//   the hull): b = the point of R nearest to d on the sphere, searched over R's boundary: the arcs
//   of the valid facets' edges used by one valid facet only, or, without valid facets, the
//   "skeleton" of the points: the point itself for one point, the minor arc for two (two
//   antipodal points are two isolated points), and for points on one great circle the arcs
//   between neighbours around the circle except a gap of 180 degrees or more (so the arcs cover
//   exactly the cone of the points). The weights at b are the chord-linear weights of the arc's
//   endpoints (equal to the facet barycentrics on that edge), sharpened as above, then scaled by
//   c = max(0, d . b) in Cosine and Dummy mode, c^2 in Cosine2 mode. ViewBlend.facet is -1 and
//   falloff is c (or c^2). Because R is a convex cone, b moves continuously wherever c > 0, so
//   the weights are continuous everywhere, equal the hull blend on R's boundary, and reduce to
//   the paper's single-key formula c = max(0, V_key . V_eye) (section 3.3, figure 7).
// - Sharpness that is not finite or not positive is treated as 1. A zero or non-finite view
//   direction gives no weights (the base model) with falloff 0.
#include "celform/algorithms/view_sphere.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

namespace celform::algo {

namespace {

using Vec3 = Eigen::Vector3d;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr double kPi = 3.14159265358979323846;
/// A facet takes part in lookups when its plane is at least this far from the origin (unit
/// normal, unit points): planes nearer the origin make the barycentric solve ill-conditioned.
constexpr double kPlaneEpsilon = 1e-10;
/// Relative tolerance of the "ray hits the triangle" test (barycentric numerator >= -tol * scale).
constexpr double kInsideTolerance = 1e-12;
/// A weight this close to 1 becomes exactly 1 (exact shape at a key's direction).
constexpr double kSnapTolerance = 1e-12;
/// Angle from a cube face's axis to its corners, acos(1/sqrt(3)).
constexpr double kFaceCornerAngle = 0.95531661812450927816;
/// Safety margins of the conservative cell/facet overlap tests (radians, cube-face units).
constexpr double kCapMargin = 1e-6;
constexpr double kUvMargin = 1e-9;

struct Arc {
    int a = -1;
    int b = -1;
    Vec3 pa = Vec3::Zero();
    Vec3 pb = Vec3::Zero();
    Vec3 normal = Vec3::Zero(); ///< unit pa x pb
};

/// Up to three hull points with their barycentric or chord-linear weights.
struct PointWeights {
    std::array<int, 3> point{-1, -1, -1};
    std::array<double, 3> weight{0.0, 0.0, 0.0};
    int count = 0;
    void add(int p, double w)
    {
        point[count] = p;
        weight[count] = w;
        ++count;
    }
};

double angleBetween(const Vec3& a, const Vec3& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// Cube-map cell of a unit direction: face = 2 * major axis + (negative), then an n by n grid on
/// the face in gnomonic coordinates (u, v) in [-1, 1].
inline int cellIndex1d(double u, int n)
{
    return std::clamp(static_cast<int>(std::floor((u + 1.0) * 0.5 * n)), 0, n - 1);
}

inline int cellOf(const Vec3& d, int n)
{
    const double ax = std::abs(d.x());
    const double ay = std::abs(d.y());
    const double az = std::abs(d.z());
    int axis = 0;
    if (ay > ax && ay >= az)
        axis = 1;
    else if (az > ax && az > ay)
        axis = 2;
    const double inv = 1.0 / std::abs(d[axis]);
    const int i = cellIndex1d(d[(axis + 1) % 3] * inv, n);
    const int j = cellIndex1d(d[(axis + 2) % 3] * inv, n);
    const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    return (face * n + j) * n + i;
}

/// Keeps w' = w^alpha / sum w^alpha (paper 1, section 3.2.2), after snapping a weight within
/// kSnapTolerance of 1 to exactly 1. Computed relative to the largest weight so that a large
/// alpha cannot underflow every term.
void sharpen(PointWeights& pw, double alpha)
{
    for (int i = 0; i < pw.count; ++i) {
        if (pw.weight[i] >= 1.0 - kSnapTolerance) {
            for (int k = 0; k < pw.count; ++k)
                pw.weight[k] = (k == i) ? 1.0 : 0.0;
            return;
        }
    }
    if (alpha == 1.0)
        return;
    double wMax = 0.0;
    for (int i = 0; i < pw.count; ++i)
        wMax = std::max(wMax, pw.weight[i]);
    if (wMax <= 0.0)
        return;
    double sum = 0.0;
    for (int i = 0; i < pw.count; ++i) {
        pw.weight[i] = std::pow(pw.weight[i] / wMax, alpha);
        sum += pw.weight[i];
    }
    for (int i = 0; i < pw.count; ++i)
        pw.weight[i] /= sum;
}

} // namespace

struct ViewSphere::Impl {
    std::vector<Vec3> points;
    int keyCount = 0;
    UnspecifiedRegions mode = UnspecifiedRegions::Dummy;

    /// Valid facets, counter-clockwise seen from outside (outward normal away from the origin).
    std::vector<std::array<int, 3>> facets;
    /// Per facet, the inverse of [p0 p1 p2]: lambda = inverse * d is proportional to the
    /// barycentric coordinates of the ray hit and all >= 0 iff the ray hits the triangle.
    std::vector<Eigen::Matrix3d> inverses;
    /// True when the origin is strictly inside the hull: every direction hits a valid facet.
    bool fullyCovered = false;

    /// Boundary of the covered region (or the skeleton when there are no facets).
    std::vector<Arc> arcs;
    std::vector<int> isolated;

    /// Cube-map grid over the valid facets: cells [cellStart[c], cellStart[c+1]) of cellFacets.
    int gridN = 0;
    std::vector<int> cellStart;
    std::vector<int> cellFacets;

    void addFacet(int a, int b, int c);
    void addArc(int a, int b);
    void buildBoundary();
    void buildGreatCircleSkeleton(const Vec3& planeNormal);
    void buildGrid();
    int locate(const Vec3& d, Vec3& lambda) const;
    double nearestOnBoundary(const Vec3& d, PointWeights& pw) const;
};

void ViewSphere::Impl::addFacet(int a, int b, int c)
{
    Eigen::Matrix3d m;
    m.col(0) = points[a];
    m.col(1) = points[b];
    m.col(2) = points[c];
    facets.push_back({a, b, c});
    inverses.push_back(m.inverse());
}

void ViewSphere::Impl::addArc(int a, int b)
{
    Arc arc;
    arc.a = a;
    arc.b = b;
    arc.pa = points[a];
    arc.pb = points[b];
    const Vec3 n = arc.pa.cross(arc.pb);
    const double len = n.norm();
    if (len < 1e-12)
        return; // antipodal or equal: no unique arc (callers keep such points as isolated)
    arc.normal = n / len;
    arcs.push_back(arc);
}

/// Boundary of the covered region: edges used by exactly one valid facet. Points on no valid
/// facet and no arc are kept as isolated points (only possible with near-degenerate facets).
void ViewSphere::Impl::buildBoundary()
{
    std::map<std::pair<int, int>, int> edgeUse;
    for (const auto& f : facets) {
        for (int k = 0; k < 3; ++k) {
            const int a = f[k];
            const int b = f[(k + 1) % 3];
            ++edgeUse[{std::min(a, b), std::max(a, b)}];
        }
    }
    for (const auto& [edge, uses] : edgeUse) {
        if (uses == 1)
            addArc(edge.first, edge.second);
    }
    std::vector<char> used(points.size(), 0);
    for (const auto& f : facets)
        for (int v : f)
            used[v] = 1;
    for (const Arc& arc : arcs)
        used[arc.a] = used[arc.b] = 1;
    for (int i = 0; i < static_cast<int>(points.size()); ++i)
        if (!used[i])
            isolated.push_back(i);
}

/// Skeleton of points on one great circle (plane normal given): arcs between neighbours around
/// the circle, leaving out any gap of 180 degrees or more, so that the arcs cover exactly the
/// cone of the points (the whole circle when the points surround the origin).
void ViewSphere::Impl::buildGreatCircleSkeleton(const Vec3& planeNormal)
{
    const int n = static_cast<int>(points.size());
    Vec3 u = points[0] - points[0].dot(planeNormal) * planeNormal;
    u.normalize();
    const Vec3 v = planeNormal.cross(u);
    std::vector<std::pair<double, int>> order;
    for (int i = 0; i < n; ++i)
        order.emplace_back(std::atan2(points[i].dot(v), points[i].dot(u)), i);
    std::sort(order.begin(), order.end());
    std::vector<char> used(n, 0);
    for (int k = 0; k < n && n >= 2; ++k) {
        const auto& [t0, a] = order[k];
        const auto& [t1raw, b] = order[(k + 1) % n];
        const double t1 = (k + 1 == n) ? t1raw + 2.0 * kPi : t1raw;
        if (t1 - t0 < kPi - 1e-9) {
            const std::size_t before = arcs.size();
            addArc(a, b);
            if (arcs.size() > before)
                used[a] = used[b] = 1;
        }
    }
    for (int i = 0; i < n; ++i)
        if (!used[i])
            isolated.push_back(i);
}

void ViewSphere::Impl::buildGrid()
{
    const int facetCount = static_cast<int>(facets.size());
    gridN = 0;
    cellStart.clear();
    cellFacets.clear();
    if (facetCount == 0)
        return;
    // About two cells per facet: few candidates per cell, a small table.
    const int n = std::clamp(static_cast<int>(std::ceil(std::sqrt(facetCount / 3.0))), 1, 128);
    const int cellsPerFace = n * n;
    std::vector<std::pair<int, int>> pairs; // (cell, facet)
    pairs.reserve(static_cast<std::size_t>(facetCount) * 8);

    auto cellCap = [n](int axis, double s, int i, int j, Vec3& centre) {
        const int b = (axis + 1) % 3;
        const int c = (axis + 2) % 3;
        auto dir = [&](double u, double v) {
            Vec3 p;
            p[axis] = s;
            p[b] = u;
            p[c] = v;
            return p.normalized();
        };
        const double u0 = -1.0 + 2.0 * i / n;
        const double u1 = -1.0 + 2.0 * (i + 1) / n;
        const double v0 = -1.0 + 2.0 * j / n;
        const double v1 = -1.0 + 2.0 * (j + 1) / n;
        centre = dir(0.5 * (u0 + u1), 0.5 * (v0 + v1));
        double r = 0.0;
        for (const Vec3& corner : {dir(u0, v0), dir(u1, v0), dir(u0, v1), dir(u1, v1)})
            r = std::max(r, angleBetween(centre, corner));
        return r;
    };

    for (int f = 0; f < facetCount; ++f) {
        const Vec3& p0 = points[facets[f][0]];
        const Vec3& p1 = points[facets[f][1]];
        const Vec3& p2 = points[facets[f][2]];
        // Bounding cap of the spherical triangle (convex, so inside the cap of its corners
        // whenever that cap is smaller than a hemisphere).
        const Vec3 capCenter = (p0 + p1 + p2).normalized();
        const double capRadius
            = std::max({angleBetween(capCenter, p0), angleBetween(capCenter, p1), angleBetween(capCenter, p2)});
        const bool hugeCap = capRadius >= 0.5 * kPi - kCapMargin;
        for (int face = 0; face < 6; ++face) {
            const int axis = face / 2;
            const double s = (face % 2) ? -1.0 : 1.0;
            const int b = (axis + 1) % 3;
            const int c = (axis + 2) % 3;
            if (!hugeCap) {
                const double axisAngle = std::acos(std::clamp(s * capCenter[axis], -1.0, 1.0));
                if (axisAngle - capRadius > kFaceCornerAngle + kCapMargin)
                    continue; // the cap misses the face's pyramid
            }
            const double minHeight = std::min({s * p0[axis], s * p1[axis], s * p2[axis]});
            if (minHeight > 1e-3) {
                // In the face's open hemisphere the gnomonic projection maps the spherical
                // triangle onto the planar triangle of its projected corners: its (u, v) box is
                // exact.
                double uMin = std::numeric_limits<double>::infinity();
                double uMax = -uMin;
                double vMin = uMin;
                double vMax = -uMin;
                for (const Vec3* p : {&p0, &p1, &p2}) {
                    const double h = s * (*p)[axis];
                    const double u = (*p)[b] / h;
                    const double v = (*p)[c] / h;
                    uMin = std::min(uMin, u);
                    uMax = std::max(uMax, u);
                    vMin = std::min(vMin, v);
                    vMax = std::max(vMax, v);
                }
                if (uMax < -1.0 - kUvMargin || uMin > 1.0 + kUvMargin || vMax < -1.0 - kUvMargin
                    || vMin > 1.0 + kUvMargin)
                    continue;
                const int i0 = cellIndex1d(uMin - kUvMargin, n);
                const int i1 = cellIndex1d(uMax + kUvMargin, n);
                const int j0 = cellIndex1d(vMin - kUvMargin, n);
                const int j1 = cellIndex1d(vMax + kUvMargin, n);
                for (int j = j0; j <= j1; ++j)
                    for (int i = i0; i <= i1; ++i)
                        pairs.emplace_back((face * n + j) * n + i, f);
            } else {
                // Rare (a facet reaching the face's horizon): test each cell's bounding cap.
                for (int j = 0; j < n; ++j) {
                    for (int i = 0; i < n; ++i) {
                        Vec3 cellCenter;
                        const double cellRadius = cellCap(axis, s, i, j, cellCenter);
                        if (hugeCap || angleBetween(cellCenter, capCenter) <= capRadius + cellRadius + kCapMargin)
                            pairs.emplace_back((face * n + j) * n + i, f);
                    }
                }
            }
        }
    }

    const int cellCount = 6 * cellsPerFace;
    cellStart.assign(cellCount + 1, 0);
    for (const auto& pr : pairs)
        ++cellStart[pr.first + 1];
    for (int c = 0; c < cellCount; ++c)
        cellStart[c + 1] += cellStart[c];
    cellFacets.resize(pairs.size());
    std::vector<int> fill(cellStart.begin(), cellStart.end() - 1);
    for (const auto& pr : pairs)
        cellFacets[fill[pr.first]++] = pr.second;
    gridN = n;
}

/// Valid facet whose cone contains the unit direction d, or -1; lambda gets the (unnormalised)
/// barycentric numerators.
int ViewSphere::Impl::locate(const Vec3& d, Vec3& lambda) const
{
    if (gridN == 0)
        return -1;
    const int cell = cellOf(d, gridN);
    int best = -1;
    double bestScore = -std::numeric_limits<double>::infinity();
    auto test = [&](int f) {
        const Vec3 l = inverses[f] * d;
        const double scale = l.cwiseAbs().sum();
        const double score = l.minCoeff() / scale;
        if (score > bestScore) {
            bestScore = score;
            best = f;
            lambda = l;
        }
        return score >= -kInsideTolerance;
    };
    for (int k = cellStart[cell]; k < cellStart[cell + 1]; ++k)
        if (test(cellFacets[k]))
            return cellFacets[k];
    // The candidate lists are conservative, so a miss means "not covered", except for rounding at
    // a shared edge; where everything is covered, the best candidate is then the answer. An
    // empty list there cannot happen short of a bug; scan rather than fail.
    if (!fullyCovered)
        return -1;
    if (best < 0)
        for (int f = 0; f < static_cast<int>(facets.size()); ++f)
            test(f);
    return best;
}

/// Nearest point b of the covered region's boundary (or skeleton) to the unit direction d.
/// Returns cos(angle(d, b)) (-infinity when there is nothing) and the chord-linear weights of the
/// arc endpoints at b.
double ViewSphere::Impl::nearestOnBoundary(const Vec3& d, PointWeights& pw) const
{
    double bestCos = -std::numeric_limits<double>::infinity();
    auto takePoint = [&](int p, double cosine) {
        if (cosine > bestCos) {
            bestCos = cosine;
            pw = PointWeights{};
            pw.add(p, 1.0);
        }
    };
    for (const Arc& arc : arcs) {
        // Closest point of a great-circle arc: d projected to the arc's plane if that falls
        // inside the arc, else the nearer endpoint.
        const Vec3 q = d - d.dot(arc.normal) * arc.normal;
        const double qLen = q.norm();
        if (qLen > 1e-15) {
            const double alpha = q.cross(arc.pb).dot(arc.normal); // share of pa (chord-linear)
            const double beta = arc.pa.cross(q).dot(arc.normal); // share of pb
            if (alpha >= 0.0 && beta >= 0.0 && alpha + beta > 0.0 && qLen > bestCos) {
                bestCos = qLen; // d . (q / |q|) = |q|
                pw = PointWeights{};
                pw.add(arc.a, alpha / (alpha + beta));
                pw.add(arc.b, beta / (alpha + beta));
            }
        }
        takePoint(arc.a, d.dot(arc.pa));
        takePoint(arc.b, d.dot(arc.pb));
    }
    for (int p : isolated)
        takePoint(p, d.dot(points[p]));
    return bestCos;
}

ViewSphere::ViewSphere()
    : m(std::make_unique<Impl>())
{ }
ViewSphere::~ViewSphere() = default;
ViewSphere::ViewSphere(ViewSphere&&) noexcept = default;
ViewSphere& ViewSphere::operator=(ViewSphere&&) noexcept = default;
ViewSphere::ViewSphere(const ViewSphere& other)
    : m(std::make_unique<Impl>(*other.m))
{ }
ViewSphere& ViewSphere::operator=(const ViewSphere& other)
{
    if (this != &other)
        m = std::make_unique<Impl>(*other.m);
    return *this;
}

const std::vector<Eigen::Vector3d>& ViewSphere::points() const
{
    return m->points;
}
int ViewSphere::keyCount() const
{
    return m->keyCount;
}
const std::vector<std::array<int, 3>>& ViewSphere::facets() const
{
    return m->facets;
}

std::optional<ViewSphere> ViewSphere::build(
    const std::vector<Eigen::Vector3d>& keyDirections, UnspecifiedRegions mode, std::string* error)
{
    auto fail = [error](const std::string& message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    ViewSphere sphere;
    Impl& s = *sphere.m;
    s.mode = mode;
    s.keyCount = static_cast<int>(keyDirections.size());
    for (int i = 0; i < s.keyCount; ++i) {
        const Vec3& k = keyDirections[i];
        if (!k.allFinite())
            return fail("Key direction " + std::to_string(i) + " is not finite.");
        const double len = k.norm();
        if (!(len > 0.0))
            return fail("Key direction " + std::to_string(i) + " has zero length.");
        s.points.push_back(k / len);
    }
    const double duplicateCos = std::cos(kDuplicateAngleDegrees * kPi / 180.0);
    for (int i = 0; i < s.keyCount; ++i) {
        for (int j = i + 1; j < s.keyCount; ++j) {
            if (s.points[i].dot(s.points[j]) > duplicateCos) {
                std::ostringstream msg;
                msg << "Keys " << i << " and " << j << " have the same view direction ("
                    << angleBetween(s.points[i], s.points[j]) * 180.0 / kPi << " degrees apart, less than "
                    << kDuplicateAngleDegrees << ").";
                return fail(msg.str());
            }
        }
    }
    if (mode == UnspecifiedRegions::Dummy) {
        // DESIGN.md: dummies at the six axis directions, minus those within 45 degrees of a key.
        const double leaveOutCos = std::cos(45.0 * kPi / 180.0) - 1e-12;
        for (int axis = 0; axis < 3; ++axis) {
            for (double sign : {1.0, -1.0}) {
                Vec3 dummy = Vec3::Zero();
                dummy[axis] = sign;
                bool nearKey = false;
                for (int i = 0; i < s.keyCount && !nearKey; ++i)
                    nearKey = s.points[i].dot(dummy) >= leaveOutCos;
                if (!nearKey)
                    s.points.push_back(dummy);
            }
        }
    }

    const int n = static_cast<int>(s.points.size());
    if (n == 0)
        return sphere;
    if (n == 1) {
        s.isolated.push_back(0);
        return sphere;
    }
    if (n == 2) {
        const Vec3 normal = s.points[0].cross(s.points[1]);
        if (normal.norm() < 1e-12) { // antipodal: no unique arc, two isolated points
            s.isolated = {0, 1};
            return sphere;
        }
        s.buildGreatCircleSkeleton(normal.normalized());
        return sphere;
    }

    std::vector<Kernel::Point_3> cgalPoints;
    cgalPoints.reserve(n);
    for (const Vec3& p : s.points)
        cgalPoints.emplace_back(p.x(), p.y(), p.z());

    // Distinct points on a sphere are never collinear, but rounding could make three so.
    int i1 = 1;
    int i2 = -1;
    for (int k = 2; k < n && i2 < 0; ++k)
        if (!CGAL::collinear(cgalPoints[0], cgalPoints[i1], cgalPoints[k]))
            i2 = k;
    bool coplanar = true;
    if (i2 >= 0) {
        for (int k = 1; k < n && coplanar; ++k)
            coplanar = CGAL::coplanar(cgalPoints[0], cgalPoints[i1], cgalPoints[i2], cgalPoints[k]);
    }

    if (i2 < 0 || coplanar) {
        Vec3 normal = (i2 >= 0) ? Vec3((s.points[i1] - s.points[0]).cross(s.points[i2] - s.points[0]))
                                : Vec3(s.points[0].cross(s.points[1]));
        if (normal.norm() == 0.0)
            normal = s.points[0].unitOrthogonal();
        normal.normalize();
        if (normal.dot(s.points[0]) < 0.0)
            normal = -normal;
        if (normal.dot(s.points[0]) <= kPlaneEpsilon || i2 < 0) {
            s.buildGreatCircleSkeleton(normal);
            return sphere;
        }
        // A small circle: the points are in convex position; fan-triangulate counter-clockwise
        // about the normal pointing away from the origin.
        const Vec3 centre = normal.dot(s.points[0]) * normal;
        const Vec3 u = (s.points[0] - centre).normalized();
        const Vec3 v = normal.cross(u);
        std::vector<std::pair<double, int>> order;
        for (int k = 0; k < n; ++k)
            order.emplace_back(std::atan2((s.points[k] - centre).dot(v), (s.points[k] - centre).dot(u)), k);
        std::sort(order.begin(), order.end());
        for (int k = 1; k + 1 < n; ++k)
            s.addFacet(order[0].second, order[k].second, order[k + 1].second);
        s.buildBoundary();
        s.buildGrid();
        return sphere;
    }

    std::vector<Kernel::Point_3> hullPoints;
    std::vector<std::array<std::size_t, 3>> hullTriangles;
    CGAL::convex_hull_3(cgalPoints.begin(), cgalPoints.end(), hullPoints, hullTriangles);
    // The hull's vertices are copies of input points: map them back by their exact coordinates.
    std::map<std::array<double, 3>, int> indexOf;
    for (int k = 0; k < n; ++k)
        indexOf[{s.points[k].x(), s.points[k].y(), s.points[k].z()}] = k;
    std::vector<int> hullIndex(hullPoints.size(), -1);
    Vec3 interior = Vec3::Zero();
    for (std::size_t k = 0; k < hullPoints.size(); ++k) {
        const auto it = indexOf.find({hullPoints[k].x(), hullPoints[k].y(), hullPoints[k].z()});
        assert(it != indexOf.end());
        hullIndex[k] = it->second;
        interior += s.points[it->second];
    }
    interior /= static_cast<double>(hullPoints.size());

    int hullFacetCount = 0;
    std::vector<std::array<int, 3>> allTriangles;
    for (const auto& t : hullTriangles) {
        std::array<int, 3> f{hullIndex[t[0]], hullIndex[t[1]], hullIndex[t[2]]};
        const Vec3& p0 = s.points[f[0]];
        Vec3 normal = (s.points[f[1]] - p0).cross(s.points[f[2]] - p0);
        const double len = normal.norm();
        if (len == 0.0)
            continue;
        normal /= len;
        if (normal.dot(p0 - interior) < 0.0) { // CGAL orients outward; make sure of it
            std::swap(f[1], f[2]);
            normal = -normal;
        }
        ++hullFacetCount;
        allTriangles.push_back(f);
        if (normal.dot(p0) > kPlaneEpsilon)
            s.addFacet(f[0], f[1], f[2]);
    }
    s.fullyCovered = hullFacetCount > 0 && static_cast<int>(s.facets.size()) == hullFacetCount;
    if (s.facets.empty()) {
        // Every hull plane passes (within kPlaneEpsilon) through the origin: the points are on a
        // great circle up to rounding. Use the skeleton of that circle (largest triangle's plane).
        Vec3 best = Vec3::UnitZ();
        double bestArea = -1.0;
        for (const auto& f : allTriangles) {
            const Vec3 nrm = (s.points[f[1]] - s.points[f[0]]).cross(s.points[f[2]] - s.points[f[0]]);
            if (nrm.norm() > bestArea) {
                bestArea = nrm.norm();
                best = nrm.normalized();
            }
        }
        s.buildGreatCircleSkeleton(best);
        return sphere;
    }
    if (!s.fullyCovered)
        s.buildBoundary();
    s.buildGrid();
    return sphere;
}

ViewBlend ViewSphere::blend(const Eigen::Vector3d& viewDirection, double sharpness) const
{
    ViewBlend result;
    blend(viewDirection, sharpness, result);
    return result;
}

void ViewSphere::blend(const Eigen::Vector3d& viewDirection, double sharpness, ViewBlend& result) const
{
    result.weights.clear();
    result.facet = -1;
    result.barycentric = Eigen::Vector3d::Zero();
    result.falloff = 1.0;
    const Impl& s = *m;
    const double len = viewDirection.norm();
    if (!std::isfinite(len) || !(len > 0.0) || s.points.empty()) {
        result.falloff = 0.0;
        return;
    }
    const Vec3 d = viewDirection / len;
    const double alpha = (std::isfinite(sharpness) && sharpness > 0.0) ? sharpness : 1.0;

    PointWeights pw;
    double falloff = 1.0;
    Vec3 lambda;
    const int facet = s.locate(d, lambda);
    if (facet >= 0) {
        // Paper 1, section 3.2.2: the blending coefficients are the barycentric coordinates of
        // the ray's hit in the planar hull triangle (lambda / sum lambda).
        lambda = lambda.cwiseMax(0.0);
        const double sum = lambda.sum();
        for (int k = 0; k < 3; ++k)
            pw.add(s.facets[facet][k], sum > 0.0 ? lambda[k] / sum : 1.0 / 3.0);
        for (int k = 0; k < 3; ++k) {
            if (pw.weight[k] >= 1.0 - kSnapTolerance) {
                for (int j = 0; j < 3; ++j)
                    pw.weight[j] = (j == k) ? 1.0 : 0.0;
                break;
            }
        }
        result.facet = facet;
        result.barycentric = Vec3(pw.weight[0], pw.weight[1], pw.weight[2]);
    } else {
        // Paper 1, section 3.3: outside the keys' coverage, fall off towards the base model from
        // the nearest covered direction b, c = max(0, d . b) (squared in Cosine2 mode).
        double c = s.nearestOnBoundary(d, pw);
        c = std::clamp(c, 0.0, 1.0);
        if (c >= 1.0 - kSnapTolerance)
            c = 1.0;
        falloff = (s.mode == UnspecifiedRegions::Cosine2) ? c * c : c;
        result.falloff = falloff;
        if (falloff == 0.0)
            return;
    }
    sharpen(pw, alpha);
    for (int k = 0; k < pw.count; ++k) {
        const double w = pw.weight[k] * falloff;
        if (pw.point[k] < s.keyCount && w > 0.0) // dummies are base copies: their share is the base's
            result.weights.push_back({pw.point[k], w});
    }
    std::sort(result.weights.begin(), result.weights.end(),
        [](const KeyWeight& a, const KeyWeight& b) { return a.key < b.key; });
    return;
}

} // namespace celform::algo
