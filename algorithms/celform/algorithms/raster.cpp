// The CPU G-buffer rasteriser (DESIGN.md, "Rendering"): exact fixed-point edge functions with the
// top-left fill rule, near-plane and guard-band clipping in camera space, perspective-correct
// barycentrics, and capsule-shaped anti-aliased strokes tested against the G-buffer depth.
#include "celform/algorithms/raster.h"
#include "celform/algorithms/fresh_memory.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>

namespace celform::algo {

namespace {

/// Screen positions are snapped to 1/256 pixel, as GPU rasterisers do: edge functions are then
/// exact 64-bit integers, so a pixel centre on a shared edge is decided identically for both
/// triangles and the fill rule can give it to exactly one of them.
constexpr int kSubBits = 8;
constexpr std::int64_t kSubUnit = std::int64_t(1) << kSubBits;
constexpr std::int64_t kSubHalf = kSubUnit / 2;
/// Guard band in pixels: screen coordinates beyond +/- kGuard are clipped away in camera space
/// first. 2^15 px in 1/256 units is 2^23; edge-function products stay below 2^50 (int64-exact).
constexpr double kGuard = 32768.0;
constexpr double kPi = 3.14159265358979323846;

std::int64_t toFixed(double pixel)
{
    return std::int64_t(std::floor(pixel * double(kSubUnit) + 0.5));
}

std::int64_t floorDiv(std::int64_t a, std::int64_t b)
{
    const std::int64_t q = a / b;
    return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

enum Outcode : std::uint8_t {
    kBehind = 1, ///< depth <= near: must be clipped
    kOutsideGuard = 2, ///< projects beyond the guard band: must be clipped
    kLeft = 4, ///< the four image-side bits reject triangles wholly outside the image
    kRight = 8,
    kAbove = 16,
    kBelow = 32,
    kInvalid = 64, ///< non-finite coordinates: faces using it are skipped
};

/// A vertex ready for scan conversion (one per mesh vertex, packed so a face reads one cache line
/// per corner): snapped pixel position (coverage), exact pixel position (interpolation: snapping
/// would cost 1e-4 in barycentrics and much more in depth near the horizon), and depth.
struct RasterVertex {
    double px = 0.0;
    double py = 0.0;
    double depth = 1.0;
    std::int32_t x = 0; ///< 1/256 pixel; |x| <= 2^23 inside the guard band
    std::int32_t y = 0;
    std::uint8_t code = 0; ///< Outcode bits
};

struct Target {
    int width = 0;
    int height = 0;
    bool perspective = true;
    float* depth = nullptr;
    std::int32_t* faceId = nullptr;
    Eigen::Vector3f* bary = nullptr;
};

/// Scan-converts one triangle: samples at pixel centres, top-left rule, strict depth test. Faces
/// arrive in increasing id order, so "strictly nearer wins" gives depth ties to the lower id.
/// corners: columns are the barycentrics of a, b, c in the original face (clipped pieces), or
/// null for the face itself.
void rasterTriangle(const RasterVertex& a, const RasterVertex& first, const RasterVertex& second,
    const Eigen::Matrix3d* corners, std::int32_t face, const Target& t)
{
    std::int64_t area = (std::int64_t(first.x) - a.x) * (std::int64_t(second.y) - a.y)
        - (std::int64_t(first.y) - a.y) * (std::int64_t(second.x) - a.x);
    if (area == 0)
        return;
    const bool swapped = area < 0; // back-facing on screen (or mirrored): same coverage, other winding
    const RasterVertex& b = swapped ? second : first;
    const RasterVertex& c = swapped ? first : second;
    area = swapped ? -area : area;
    const std::int64_t minX = std::min({a.x, b.x, c.x});
    const std::int64_t maxX = std::max({a.x, b.x, c.x});
    const std::int64_t minY = std::min({a.y, b.y, c.y});
    const std::int64_t maxY = std::max({a.y, b.y, c.y});
    // Pixel i has its centre at i * 256 + 128 in fixed point.
    const std::int64_t i0 = std::max<std::int64_t>(0, floorDiv(minX - kSubHalf + kSubUnit - 1, kSubUnit));
    const std::int64_t i1 = std::min<std::int64_t>(t.width - 1, floorDiv(maxX - kSubHalf, kSubUnit));
    const std::int64_t j0 = std::max<std::int64_t>(0, floorDiv(minY - kSubHalf + kSubUnit - 1, kSubUnit));
    const std::int64_t j1 = std::min<std::int64_t>(t.height - 1, floorDiv(maxY - kSubHalf, kSubUnit));
    if (i0 > i1 || j0 > j1)
        return;

    // Edge function of edge p -> q at s: (q.x - p.x) (s.y - p.y) - (q.y - p.y) (s.x - p.x), positive
    // inside. With y down, an edge whose interior lies to +x (dy < 0) is a left edge, a
    // horizontal edge with the interior below (dy == 0, dx > 0) is a top edge; samples exactly on
    // other edges are left to the neighbour (bias -1 turns ">= 0" into "> 0").
    struct Edge {
        std::int64_t stepX, stepY, rowStart, minimum;
    };
    const RasterVertex* v[3] = {&a, &b, &c};
    Edge e[3];
    const std::int64_t sx0 = i0 * kSubUnit + kSubHalf;
    const std::int64_t sy0 = j0 * kSubUnit + kSubHalf;
    for (int k = 0; k < 3; ++k) {
        // Edge k is opposite vertex k, so its function is vertex k's (unnormalised) barycentric.
        const RasterVertex& p = *v[(k + 1) % 3];
        const RasterVertex& q = *v[(k + 2) % 3];
        const std::int64_t dx = std::int64_t(q.x) - p.x;
        const std::int64_t dy = std::int64_t(q.y) - p.y;
        const bool topLeft = dy < 0 || (dy == 0 && dx > 0);
        e[k].stepX = -dy * kSubUnit;
        e[k].stepY = dx * kSubUnit;
        e[k].rowStart = dx * (sy0 - p.y) - dy * (sx0 - p.x);
        e[k].minimum = topLeft ? 0 : 1;
    }
    // Exact screen-space edge functions for interpolation, relative to vertex a for precision.
    const double abx = b.px - a.px, aby = b.py - a.py, acx = c.px - a.px, acy = c.py - a.py;
    const double exactArea = abx * acy - aby * acx;
    const bool exact = exactArea != 0.0 && std::isfinite(exactArea);
    const double invExactArea = exact ? 1.0 / exactArea : 0.0;
    const double invArea = 1.0 / double(area);
    for (std::int64_t j = j0; j <= j1; ++j) {
        std::int64_t w0 = e[0].rowStart, w1 = e[1].rowStart, w2 = e[2].rowStart;
        for (std::int64_t i = i0; i <= i1; ++i) {
            if (((w0 - e[0].minimum) | (w1 - e[1].minimum) | (w2 - e[2].minimum)) >= 0) {
                const std::size_t idx = std::size_t(j) * std::size_t(t.width) + std::size_t(i);
                // Screen-space barycentrics at the pixel centre, clamped to the triangle: a sample
                // inside only because of snapping takes the nearest edge value, never extrapolates.
                double l1, l2;
                if (exact) {
                    const double sx = double(i) + 0.5 - a.px, sy = double(j) + 0.5 - a.py;
                    l1 = (sx * acy - sy * acx) * invExactArea;
                    l2 = (abx * sy - aby * sx) * invExactArea;
                } else {
                    l1 = double(w1) * invArea;
                    l2 = double(w2) * invArea;
                }
                l1 = std::clamp(l1, 0.0, 1.0);
                l2 = std::clamp(l2, 0.0, 1.0 - l1);
                const double l0 = 1.0 - l1 - l2;
                double q0, q1, q2, depth;
                if (t.perspective) {
                    // Screen barycentrics divided by depth and
                    // renormalised are the perspective-correct ones; depth is their harmonic mean.
                    q0 = l0 / a.depth;
                    q1 = l1 / b.depth;
                    q2 = l2 / c.depth;
                    const double s = q0 + q1 + q2;
                    depth = 1.0 / s;
                    q0 *= depth;
                    q1 *= depth;
                    q2 *= depth;
                } else {
                    q0 = l0;
                    q1 = l1;
                    q2 = l2;
                    depth = q0 * a.depth + q1 * b.depth + q2 * c.depth;
                }
                const float d = float(depth);
                if (d < t.depth[idx]) {
                    t.depth[idx] = d;
                    t.faceId[idx] = face;
                    const Eigen::Vector3d own(q0, swapped ? q2 : q1, swapped ? q1 : q2);
                    t.bary[idx] = corners ? Eigen::Vector3f(((*corners) * own).cast<float>()) : own.cast<float>();
                }
            }
            w0 += e[0].stepX;
            w1 += e[1].stepX;
            w2 += e[2].stepX;
        }
        e[0].rowStart += e[0].stepY;
        e[1].rowStart += e[1].stepY;
        e[2].rowStart += e[2].stepY;
    }
}

/// A polygon corner during clipping: camera-space position and barycentrics in the original face;
/// source is the mesh vertex it still is (so its snapped position matches the unclipped
/// neighbours exactly), or -1 for a corner created by a clip plane.
struct ClipVertex {
    Eigen::Vector3d cam;
    Eigen::Vector3d bary;
    std::int32_t source = -1;
};

/// Sutherland-Hodgman against one plane given by a signed distance that is linear in camera
/// space (so barycentrics interpolate linearly too). Returns the new corner count.
template <typename Distance> int clipPolygon(const ClipVertex* in, int count, ClipVertex* out, Distance distance)
{
    int n = 0;
    for (int k = 0; k < count; ++k) {
        const ClipVertex& p = in[k];
        const ClipVertex& q = in[(k + 1) % count];
        const double dp = distance(p.cam);
        const double dq = distance(q.cam);
        if (dp >= 0)
            out[n++] = p;
        if ((dp >= 0) != (dq >= 0)) {
            const double s = dp / (dp - dq);
            ClipVertex r;
            r.cam = p.cam + s * (q.cam - p.cam);
            r.bary = p.bary + s * (q.bary - p.bary);
            out[n++] = r;
        }
    }
    return n;
}

} // namespace

Eigen::Vector3d RasterCamera::forward() const
{
    return (target - eye).normalized();
}

Eigen::Vector3d RasterCamera::right() const
{
    return forward().cross(up).normalized();
}

Eigen::Vector3d RasterCamera::trueUp() const
{
    return right().cross(forward());
}

ProjectionFrame::ProjectionFrame(const RasterCamera& c)
    : eye(c.eye)
    , forward(c.forward())
    , right(c.right())
    , up(c.trueUp())
    , cx(0.5 * c.width + c.horizontalShift * c.width)
    , cy(0.5 * c.height)
    , orthographic(c.orthographic)
{
    if (orthographic)
        scale = double(c.height) / c.orthoHeight;
    else
        scale = 0.5 * c.height / std::tan(0.5 * c.fovYDegrees * kPi / 180.0);
}

Eigen::Vector3d ProjectionFrame::unproject(double x, double y, double depth) const
{
    const double u = (x - cx) / scale, v = (cy - y) / scale;
    if (orthographic)
        return eye + u * right + v * up + depth * forward;
    return eye + depth * (forward + u * right + v * up);
}

Eigen::Vector3d RasterCamera::project(const Eigen::Vector3d& point) const
{
    return ProjectionFrame(*this).project(point);
}

void RasterCamera::ray(double x, double y, Eigen::Vector3d& origin, Eigen::Vector3d& direction) const
{
    const ProjectionFrame frame(*this);
    const double u = (x - frame.cx) / frame.scale;
    const double v = (frame.cy - y) / frame.scale;
    if (frame.orthographic) {
        origin = frame.eye + u * frame.right + v * frame.up;
        direction = frame.forward;
    } else {
        origin = frame.eye;
        direction = (frame.forward + u * frame.right + v * frame.up).normalized();
    }
}

void rasterise(const Positions& shape, const Faces& faces, const Positions& vertexNormals, const RasterCamera& camera,
    GBuffer& out, bool positions)
{
    assert(camera.width >= 0 && camera.height >= 0 && camera.width < kGuard && camera.height < kGuard);
    assert(vertexNormals.rows() == 0 || vertexNormals.rows() == shape.rows());
    const int width = std::max(0, camera.width);
    const int height = std::max(0, camera.height);
    const std::size_t pixelCount = std::size_t(width) * std::size_t(height);
    out.width = width;
    out.height = height;
    reserveBacked(out.depth, pixelCount);
    reserveBacked(out.faceId, pixelCount);
    if (positions)
        reserveBacked(out.position, pixelCount);
    reserveBacked(out.normal, pixelCount);
    reserveBacked(out.barycentric, pixelCount);
    out.depth.assign(pixelCount, std::numeric_limits<float>::infinity());
    out.faceId.assign(pixelCount, -1);
    // Position (when asked for), normal and barycentric are written for every pixel by the resolve
    // pass below.
    out.position.resize(positions ? pixelCount : 0);
    if (!positions)
        reserveBacked(out.facesAway, pixelCount);
    out.facesAway.resize(positions ? 0 : pixelCount);
    out.normal.resize(pixelCount);
    out.barycentric.resize(pixelCount);
    if (pixelCount == 0)
        return;

    const ProjectionFrame frame(camera);
    // Near plane: a tiny fraction of the scene size in front of the eye (for orthographic
    // cameras too, so depths stay positive for the relative depth bias of drawStrokes).
    const Eigen::AlignedBox3d box = boundingBox(shape);
    const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
    const double nearDepth = std::max(1e-5 * diagonal, 1e-12);

    // Per vertex, once: camera coordinates, snapped pixel position and outcode.
    const Eigen::Index vertexCount = shape.rows();
    const std::size_t vertexSlots = std::size_t(vertexCount);
    // Kept per thread: a sequence of frames allocates it once (issue 29); every slot is written
    // below before it is read. Camera coordinates are not kept: only faces to clip need them, and
    // they are computed again there (the same arithmetic), 24 bytes a vertex less to fault in.
    thread_local std::vector<RasterVertex> screen;
    reserveBacked(screen, vertexSlots);
    screen.resize(vertexSlots);
    const auto cameraCoordinates
        = [&](Eigen::Index v) { return frame.toCamera(shape.row(v).transpose().cast<double>()); };
    for (Eigen::Index v = 0; v < vertexCount; ++v) {
        const std::size_t s = std::size_t(v);
        const Eigen::Vector3d c = cameraCoordinates(v);
        RasterVertex& r = screen[s];
        r = RasterVertex{}; // the previous frame's values must not show through
        r.depth = c.z();
        std::uint8_t oc = 0;
        if (!c.allFinite()) {
            oc = kInvalid;
        } else if (!(c.z() > nearDepth)) {
            oc = kBehind;
        } else {
            const double x = frame.pixelX(c);
            const double y = frame.pixelY(c);
            if (!(std::abs(x) <= kGuard && std::abs(y) <= kGuard)) {
                oc |= kOutsideGuard;
            } else {
                r.px = x;
                r.py = y;
                r.x = std::int32_t(toFixed(x));
                r.y = std::int32_t(toFixed(y));
            }
            oc |= x < 0 ? kLeft : 0;
            oc |= x > width ? kRight : 0;
            oc |= y < 0 ? kAbove : 0;
            oc |= y > height ? kBelow : 0;
        }
        r.code = oc;
    }

    Target target;
    target.width = width;
    target.height = height;
    target.perspective = !frame.orthographic;
    target.depth = out.depth.data();
    target.faceId = out.faceId.data();
    target.bary = out.barycentric.data();

    const auto rasterVertex = [&](const ClipVertex& cv) {
        if (cv.source >= 0)
            return screen[std::size_t(cv.source)];
        RasterVertex r;
        r.px = frame.pixelX(cv.cam);
        r.py = frame.pixelY(cv.cam);
        r.x = std::int32_t(toFixed(r.px));
        r.y = std::int32_t(toFixed(r.py));
        r.depth = cv.cam.z();
        return r;
    };

    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const std::int32_t i[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
        assert(i[0] >= 0 && i[0] < vertexCount && i[1] >= 0 && i[1] < vertexCount && i[2] >= 0 && i[2] < vertexCount);
        const RasterVertex& r0 = screen[std::size_t(i[0])];
        const RasterVertex& r1 = screen[std::size_t(i[1])];
        const RasterVertex& r2 = screen[std::size_t(i[2])];
        const std::uint8_t c0 = r0.code, c1 = r1.code, c2 = r2.code;
        if ((c0 | c1 | c2) & kInvalid)
            continue;
        if (c0 & c1 & c2 & ~kOutsideGuard) // all behind the eye, or all beyond one side of the image
            continue;
        const std::int32_t face = std::int32_t(f);
        if (!((c0 | c1 | c2) & (kBehind | kOutsideGuard))) {
            rasterTriangle(r0, r1, r2, nullptr, face, target);
            continue;
        }
        // Crosses the near plane or leaves the guard band: clip in camera space against the
        // near plane and the four guard planes (linear in camera space for either projection).
        std::array<ClipVertex, 16> bufA, bufB;
        for (int k = 0; k < 3; ++k) {
            bufA[std::size_t(k)].cam = cameraCoordinates(i[k]);
            bufA[std::size_t(k)].bary = Eigen::Vector3d::Unit(k);
            bufA[std::size_t(k)].source = (screen[std::size_t(i[k])].code & (kBehind | kOutsideGuard)) ? -1 : i[k];
        }
        int n = clipPolygon(bufA.data(), 3, bufB.data(), [&](const Eigen::Vector3d& c) { return c.z() - nearDepth; });
        // Homogeneous pixel coordinates: pixel x = X / W with W = depth (perspective) or 1.
        const auto hx = [&](const Eigen::Vector3d& c) {
            return frame.orthographic ? frame.cx + frame.scale * c.x() : frame.cx * c.z() + frame.scale * c.x();
        };
        const auto hy = [&](const Eigen::Vector3d& c) {
            return frame.orthographic ? frame.cy - frame.scale * c.y() : frame.cy * c.z() - frame.scale * c.y();
        };
        const auto hw = [&](const Eigen::Vector3d& c) { return frame.orthographic ? 1.0 : c.z(); };
        if (n >= 3)
            n = clipPolygon(
                bufB.data(), n, bufA.data(), [&](const Eigen::Vector3d& c) { return hx(c) + kGuard * hw(c); });
        if (n >= 3)
            n = clipPolygon(
                bufA.data(), n, bufB.data(), [&](const Eigen::Vector3d& c) { return kGuard * hw(c) - hx(c); });
        if (n >= 3)
            n = clipPolygon(
                bufB.data(), n, bufA.data(), [&](const Eigen::Vector3d& c) { return hy(c) + kGuard * hw(c); });
        if (n >= 3)
            n = clipPolygon(
                bufA.data(), n, bufB.data(), [&](const Eigen::Vector3d& c) { return kGuard * hw(c) - hy(c); });
        if (n < 3)
            continue;
        // A convex polygon: a fan shares its diagonals exactly, so the fill rule leaves no seams.
        const RasterVertex first = rasterVertex(bufB[0]);
        for (int k = 2; k < n; ++k) {
            const RasterVertex previous = rasterVertex(bufB[std::size_t(k - 1)]);
            const RasterVertex next = rasterVertex(bufB[std::size_t(k)]);
            Eigen::Matrix3d corners;
            corners << bufB[0].bary, bufB[std::size_t(k - 1)].bary, bufB[std::size_t(k)].bary;
            rasterTriangle(first, previous, next, &corners, face, target);
        }
    }

    // Resolve pass, once per covered pixel: model-space position and interpolated normal of the
    // winning face (cheaper than interpolating them for every overdrawn sample).
    const bool haveNormals = vertexNormals.rows() == shape.rows() && vertexNormals.rows() > 0;
    const Eigen::Vector3f eyeF = camera.eye.cast<float>();
    for (std::size_t p = 0; p < pixelCount; ++p) {
        const std::int32_t f = out.faceId[p];
        if (f < 0) {
            if (positions)
                out.position[p].setZero();
            else
                out.facesAway[p] = 0;
            out.normal[p].setZero();
            out.barycentric[p].setZero();
            continue;
        }
        const Eigen::Vector3f& b = out.barycentric[p];
        const Eigen::Vector3f v0 = shape.row(faces(f, 0)).transpose();
        const Eigen::Vector3f v1 = shape.row(faces(f, 1)).transpose();
        const Eigen::Vector3f v2 = shape.row(faces(f, 2)).transpose();
        const Eigen::Vector3f point = b[0] * v0 + b[1] * v1 + b[2] * v2;
        Eigen::Vector3f n;
        if (haveNormals) {
            n = b[0] * vertexNormals.row(faces(f, 0)).transpose() + b[1] * vertexNormals.row(faces(f, 1)).transpose()
                + b[2] * vertexNormals.row(faces(f, 2)).transpose();
        } else {
            n = (v1 - v0).cross(v2 - v0);
        }
        const float length = n.norm();
        const Eigen::Vector3f unit = length > 0.f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::Zero();
        out.normal[p] = unit;
        if (positions)
            out.position[p] = point;
        else
            out.facesAway[p] = unit.dot(eyeF - point) < 0.f ? 1 : 0;
    }
}

namespace {

/// One capsule: distance to the segment with a one-pixel linear ramp at the edge, width and depth
/// interpolated at the closest point. The round ends make polylines join without gaps.
void drawSegment(const Eigen::Vector2f& a, const Eigen::Vector2f& b, float widthA, float widthB, float depthA,
    float depthB, const GBuffer& gbuffer, float depthBias, float* coverage)
{
    // Absolute slack for depths near zero, where the relative bias vanishes.
    constexpr float kDepthEpsilon = 1e-6f;
    const float reach = 0.5f * std::max(widthA, widthB) + 0.5f;
    if (!(reach > 0.f) || !a.allFinite() || !b.allFinite())
        return;
    // Pixel i has its centre at i + 0.5: the centres within reach of the segment's box.
    const float minX = std::min(a.x(), b.x()) - reach, maxX = std::max(a.x(), b.x()) + reach;
    const float minY = std::min(a.y(), b.y()) - reach, maxY = std::max(a.y(), b.y()) + reach;
    const int i0 = std::max(0, int(std::ceil(std::max(minX - 0.5f, -1.f))));
    const int i1 = std::min(gbuffer.width - 1, int(std::floor(std::min(maxX - 0.5f, float(gbuffer.width)))));
    const int j0 = std::max(0, int(std::ceil(std::max(minY - 0.5f, -1.f))));
    const int j1 = std::min(gbuffer.height - 1, int(std::floor(std::min(maxY - 0.5f, float(gbuffer.height)))));
    const Eigen::Vector2f d = b - a;
    const float length2 = d.squaredNorm();
    const float inverseLength2 = length2 > 0.f ? 1.f / length2 : 0.f;
    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const Eigen::Vector2f s(float(i) + 0.5f, float(j) + 0.5f);
            const float t = std::clamp((s - a).dot(d) * inverseLength2, 0.f, 1.f);
            const float distance2 = (s - (a + t * d)).squaredNorm();
            if (distance2 >= reach * reach)
                continue;
            const float distance = std::sqrt(distance2);
            const float width = widthA + t * (widthB - widthA);
            const float value = std::clamp(0.5f * width + 0.5f - distance, 0.f, 1.f);
            const std::size_t p = std::size_t(j) * std::size_t(gbuffer.width) + std::size_t(i);
            if (value <= coverage[p])
                continue;
            if (gbuffer.faceId[p] >= 0) {
                // Strokes are mesh edges a few pixels long: depth linear in screen space is within
                // the bias of the exact (reciprocal-linear) perspective depth.
                const float depth = depthA + t * (depthB - depthA);
                if (!(depth <= gbuffer.depth[p] * (1.f + depthBias) + kDepthEpsilon))
                    continue;
            }
            coverage[p] = value;
        }
    }
}

} // namespace

void drawStrokes(
    const std::vector<StyledStroke>& strokes, const GBuffer& gbuffer, std::vector<float>& coverage, float depthBias)
{
    const std::size_t pixelCount = std::size_t(std::max(0, gbuffer.width)) * std::size_t(std::max(0, gbuffer.height));
    if (coverage.size() != pixelCount)
        coverage.assign(pixelCount, 0.f);
    if (pixelCount == 0)
        return;
    for (const StyledStroke& stroke : strokes) {
        const std::size_t n = stroke.points.size();
        assert(stroke.depths.size() == n && stroke.widths.size() == n);
        if (n == 0 || stroke.depths.size() != n || stroke.widths.size() != n)
            continue;
        if (n == 1) {
            drawSegment(stroke.points[0], stroke.points[0], stroke.widths[0], stroke.widths[0], stroke.depths[0],
                stroke.depths[0], gbuffer, depthBias, coverage.data());
            continue;
        }
        for (std::size_t k = 0; k + 1 < n; ++k)
            drawSegment(stroke.points[k], stroke.points[k + 1], stroke.widths[k], stroke.widths[k + 1],
                stroke.depths[k], stroke.depths[k + 1], gbuffer, depthBias, coverage.data());
    }
}

} // namespace celform::algo
