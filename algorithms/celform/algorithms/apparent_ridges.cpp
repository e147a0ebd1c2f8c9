// Apparent ridges, written from Judd, Durand and Adelson 2007 (JDA07) and paper 3, section 4.2:
// three passes over the mesh per view (q1 per vertex, its derivative per vertex, segments per
// face), each split over a few threads in ordered blocks.
#include "celform/algorithms/apparent_ridges.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <thread>

namespace celform::algo {
namespace {

using Vec3 = Eigen::Vector3f;
using Vec2 = Eigen::Vector2f;

/// |n.v| is clamped to this before the secant: at the contour itself P is singular and q1 is
/// infinite; 1e-3 keeps q1 finite (1000 times k at most) while still far above any threshold.
constexpr float kMinCos = 1e-3f;

inline Vec3 row(const Positions& p, std::int32_t i)
{
    const float* x = p.data() + 3 * std::ptrdiff_t(i);
    return Vec3(x[0], x[1], x[2]);
}

/// Runs fn(begin, end, block) over [0, count) in `threads` ordered blocks, the last one on the
/// calling thread.
template <typename Fn> void parallelBlocks(std::size_t count, int threads, Fn fn)
{
    const int n = std::max(1, std::min(threads, int(count / 4096) + 1));
    if (n == 1) {
        fn(std::size_t(0), count, 0);
        return;
    }
    std::thread workers[7];
    const int spawned = std::min(n, 8) - 1;
    const std::size_t step = (count + std::size_t(spawned + 1) - 1) / std::size_t(spawned + 1);
    for (int t = 0; t < spawned; ++t)
        workers[t] = std::thread(fn, std::size_t(t) * step, std::min(count, std::size_t(t + 1) * step), t);
    fn(std::min(count, std::size_t(spawned) * step), count, spawned);
    for (int t = 0; t < spawned; ++t)
        workers[t].join();
}

inline int blockCount(std::size_t count, int threads)
{
    return std::min(8, std::max(1, std::min(threads, int(count / 4096) + 1)));
}

/// The unit vector from p towards the viewer.
inline Vec3 towardsViewer(const LineView& view, const Vec3& p)
{
    if (view.orthographic)
        return -view.direction.normalized();
    const Vec3 d = view.eye - p;
    const float len2 = d.squaredNorm();
    return len2 > 0.f ? Vec3(d * (1.f / std::sqrt(len2))) : Vec3(0.f, 0.f, 1.f);
}

/// JDA07, section 3: the view-dependent curvature operator Q = S P^-1 maps a screen-plane step to
/// the change of the normal. In the principal frame S = diag(k1, k2); P (the orthographic
/// projection of the tangent plane onto the screen plane) shortens steps along w, the unit tangent
/// component of the view vector, by cos(theta) = n.v, so P^-1 = I + (sec(theta) - 1) w w^T.
/// q1 is the largest singular value of Q; t1 the screen step that reaches it, carried back onto
/// the surface (T1 = P^-1 t1, normalised) so that the derivative is taken along the surface.
/// Returns q1; with kDirection also sets surfaceDir (pass 1 needs q1 everywhere, the direction
/// only where the derivative is taken, a minority of the vertices).
template <bool kDirection>
float viewDependentCurvature(float k1, float k2, float u, float v, float ndotv, Vec2* surfaceDir)
{
    // Only products of w's components appear (aa = a^2, ab, bb with w = (a, b) = (u, v) / |(u, v)|),
    // so w itself is never normalised: one square root fewer per vertex.
    const float sin2 = u * u + v * v;
    float aa = 0.f, ab = 0.f, bb = 0.f;
    if (sin2 > 1e-12f) {
        const float r = 1.f / sin2;
        aa = u * u * r;
        ab = u * v * r;
        bb = v * v * r;
    }
    const float s = 1.f / std::max(std::abs(ndotv), kMinCos) - 1.f;
    const float q11 = k1 * (1.f + s * aa), q12 = k1 * s * ab;
    const float q21 = k2 * s * ab, q22 = k2 * (1.f + s * bb);
    // Q^T Q: its largest eigenvalue is q1 squared, its eigenvector the right singular vector t1.
    const float m11 = q11 * q11 + q21 * q21, m12 = q11 * q12 + q21 * q22, m22 = q12 * q12 + q22 * q22;
    const float half = 0.5f * (m11 - m22);
    const float lambda = 0.5f * (m11 + m22) + std::sqrt(m12 * m12 + half * half);
    const float q1 = std::sqrt(std::max(lambda, 0.f));
    if (!kDirection)
        return q1;
    const Vec2 e1(m12, lambda - m11), e2(lambda - m22, m12);
    Vec2 t = e1.squaredNorm() >= e2.squaredNorm() ? e1 : e2;
    if (!(t.squaredNorm() > 1e-30f))
        t = Vec2(1.f, 0.f);
    // T1 = P^-1 t1 = t1 + s (w.t1) w, normalised once at the end (P^-1 is linear).
    const Vec2 surface(t.x() + s * (aa * t.x() + ab * t.y()), t.y() + s * (ab * t.x() + bb * t.y()));
    const float len2 = surface.squaredNorm();
    *surfaceDir = len2 > 0.f ? Vec2(surface * (1.f / std::sqrt(len2))) : Vec2(1.f, 0.f);
    return q1;
}

/// A point's noise key from the edge it lies on. Not mixed: the line style hashes keys itself.
inline std::uint32_t edgeKey(std::int32_t a, std::int32_t b)
{
    return std::uint32_t(std::min(a, b)) * 2654435761u + std::uint32_t(std::max(a, b));
}

using Record = ApparentRidgeWorkspace::VertexRecord;

/// Where Dt1q1 crosses zero on edge (x, y): linear in the slopes' magnitudes (the g vectors of the
/// two ends point against each other there). Computed from the lower vertex index, so the two
/// faces of an edge produce the same point bit for bit and the segments chain exactly.
struct Crossing {
    Vec3 point;
    float excess;
    std::uint32_t key;
};

inline Crossing crossing(const Positions& shape, const Record* rec, std::int32_t x, std::int32_t y)
{
    if (x > y)
        std::swap(x, y);
    const Record& rx = rec[x];
    const Record& ry = rec[y];
    const float sum = rx.slope + ry.slope;
    const float w = sum > 0.f ? rx.slope / sum : 0.5f;
    Crossing c;
    c.point = row(shape, x) + w * (row(shape, y) - row(shape, x));
    c.excess = rx.excess + w * (ry.excess - rx.excess);
    c.key = edgeKey(x, y);
    return c;
}

inline Vec3 gradient(const Record& r)
{
    return Vec3(r.gx, r.gy, r.gz);
}

/// JDA07's per-face rule for a segment whose ends lie on edges (a, l) and (l, b), or from the
/// first to the face centre: kept when either end passes the threshold and q1 is a maximum
/// across it, i.e. the gradients of l on one side and of a, b on the other all point towards it.
void emitSegment(const Positions& shape, const Record* rec, std::int32_t a, std::int32_t l, std::int32_t b,
    const Crossing& p, const Crossing& q, RidgeSegments& out)
{
    if (p.excess <= 0.f && q.excess <= 0.f)
        return;
    const Vec3 pa = row(shape, a), pl = row(shape, l), pb = row(shape, b);
    const Vec3 perp = ((pl - pa).cross(pb - pl)).cross(p.point - q.point);
    if (gradient(rec[a]).dot(perp) <= 0.f || gradient(rec[l]).dot(perp) >= 0.f || gradient(rec[b]).dot(perp) <= 0.f)
        return;
    out.points.push_back(p.point);
    out.points.push_back(q.point);
    out.keys.push_back(p.key);
    out.keys.push_back(q.key);
}

/// Per-vertex flags of pass 1: n.v > 0, q1 above the threshold.
constexpr std::uint8_t kFacing = 1, kAbove = 2;

/// Whether a face can hold a ridge: not turned away at all three corners (paper 3, section 4.2
/// and JDA07: faces just past the contour still take part, the ridges near contours run over
/// them), and q1 above the threshold at one corner at least.
inline bool candidate(const Record& r0, const Record& r1, const Record& r2)
{
    return !(r0.ndotv <= 0.f && r1.ndotv <= 0.f && r2.ndotv <= 0.f)
        && !(r0.excess <= 0.f && r1.excess <= 0.f && r2.excess <= 0.f);
}

void faceRidges(const Positions& shape, const Faces& faces, const Record* rec,
    const std::vector<std::int32_t>& candidates, RidgeSegments& out)
{
    const std::int32_t* tri = faces.data();
    for (const std::int32_t face : candidates) {
        const auto f = std::size_t(face);
        const std::int32_t v0 = tri[3 * f], v1 = tri[3 * f + 1], v2 = tri[3 * f + 2];
        const Record &r0 = rec[v0], &r1 = rec[v1], &r2 = rec[v2];
        if (!candidate(r0, r1, r2))
            continue;
        const Vec3 g0 = gradient(r0), g1 = gradient(r1), g2 = gradient(r2);
        // A zero crossing of Dt1q1 on an edge where the two gradients point against each other.
        // g = Dt1q1 * T1 does not change when t1 flips (both factors do), which makes the t1 of
        // the three corners consistent without choosing signs.
        const bool z01 = g0.dot(g1) <= 0.f, z12 = g1.dot(g2) <= 0.f, z20 = g2.dot(g0) <= 0.f;
        const int crossings = int(z01) + int(z12) + int(z20);
        if (crossings < 2)
            continue;
        if (crossings == 2) {
            // The corner between the two crossed edges is alone on its side of the segment.
            if (!z01)
                emitSegment(shape, rec, v1, v2, v0, crossing(shape, rec, v1, v2), crossing(shape, rec, v2, v0), out);
            else if (!z12)
                emitSegment(shape, rec, v2, v0, v1, crossing(shape, rec, v2, v0), crossing(shape, rec, v0, v1), out);
            else
                emitSegment(shape, rec, v0, v1, v2, crossing(shape, rec, v0, v1), crossing(shape, rec, v1, v2), out);
            continue;
        }
        // Three crossings: each joins the face centre (JDA07, as rtsc draws it).
        Crossing centre;
        centre.point = (row(shape, v0) + row(shape, v1) + row(shape, v2)) / 3.f;
        centre.excess = (r0.excess + r1.excess + r2.excess) / 3.f;
        centre.key = std::uint32_t(f) * 0x85ebca6bu + 0x51ed27u;
        emitSegment(shape, rec, v0, v1, v2, crossing(shape, rec, v0, v1), centre, out);
        emitSegment(shape, rec, v1, v2, v0, crossing(shape, rec, v1, v2), centre, out);
        emitSegment(shape, rec, v2, v0, v1, crossing(shape, rec, v2, v0), centre, out);
    }
}

} // namespace

float ridgeFeatureSize(const Positions& shape, const Faces& faces)
{
    std::vector<float> lengths;
    lengths.reserve(std::size_t(faces.rows()) * 3);
    const auto nv = std::int32_t(shape.rows());
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = faces(f, k), b = faces(f, (k + 1) % 3);
            if (a < 0 || b < 0 || a >= nv || b >= nv || a == b)
                continue;
            const float len = (row(shape, a) - row(shape, b)).norm();
            if (std::isfinite(len) && len > 0.f)
                lengths.push_back(len);
        }
    if (lengths.empty())
        return 0.f;
    auto middle = lengths.begin() + std::ptrdiff_t(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return *middle;
}

void computeApparentRidges(const Positions& shape, const Faces& faces, const VertexFaces& around,
    const Curvatures& curvatures, const LineView& view, const ApparentRidgeOptions& options,
    ApparentRidgeWorkspace& workspace, RidgeSegments& out)
{
    out.clear();
    const auto nv = std::size_t(shape.rows());
    const auto nf = std::size_t(faces.rows());
    const Positions& normals = curvatures.workspace.normals;
    if (nv == 0 || nf == 0 || curvatures.k1.size() != nv || std::size_t(normals.rows()) != nv
        || around.start.size() != nv + 1 || !(options.featureSize > 0.f))
        return;
    assert(!options.thresholdScale || options.thresholdScale->size() == nv);
    const std::vector<float>* scale
        = options.thresholdScale && options.thresholdScale->size() == nv ? options.thresholdScale : nullptr;
    workspace.q1.resize(nv);
    workspace.t1.resize(nv);
    workspace.dt1q1.resize(nv);
    workspace.records.resize(nv);
    float* q1 = workspace.q1.data();
    Vec3* t1 = workspace.t1.data();

    // Pass 1, per vertex: q1 (JDA07, section 3), n.v and the excess of q1 over the threshold.
    const float baseThreshold = options.threshold / options.featureSize;
    Record* rec = workspace.records.data();
    // Face blocks of passes 1b and 3; marks holds one array per block and, last, the flags.
    const int blocks = blockCount(nf, options.threads);
    if (workspace.marks.size() < std::size_t(blocks) + 1)
        workspace.marks.resize(std::size_t(blocks) + 1);
    std::vector<std::uint8_t>& flagArray = workspace.marks[std::size_t(blocks)];
    flagArray.resize(nv);
    std::uint8_t* flags = flagArray.data();
    parallelBlocks(nv, options.threads, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) {
            const auto v = std::int32_t(i);
            const Vec3 p = row(shape, v), n = row(normals, v);
            const Vec3 toViewer = towardsViewer(view, p);
            const float ndotv = toViewer.dot(n);
            q1[i] = viewDependentCurvature<false>(curvatures.k1[i], curvatures.k2[i],
                toViewer.dot(row(curvatures.dir1, v)), toViewer.dot(row(curvatures.dir2, v)), ndotv, nullptr);
            Record& r = rec[i];
            r.gx = r.gy = r.gz = 0.f;
            r.slope = 0.f;
            r.excess = q1[i] - baseThreshold * (scale ? (*scale)[i] : 1.f);
            r.ndotv = ndotv;
            flags[i] = std::uint8_t((ndotv > 0.f ? kFacing : 0) | (r.excess > 0.f ? kAbove : 0));
        }
    });

    // Pass 1b, per face: which vertices pass 3 will look at (faces not turned away whose q1 passes
    // the threshold somewhere). Only those need the derivative, the costly part: on the dragon
    // seen whole at the default threshold, a small fraction of the vertices. One mark array per
    // block, so the blocks never write the same bytes.
    if (workspace.perThread.size() < std::size_t(blocks))
        workspace.perThread.resize(std::size_t(blocks));
    if (workspace.candidates.size() < std::size_t(blocks))
        workspace.candidates.resize(std::size_t(blocks));
    parallelBlocks(nf, options.threads, [&](std::size_t begin, std::size_t end, int block) {
        std::vector<std::uint8_t>& mark = workspace.marks[std::size_t(block)];
        std::vector<std::int32_t>& list = workspace.candidates[std::size_t(block)];
        mark.assign(nv, 0);
        list.clear();
        const std::int32_t* tri = faces.data();
        for (std::size_t f = begin; f < end; ++f) {
            const std::int32_t v0 = tri[3 * f], v1 = tri[3 * f + 1], v2 = tri[3 * f + 2];
            // The same test as candidate() on one byte per corner instead of a record.
            if ((flags[v0] | flags[v1] | flags[v2]) == (kFacing | kAbove)) {
                mark[std::size_t(v0)] = mark[std::size_t(v1)] = mark[std::size_t(v2)] = 1;
                list.push_back(std::int32_t(f));
            }
        }
    });

    // Pass 2, per marked vertex: T1, then Dt1q1 by finite differences over the one-ring (JDA07,
    // section 4): the line through the vertex along T1 leaves it through one face forwards and one backwards; q1
    // is interpolated where it crosses the far edge, and the difference is divided by the
    // screen-plane length of the step. dcurv is not used: q1 depends on the view through P as
    // well as on S, and the differences capture both, the change of the projection included.
    parallelBlocks(nv, options.threads, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) {
            bool needed = false;
            for (int b = 0; b < blocks; ++b)
                needed = needed || workspace.marks[std::size_t(b)][i] != 0;
            if (!needed) {
                workspace.dt1q1[i] = 0.f;
                t1[i].setZero();
                continue;
            }
            const auto v = std::int32_t(i);
            const Vec3 p = row(shape, v), n = row(normals, v);
            const Vec3 d1 = row(curvatures.dir1, v), d2 = row(curvatures.dir2, v);
            const Vec3 toViewer = towardsViewer(view, p);
            Vec2 dir;
            viewDependentCurvature<true>(
                curvatures.k1[i], curvatures.k2[i], toViewer.dot(d1), toViewer.dot(d2), toViewer.dot(n), &dir);
            const Vec3 t = dir.x() * d1 + dir.y() * d2;
            t1[i] = t;
            const Vec3 side = n.cross(t);
            float forward = 0.f, backward = 0.f;
            bool haveForward = false, haveBackward = false;
            for (std::int32_t k = around.start[i]; k < around.start[i + 1] && !(haveForward && haveBackward); ++k) {
                const std::int32_t* tri = faces.data() + 3 * std::ptrdiff_t(around.faces[std::size_t(k)]);
                const int corner = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
                const std::int32_t a = tri[(corner + 1) % 3], b = tri[(corner + 2) % 3];
                const Vec3 pa = row(shape, a), pb = row(shape, b);
                const float da = (pa - p).dot(side), db = (pb - p).dot(side);
                if (!((da > 0.f && db < 0.f) || (da < 0.f && db > 0.f)))
                    continue;
                const float w = da / (da - db);
                const Vec3 step = pa + w * (pb - pa) - p;
                const float along = step.dot(t);
                const float screen = (step - step.dot(toViewer) * toViewer).norm();
                if (!(screen > 0.f))
                    continue;
                const float difference = (q1[a] + w * (q1[b] - q1[a]) - q1[i]) / screen;
                if (along > 0.f && !haveForward) {
                    forward = difference;
                    haveForward = true;
                } else if (along < 0.f && !haveBackward) {
                    backward = -difference;
                    haveBackward = true;
                }
            }
            float d = 0.f;
            if (haveForward && haveBackward)
                d = 0.5f * (forward + backward);
            else if (haveForward)
                d = forward;
            else if (haveBackward)
                d = backward;
            workspace.dt1q1[i] = d;
            Record& r = rec[i];
            r.gx = d * t.x();
            r.gy = d * t.y();
            r.gz = d * t.z();
            r.slope = std::abs(d);
        }
    });

    // Pass 3, per face: segments, each block into its own buffer, joined in block order.
    // The candidate lists of pass 1b, one thread each.
    std::thread workers[7];
    auto run = [&](int block) {
        RidgeSegments& mine = workspace.perThread[std::size_t(block)];
        mine.clear();
        faceRidges(shape, faces, rec, workspace.candidates[std::size_t(block)], mine);
    };
    for (int b = 1; b < blocks; ++b)
        workers[b - 1] = std::thread(run, b);
    run(0);
    for (int b = 1; b < blocks; ++b)
        workers[b - 1].join();
    std::size_t total = 0;
    for (int b = 0; b < blocks; ++b)
        total += workspace.perThread[std::size_t(b)].points.size();
    out.points.reserve(total);
    out.keys.reserve(total);
    for (int b = 0; b < blocks; ++b) {
        const RidgeSegments& part = workspace.perThread[std::size_t(b)];
        out.points.insert(out.points.end(), part.points.begin(), part.points.end());
        out.keys.insert(out.keys.end(), part.keys.begin(), part.keys.end());
    }
}

} // namespace celform::algo
