// Feature lines: edge adjacency once per topology, feature edges per frame, strokes and their
// hand-drawn look (comic paper, "Outlining"; paper 3, section 4.2.2).
#include "celform/algorithms/lines.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

namespace celform::algo {
namespace {

constexpr std::uint8_t kOutlineBits = kSilhouette | kBorder;

/// What the edge pass needs of a face, packed in 8 bytes so the two faces of an edge cost two
/// cache lines at most: the unit normal in 16-bit fixed point (1/32767 per unit: crease angles
/// are exact to a few thousandths of a degree) and the facing. Unit vectors keep every partial
/// dot product within 32767^2 (Cauchy-Schwarz), so the crease test runs in int32 arithmetic.
struct FaceRecord {
    std::int16_t normal[3];
    std::int16_t facing; ///< 1 front, -1 back, 0 degenerate
};
static_assert(sizeof(FaceRecord) == 8, "FaceRecord must stay packed");
constexpr float kNormalScale = 32767.0f;

/// Round half away from zero, inline (std::lrint is a libm call: 14% of the frame).
std::int16_t toFixed(float x)
{
    return std::int16_t(x + std::copysign(0.5f, x));
}

/// Per-frame face records, kept between frames so extraction does not allocate (and page-fault
/// on 7 MB of fresh memory for the dragon) every frame. One per thread, so views extracting
/// lines concurrently do not share it.
std::vector<FaceRecord>& faceScratch()
{
    thread_local std::vector<FaceRecord> scratch;
    return scratch;
}

/// The edge pass's list of every edge with its kind (features first), kept per thread: room for
/// every edge, of which about 2 % are written, left uninitialised, so that the pages no feature
/// edge reaches are never faulted in (issue 29: 6.5 MB of the dragon, per thread).
struct EdgeScratch {
    std::unique_ptr<std::int32_t[]> edges;
    std::unique_ptr<std::uint8_t[]> kinds;
    std::size_t size = 0;
};
EdgeScratch& edgeScratch()
{
    thread_local EdgeScratch scratch;
    return scratch;
}

/// Working memory of the crease hysteresis, kept per thread like faceScratch.
struct HysteresisScratch {
    std::vector<std::uint8_t> reached; ///< per vertex: touched by an accepted crease
    std::vector<std::pair<std::int32_t, std::int32_t>> weakAt; ///< (vertex, index into out), sorted
    std::vector<std::int32_t> queue;
};
HysteresisScratch& hysteresisScratch()
{
    thread_local HysteresisScratch scratch;
    return scratch;
}

/// Internal mark of the edge pass: dihedral angle between the low and the high crease angle.
constexpr std::uint8_t kWeakCrease = 0x80;

/// Crease hysteresis (after Canny's edge linking, here along mesh edges): weak creases reached
/// from an accepted crease through shared vertices and other weak creases become creases; the
/// rest are dropped. Keeps out in ascending edge order.
void linkWeakCreases(const EdgeTopology& topology, std::int32_t vertexCount, FeatureEdges& out)
{
    HysteresisScratch& h = hysteresisScratch();
    h.weakAt.clear();
    for (std::size_t i = 0; i < out.edges.size(); ++i)
        if (out.kinds[i] & kWeakCrease)
            for (int k = 0; k < 2; ++k)
                h.weakAt.emplace_back(topology.edges(out.edges[i], k), std::int32_t(i));
    if (h.weakAt.empty())
        return;
    std::sort(h.weakAt.begin(), h.weakAt.end());
    h.reached.assign(std::size_t(vertexCount), 0);
    for (std::size_t i = 0; i < out.edges.size(); ++i)
        if (out.kinds[i] & kCrease)
            for (int k = 0; k < 2; ++k)
                h.reached[std::size_t(topology.edges(out.edges[i], k))] = 1;
    h.queue.clear();
    for (const auto& [v, i] : h.weakAt)
        if (h.reached[std::size_t(v)])
            h.queue.push_back(i);
    while (!h.queue.empty()) {
        const std::int32_t i = h.queue.back();
        h.queue.pop_back();
        std::uint8_t& kind = out.kinds[std::size_t(i)];
        if (!(kind & kWeakCrease))
            continue;
        kind = std::uint8_t((kind & ~kWeakCrease) | kCrease);
        for (int k = 0; k < 2; ++k) {
            const std::int32_t v = topology.edges(out.edges[std::size_t(i)], k);
            if (h.reached[std::size_t(v)])
                continue;
            h.reached[std::size_t(v)] = 1;
            auto it = std::lower_bound(
                h.weakAt.begin(), h.weakAt.end(), std::make_pair(v, std::numeric_limits<std::int32_t>::min()));
            for (; it != h.weakAt.end() && it->first == v; ++it)
                if (out.kinds[std::size_t(it->second)] & kWeakCrease)
                    h.queue.push_back(it->second);
        }
    }
    // Weak creases left unreached go; edges that were only that leave the list.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < out.edges.size(); ++i) {
        const auto kind = std::uint8_t(out.kinds[i] & ~kWeakCrease);
        if (kind == 0)
            continue;
        out.edges[kept] = out.edges[i];
        out.kinds[kept] = kind;
        ++kept;
    }
    out.edges.resize(kept);
    out.kinds.resize(kept);
}

/// lowbias32 integer hash (Chris Wellons): cheap and well mixed, so neighbouring vertex indices
/// get unrelated noise.
std::uint32_t mixBits(std::uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/// Noise in [-1, 1) attached to a vertex index, not to a screen position: it moves with the
/// surface point from frame to frame (frame-coherent hand-drawn look).
float vertexNoise(std::int32_t vertex, std::uint32_t seed, std::uint32_t salt)
{
    const std::uint32_t h = mixBits(std::uint32_t(vertex) * 0x9e3779b9U ^ mixBits(seed * 0x85ebca6bU + salt));
    return float(h >> 8) * (2.0f / 16777216.0f) - 1.0f;
}

constexpr std::uint32_t kJitterSalt = 0x4a17u;
constexpr std::uint32_t kWidthSalt = 0x3d1bu;
/// Overshoot ends taper to this fraction of the end width, like a pen lifted off the paper.
constexpr float kOvershootTaper = 0.6f;

/// Styles one run of projected vertices (depth > 0 everywhere). A closed run is emitted with its
/// first point repeated at the end so the polyline closes; only open runs overshoot.
void styleRun(const std::vector<std::int32_t>& ids, bool closed, std::uint8_t kinds,
    const std::vector<Eigen::Vector3f>& projected, const LineStyle& style, const std::vector<std::uint32_t>* noiseKeys,
    std::vector<StyledStroke>& out)
{
    auto noiseId = [&](std::size_t i) { return noiseKeys ? std::int32_t((*noiseKeys)[std::size_t(ids[i])]) : ids[i]; };
    const std::size_t m = ids.size();
    if (m < 2)
        return;
    StyledStroke s;
    s.kinds = kinds;
    s.closed = closed;
    const float base = (kinds & kOutlineBits) ? style.outlineWidth : style.innerWidth;
    s.points.resize(m);
    s.depths.resize(m);
    s.widths.assign(m, base);
    for (std::size_t i = 0; i < m; ++i) {
        const Eigen::Vector3f& p = projected[std::size_t(ids[i])];
        s.points[i] = p.head<2>();
        s.depths[i] = p.z();
    }
    auto prevIndex = [&](std::size_t i) { return i > 0 ? i - 1 : (closed ? m - 1 : 0); };
    auto nextIndex = [&](std::size_t i) { return i + 1 < m ? i + 1 : (closed ? 0 : m - 1); };

    if (style.widthVariation != 0.0f) {
        // Comic paper: lines "of varying width". The per-vertex noise is smoothed with a
        // [1 2 1] kernel along the stroke so adjacent points do not alternate thick/thin.
        std::vector<float> noise(m);
        for (std::size_t i = 0; i < m; ++i)
            noise[i] = vertexNoise(noiseId(i), style.seed, kWidthSalt);
        for (std::size_t i = 0; i < m; ++i) {
            const std::size_t a = prevIndex(i), b = nextIndex(i);
            float sum = 2.0f * noise[i], weight = 2.0f;
            if (a != i) {
                sum += noise[a];
                weight += 1.0f;
            }
            if (b != i) {
                sum += noise[b];
                weight += 1.0f;
            }
            s.widths[i] = std::max(0.0f, base * (1.0f + style.widthVariation * sum / weight));
        }
    }

    if (style.jitter != 0.0f) {
        // Comic paper: lines are "jagged". Offsets are perpendicular to the projected stroke and
        // their signed length comes from the vertex index alone, so a vertex keeps its offset
        // magnitude whatever the camera does; only its direction follows the stroke.
        std::vector<Eigen::Vector2f> jittered(m);
        for (std::size_t i = 0; i < m; ++i) {
            Eigen::Vector2f t = s.points[nextIndex(i)] - s.points[prevIndex(i)];
            const float len = t.norm();
            t = len > 0.0f ? Eigen::Vector2f(t / len) : Eigen::Vector2f(1.0f, 0.0f);
            const Eigen::Vector2f normal(-t.y(), t.x());
            jittered[i] = s.points[i] + style.jitter * vertexNoise(noiseId(i), style.seed, kJitterSalt) * normal;
        }
        s.points.swap(jittered);
    }

    if (closed) {
        s.points.push_back(s.points.front());
        s.depths.push_back(s.depths.front());
        s.widths.push_back(s.widths.front());
    } else {
        overshootEnds(s, style.overshoot);
    }
    out.push_back(std::move(s));
}

} // namespace

void overshootEnds(StyledStroke& s, float overshoot)
{
    const std::size_t m = s.points.size();
    if (overshoot <= 0.0f || s.closed || m < 2)
        return;
    // Comic paper: lines "often overshoot the desired direction somewhat". Each end is
    // extended along its end tangent (first non-degenerate segment from that end).
    auto extension = [&](std::size_t end, int step) -> std::optional<Eigen::Vector2f> {
        for (std::size_t k = 1; k < m; ++k) {
            const std::size_t j = step > 0 ? end + k : end - k;
            const Eigen::Vector2f d = s.points[end] - s.points[j];
            const float len = d.norm();
            if (len > 0.0f)
                return Eigen::Vector2f(s.points[end] + d * (overshoot / len));
        }
        return std::nullopt;
    };
    const auto head = extension(0, +1);
    const auto tail = extension(m - 1, -1);
    if (tail) {
        s.points.push_back(*tail);
        s.depths.push_back(s.depths[m - 1]);
        s.widths.push_back(s.widths[m - 1] * kOvershootTaper);
    }
    if (head) {
        s.points.insert(s.points.begin(), *head);
        s.depths.insert(s.depths.begin(), s.depths.front());
        s.widths.insert(s.widths.begin(), s.widths.front() * kOvershootTaper);
    }
}

void extractFeatureEdges(const Positions& shape, const Faces& faces, const EdgeTopology& topology,
    const std::vector<std::int32_t>& faceMaterials, const LineView& view, const LineSettings& settings,
    FeatureEdges& out)
{
    out.edges.clear();
    out.kinds.clear();
    const auto nf = std::size_t(faces.rows());
    const auto ne = std::size_t(topology.edges.rows());
    assert(topology.faces.rows() == topology.edges.rows() && topology.nonManifold.size() == ne);
    assert(faceMaterials.empty() || faceMaterials.size() == nf);
    const bool useMaterials = settings.materialBoundaries && faceMaterials.size() == nf && nf > 0;
    if (!settings.silhouettes && !settings.creases && !settings.borders && !useMaterials)
        return;

    // Face pass: unit normal and facing once per face. Facing is sign(dot(n_f, p - eye)) with p
    // the face's first vertex (paper 3, section 4.2.2: per-triangle view vectors; the comic
    // paper's "dot product negative = facing the viewer"). Every point p of the face's plane
    // gives the same dot product, so this equals the test at the shared edge point for both
    // faces of an edge, and classifying each face once keeps it consistent across its three
    // edges: on a closed mesh the silhouettes then bound the front-facing region and chain into
    // closed loops. Edge-on faces (dot == 0) count as back-facing; degenerate faces (zero normal)
    // have no facing and make no silhouettes or creases. For stereo, pass the centre eye
    // (paper 3, section 4.2) so both images get the same lines.
    std::vector<FaceRecord>& records = faceScratch();
    records.resize(nf);
    // Blocks of faces: the scattered corner loads first, then branch-free arithmetic on small
    // arrays. GCC 12 vectorizes the view-vector loop but not yet the normal loop ("control flow
    // in loop"); the layout is kept so that a compiler that if-converts it can.
    constexpr std::size_t kBlock = 64;
    alignas(32) float ax[kBlock], ay[kBlock], az[kBlock], ux[kBlock], uy[kBlock], uz[kBlock];
    alignas(32) float wx[kBlock], wy[kBlock], wz[kBlock], vx[kBlock], vy[kBlock], vz[kBlock];
    const float* pos = shape.data();
    const std::int32_t* tri = faces.data();
    const Eigen::Vector3f eye = view.eye, direction = view.direction;
    for (std::size_t f0 = 0; f0 < nf; f0 += kBlock) {
        const std::size_t count = std::min(kBlock, nf - f0);
#if defined(__GNUC__)
        // The corners of the next block are the scattered reads of this pass: fetch them while
        // this block computes.
        const std::size_t next = std::min(nf, f0 + 2 * kBlock);
        for (std::size_t k = 3 * (f0 + kBlock); k < 3 * next; ++k)
            __builtin_prefetch(pos + 3 * std::size_t(tri[k]));
#endif
        for (std::size_t i = 0; i < count; ++i) {
            const float* pa = pos + 3 * std::size_t(tri[3 * (f0 + i)]);
            const float* pb = pos + 3 * std::size_t(tri[3 * (f0 + i) + 1]);
            const float* pc = pos + 3 * std::size_t(tri[3 * (f0 + i) + 2]);
            ax[i] = pa[0];
            ay[i] = pa[1];
            az[i] = pa[2];
            ux[i] = pb[0] - pa[0];
            uy[i] = pb[1] - pa[1];
            uz[i] = pb[2] - pa[2];
            wx[i] = pc[0] - pa[0];
            wy[i] = pc[1] - pa[1];
            wz[i] = pc[2] - pa[2];
        }
        if (view.orthographic) {
            std::fill_n(vx, count, direction.x());
            std::fill_n(vy, count, direction.y());
            std::fill_n(vz, count, direction.z());
        } else {
            for (std::size_t i = 0; i < count; ++i) {
                vx[i] = ax[i] - eye.x();
                vy[i] = ay[i] - eye.y();
                vz[i] = az[i] - eye.z();
            }
        }
        // Pure float arithmetic with selects into small arrays (vectorizes), then the packing
        // into 16-bit records in a loop of its own.
        alignas(32) float qx[kBlock], qy[kBlock], qz[kBlock], side[kBlock];
        for (std::size_t i = 0; i < count; ++i) {
            const float nx = uy[i] * wz[i] - uz[i] * wy[i];
            const float ny = uz[i] * wx[i] - ux[i] * wz[i];
            const float nz = ux[i] * wy[i] - uy[i] * wx[i];
            const float len2 = nx * nx + ny * ny + nz * nz;
            // Degenerate faces (zero or overflowing normal) get a zero normal and no facing.
            const bool proper = (len2 > 0.0f) & (len2 <= std::numeric_limits<float>::max());
            // Every product is computed unconditionally and only selected afterwards: a product
            // under a condition is a trapping operation GCC will not if-convert, and the loop
            // would stay scalar.
            const float inverse = kNormalScale / std::sqrt(proper ? len2 : 1.0f);
            const float sx = nx * inverse, sy = ny * inverse, sz = nz * inverse;
            qx[i] = proper ? sx : 0.0f;
            qy[i] = proper ? sy : 0.0f;
            qz[i] = proper ? sz : 0.0f;
            const float d = nx * vx[i] + ny * vy[i] + nz * vz[i];
            const float facing = d < 0.0f ? 1.0f : -1.0f;
            side[i] = proper ? facing : 0.0f;
        }
        FaceRecord* r = records.data() + f0;
        for (std::size_t i = 0; i < count; ++i) {
            r[i].normal[0] = toFixed(qx[i]);
            r[i].normal[1] = toFixed(qy[i]);
            r[i].normal[2] = toFixed(qz[i]);
            r[i].facing = std::int16_t(side[i]);
        }
    }

    // Edge pass. Crease: the angle between the unit face normals exceeds the threshold, i.e.
    // their dot product is below its cosine (the comic paper's thinner "special" edges).
    const float cosCrease = std::cos(settings.creaseAngleDegrees * float(3.14159265358979323846 / 180.0));
    // In fixed point; a cosine below -1 (threshold above 180 degrees) leaves nothing to find.
    const std::int32_t cosCreaseFixed = cosCrease < -1.0f
        ? std::numeric_limits<std::int32_t>::min()
        : std::int32_t(std::lrint(double(cosCrease) * double(kNormalScale) * double(kNormalScale)));
    // Hysteresis: below the high threshold's cosine but below the low one's is a weak crease.
    const bool hysteresis = settings.creases && settings.creaseLowAngleDegrees < settings.creaseAngleDegrees;
    const float cosLow
        = std::cos(std::max(settings.creaseLowAngleDegrees, 0.0f) * float(3.14159265358979323846 / 180.0));
    const std::int32_t cosLowFixed = hysteresis
        ? std::max(
            cosCreaseFixed, std::int32_t(std::lrint(double(cosLow) * double(kNormalScale) * double(kNormalScale))))
        : cosCreaseFixed;
    const FaceRecord* rec = records.data();
    constexpr std::size_t kPrefetchDistance = 32;
    const std::int32_t* edgeFaces = topology.faces.data();
    const std::uint8_t* nonManifold = topology.nonManifold.data();
    const bool anyNonManifold = topology.nonManifoldEdges > 0;
    const std::uint8_t borderBit = settings.borders ? kBorder : 0;
    const std::uint8_t nonManifoldBit = settings.creases ? kCrease : 0;
    const std::uint8_t silhouetteBit = settings.silhouettes ? kSilhouette : 0;
    const std::uint8_t creaseBit = settings.creases ? kCrease : 0;
    const std::uint8_t weakBit = settings.creases ? kWeakCrease : 0;
    // Branch-free append: every edge is written at the end of the scratch list and the end moves
    // on only for a feature edge (about 2 % of them), so no branch depends on the data.
    EdgeScratch& found = edgeScratch();
    if (found.size < ne) {
        found.edges.reset(new std::int32_t[ne]);
        found.kinds.reset(new std::uint8_t[ne]);
        found.size = ne;
    }
    std::int32_t* foundEdges = found.edges.get();
    std::uint8_t* foundKinds = found.kinds.get();
    std::size_t count = 0;
    for (std::size_t e = 0; e < ne; ++e) {
#if defined(__GNUC__)
        // rec[f0] and rec[f1] are the scattered reads of the loop; fetch them a few edges ahead.
        if (e + kPrefetchDistance < ne) {
            __builtin_prefetch(rec + edgeFaces[2 * (e + kPrefetchDistance)]);
            __builtin_prefetch(rec + std::max(edgeFaces[2 * (e + kPrefetchDistance) + 1], 0));
        }
#endif
        const std::int32_t f0 = edgeFaces[2 * e], f1 = edgeFaces[2 * e + 1];
        const bool open = f1 < 0;
        const std::int32_t other = open ? f0 : f1;
        const FaceRecord r0 = rec[f0], r1 = rec[other];
        // Both faces proper: product +-1; a silhouette: -1 (front and back).
        const std::int32_t facing = std::int32_t(r0.facing) * r1.facing;
        const std::int32_t dot = std::int32_t(r0.normal[0]) * r1.normal[0] + std::int32_t(r0.normal[1]) * r1.normal[1]
            + std::int32_t(r0.normal[2]) * r1.normal[2];
        // Crease: strong (dot below the crease angle's cosine), weak (below the low angle's:
        // hysteresis) or neither; degenerate faces make none.
        const std::uint8_t crease = dot < cosCreaseFixed ? creaseBit : (dot < cosLowFixed ? weakBit : 0);
        std::uint8_t kind = std::uint8_t((facing < 0 ? silhouetteBit : 0) | (facing != 0 ? crease : 0));
        if (useMaterials) // loop-invariant
            kind |= faceMaterials[std::size_t(f0)] != faceMaterials[std::size_t(other)] ? kMaterialBoundary : 0;
        // More than two faces: which two the topology kept is arbitrary, so front/back and
        // dihedral tests would be too. Such an edge is a geometric feature (fins, touching
        // parts), drawn as a crease.
        if (anyNonManifold) // loop-invariant
            kind = nonManifold[e] ? nonManifoldBit : kind;
        kind = open ? borderBit : kind;
        foundEdges[count] = std::int32_t(e);
        foundKinds[count] = kind;
        count += kind != 0 ? 1 : 0;
    }
    out.edges.assign(foundEdges, foundEdges + count);
    out.kinds.assign(foundKinds, foundKinds + count);
    if (hysteresis)
        linkWeakCreases(topology, std::int32_t(shape.rows()), out);
}

std::vector<Stroke> chainStrokes(const EdgeTopology& topology, const FeatureEdges& features)
{
    assert(features.edges.size() == features.kinds.size());
    const std::size_t n = features.edges.size();
    std::vector<Stroke> strokes;
    if (n == 0)
        return strokes;

    // Two classes never join: outlines (silhouette or border bits) and inner lines (the rest).
    auto classOf = [&](std::size_t i) { return (features.kinds[i] & kOutlineBits) ? 0 : 1; };
    auto endpoint = [&](std::size_t i, int k) { return topology.edges(features.edges[i], k); };
    std::int32_t nv = 0;
    for (std::size_t i = 0; i < n; ++i)
        nv = std::max(nv, endpoint(i, 1) + 1); // v0 < v1

    // Incidence lists per (vertex, class) slot, slot = 2 * vertex + class, in CSR form.
    std::vector<std::int32_t> slotStart(2 * std::size_t(nv) + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 2; ++k)
            ++slotStart[2 * std::size_t(endpoint(i, k)) + std::size_t(classOf(i)) + 1];
    for (std::size_t s = 0; s + 1 < slotStart.size(); ++s)
        slotStart[s + 1] += slotStart[s];
    std::vector<std::int32_t> incident(2 * n);
    {
        std::vector<std::int32_t> fill(slotStart.begin(), slotStart.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < 2; ++k)
                incident[std::size_t(fill[2 * std::size_t(endpoint(i, k)) + std::size_t(classOf(i))]++)]
                    = std::int32_t(i);
    }

    std::vector<char> visited(n, 0);
    // From vertex v, reached through feature edge `from`, the next edge of the same class when v
    // is a pass-through vertex (exactly two edges of that class), else -1.
    auto nextEdge = [&](std::int32_t v, std::size_t from) -> std::int64_t {
        const std::size_t slot = 2 * std::size_t(v) + std::size_t(classOf(from));
        if (slotStart[slot + 1] - slotStart[slot] != 2)
            return -1;
        const std::int32_t a = incident[std::size_t(slotStart[slot])];
        const std::int32_t b = incident[std::size_t(slotStart[slot]) + 1];
        return std::size_t(a) == from ? b : a;
    };
    auto otherEnd
        = [&](std::size_t i, std::int32_t v) { return endpoint(i, 0) == v ? endpoint(i, 1) : endpoint(i, 0); };

    // Feature edges come in ascending edge order, and each stroke starts from its first
    // unvisited edge: strokes are ordered by their smallest edge index, deterministically.
    std::vector<std::int32_t> backward;
    for (std::size_t start = 0; start < n; ++start) {
        if (visited[start])
            continue;
        visited[start] = 1;
        Stroke s;
        s.kinds = features.kinds[start];
        const std::int32_t v0 = endpoint(start, 0);
        s.vertices = {v0, endpoint(start, 1)};
        // Forward from v1.
        std::size_t at = start;
        std::int32_t v = s.vertices.back();
        for (;;) {
            const std::int64_t next = nextEdge(v, at);
            if (next < 0)
                break;
            if (std::size_t(next) == start) {
                s.closed = true; // back at v0 through the start edge's other neighbour
                break;
            }
            if (visited[std::size_t(next)])
                break;
            at = std::size_t(next);
            visited[at] = 1;
            s.kinds |= features.kinds[at];
            v = otherEnd(at, v);
            s.vertices.push_back(v);
        }
        if (s.closed) {
            s.vertices.pop_back(); // v0 is not repeated
        } else {
            // Backward from v0, then prepend.
            backward.clear();
            at = start;
            v = v0;
            for (;;) {
                const std::int64_t next = nextEdge(v, at);
                if (next < 0 || visited[std::size_t(next)])
                    break;
                at = std::size_t(next);
                visited[at] = 1;
                s.kinds |= features.kinds[at];
                v = otherEnd(at, v);
                backward.push_back(v);
            }
            s.vertices.insert(s.vertices.begin(), backward.rbegin(), backward.rend());
        }
        strokes.push_back(std::move(s));
    }
    return strokes;
}

std::vector<StyledStroke> styleProjectedStrokes(const std::vector<Stroke>& strokes,
    const std::vector<Eigen::Vector3f>& projected, const LineStyle& style, const std::vector<std::uint32_t>* noiseKeys)
{
    assert(!noiseKeys || noiseKeys->size() == projected.size());
    std::vector<StyledStroke> out;
    out.reserve(strokes.size());
    std::vector<std::int32_t> run;
    for (const Stroke& stroke : strokes) {
        const std::size_t m = stroke.vertices.size();
        if (m < 2)
            continue;
        auto visible = [&](std::size_t i) {
            const auto v = std::size_t(stroke.vertices[i]);
            assert(v < projected.size());
            return projected[v].z() > 0.0f;
        };
        std::size_t firstHidden = m;
        for (std::size_t i = 0; i < m && firstHidden == m; ++i)
            if (!visible(i))
                firstHidden = i;
        if (firstHidden == m) {
            styleRun(stroke.vertices, stroke.closed, stroke.kinds, projected, style, noiseKeys, out);
            continue;
        }
        // Points behind the camera split the stroke into open runs. A closed stroke is walked
        // from its first hidden point round to it again, so a run across the seam stays whole.
        const std::size_t count = stroke.closed ? m + 1 : m;
        const std::size_t begin = stroke.closed ? firstHidden : 0;
        run.clear();
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t i = (begin + k) % m;
            if (visible(i)) {
                run.push_back(stroke.vertices[i]);
            } else {
                styleRun(run, false, stroke.kinds, projected, style, noiseKeys, out);
                run.clear();
            }
        }
        styleRun(run, false, stroke.kinds, projected, style, noiseKeys, out);
    }
    return out;
}

} // namespace celform::algo
