// Snakes (paper 3, section 4.2.1): apparent-ridge segments merged at nearby ends through a spatial
// hash, walked into polylines, smoothed once and filtered by length.
#include "celform/algorithms/ridge_snakes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace celform::algo {
namespace {

std::uint64_t cellKey(std::int32_t cx, std::int32_t cy)
{
    return (std::uint64_t(std::uint32_t(cx)) << 32) | std::uint64_t(std::uint32_t(cy));
}

std::size_t hashSlot(std::uint64_t key, std::size_t mask)
{
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return std::size_t(key) & mask;
}

/// Open-addressing table from a screen cell to the first node in it (nodes in a cell are linked
/// through nodeNext). Sized once per call to at least twice the number of ends.
struct CellTable {
    std::vector<std::uint64_t>& keys;
    std::vector<std::int32_t>& first;
    std::size_t mask = 0;

    void reset(std::size_t ends)
    {
        std::size_t capacity = 16;
        while (capacity < 2 * ends)
            capacity *= 2;
        keys.assign(capacity, 0);
        first.assign(capacity, -1);
        mask = capacity - 1;
    }
    /// The slot of key (empty slots have first == -1).
    std::size_t find(std::uint64_t key) const
    {
        std::size_t s = hashSlot(key, mask);
        while (first[s] >= 0 && keys[s] != key)
            s = (s + 1) & mask;
        return s;
    }
};

} // namespace

void clusterSnakes(const RidgeSegments& segments, const RasterCamera& camera, const SnakeOptions& options,
    SnakeWorkspace& ws, RidgeSnakes& out)
{
    out.clear();
    const std::size_t ends = segments.points.size();
    if (ends < 2)
        return;
    const float h = std::max(options.joinPixels, 1e-3f);
    const float h2 = h * h;
    const std::size_t segmentCount = ends / 2;

    // 1. Ends to nodes by identity: the two faces of an edge put their line vertex on it at the
    // same point with the same key, so segments chain exactly where the ridge runs on. Merging by
    // screen distance here instead would collapse segments shorter than the tolerance (on a fine
    // mesh most are under a pixel long).
    ws.endpointNode.resize(ends);
    ws.nodePoint.clear();
    ws.nodeKey.clear();
    ws.nodeNext.clear();
    CellTable table{ws.cellKeys, ws.cellFirst};
    table.reset(ends);
    for (std::size_t i = 0; i < ends; ++i) {
        const Eigen::Vector3f& p = segments.points[i];
        const std::uint64_t key = segments.keys[i];
        const std::size_t slot = table.find(key);
        std::int32_t node = -1;
        for (std::int32_t k = ws.cellFirst[slot]; k >= 0; k = ws.nodeNext[std::size_t(k)])
            if (ws.nodePoint[std::size_t(k)] == p) {
                node = k;
                break;
            }
        if (node < 0) {
            node = std::int32_t(ws.nodePoint.size());
            ws.nodePoint.push_back(p);
            ws.nodeKey.push_back(segments.keys[i]);
            ws.nodeNext.push_back(ws.cellFirst[slot]);
            if (ws.cellFirst[slot] < 0)
                ws.cellKeys[slot] = key;
            ws.cellFirst[slot] = node;
        }
        ws.endpointNode[i] = node;
    }
    const std::size_t nodes = ws.nodePoint.size();

    // Connections: the segments (those with two distinct ends), components by union-find.
    ws.edgeA.clear();
    ws.edgeB.clear();
    ws.parent.resize(nodes);
    for (std::size_t n = 0; n < nodes; ++n)
        ws.parent[n] = std::int32_t(n);
    auto findRoot = [&](std::int32_t n) {
        while (ws.parent[std::size_t(n)] != n) {
            ws.parent[std::size_t(n)] = ws.parent[std::size_t(ws.parent[std::size_t(n)])];
            n = ws.parent[std::size_t(n)];
        }
        return n;
    };
    ws.degree.assign(nodes, 0);
    ws.componentSize.assign(nodes, 1);
    auto connect = [&](std::int32_t a, std::int32_t b) {
        ws.edgeA.push_back(a);
        ws.edgeB.push_back(b);
        ++ws.degree[std::size_t(a)];
        ++ws.degree[std::size_t(b)];
        const std::int32_t ra = findRoot(a), rb = findRoot(b);
        if (ra != rb) {
            ws.parent[std::size_t(rb)] = ra;
            ws.componentSize[std::size_t(ra)] += ws.componentSize[std::size_t(rb)];
        }
    };
    for (std::size_t s = 0; s < segmentCount; ++s) {
        const std::int32_t a = ws.endpointNode[2 * s], b = ws.endpointNode[2 * s + 1];
        if (a != b)
            connect(a, b);
    }

    // 2. Listing 4.4's joining, on the snakes' heads and tails (nodes with one segment): each
    // merges with the nearest free end within h pixels on screen, found through a spatial hash of h-wide
    // cells (the 3 x 3 cells around it), so the whole pass is linear. Joining a snake's head to its
    // own tail closes it, which the listing allows for snakes of three vertices or more.
    ws.screen.resize(nodes);
    ws.joined.assign(nodes, 0);
    ws.alias.resize(nodes);
    for (std::size_t n = 0; n < nodes; ++n)
        ws.alias[n] = std::int32_t(n);
    table.reset(nodes);
    ws.nodeNext.assign(nodes, -1);
    const ProjectionFrame projection(camera);
    for (std::size_t n = 0; n < nodes; ++n) {
        ws.screen[n] = Eigen::Vector2f(std::numeric_limits<float>::quiet_NaN(), 0.f);
        if (ws.degree[n] != 1)
            continue;
        const Eigen::Vector3d p = projection.project(ws.nodePoint[n].cast<double>());
        const Eigen::Vector2f sp(float(p.x()), float(p.y()));
        if (!(p.z() > 0.0) || !(std::abs(sp.x()) < 1e8f) || !(std::abs(sp.y()) < 1e8f))
            continue; // behind the camera or off to infinity: never joined
        ws.screen[n] = sp;
        const std::uint64_t key = cellKey(std::int32_t(std::floor(sp.x() / h)), std::int32_t(std::floor(sp.y() / h)));
        const std::size_t slot = table.find(key);
        if (ws.cellFirst[slot] < 0)
            ws.cellKeys[slot] = key;
        ws.nodeNext[n] = ws.cellFirst[slot];
        ws.cellFirst[slot] = std::int32_t(n);
    }
    for (std::size_t n = 0; n < nodes; ++n) {
        const Eigen::Vector2f sp = ws.screen[n];
        if (ws.degree[n] != 1 || ws.joined[n] || !std::isfinite(sp.x()))
            continue;
        const std::int32_t cx = std::int32_t(std::floor(sp.x() / h)), cy = std::int32_t(std::floor(sp.y() / h));
        const std::int32_t root = findRoot(std::int32_t(n));
        std::int32_t best = -1;
        float bestDistance = h2;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const std::size_t slot = table.find(cellKey(cx + dx, cy + dy));
                for (std::int32_t k = ws.cellFirst[slot]; k >= 0; k = ws.nodeNext[std::size_t(k)]) {
                    if (std::size_t(k) == n || ws.joined[std::size_t(k)])
                        continue;
                    if (findRoot(k) == root && ws.componentSize[std::size_t(root)] < 3)
                        continue;
                    const float d2 = (ws.screen[std::size_t(k)] - sp).squaredNorm();
                    if (d2 < bestDistance || (d2 == bestDistance && best >= 0 && k < best)) {
                        bestDistance = d2;
                        best = k;
                    }
                }
            }
        if (best >= 0) {
            // The two ends become one snake vertex, halfway between them.
            ws.joined[n] = ws.joined[std::size_t(best)] = 1;
            ws.alias[std::size_t(best)] = std::int32_t(n);
            ws.nodePoint[n] = 0.5f * (ws.nodePoint[n] + ws.nodePoint[std::size_t(best)]);
            const std::int32_t rb = findRoot(best);
            if (rb != root) {
                ws.parent[std::size_t(rb)] = root;
                ws.componentSize[std::size_t(root)] += ws.componentSize[std::size_t(rb)];
            }
        }
    }
    for (std::size_t e = 0; e < ws.edgeA.size(); ++e) {
        ws.edgeA[e] = ws.alias[std::size_t(ws.edgeA[e])];
        ws.edgeB[e] = ws.alias[std::size_t(ws.edgeB[e])];
    }

    // Adjacency in compressed rows over the segments between snake vertices.
    const std::size_t edges = ws.edgeA.size();
    ws.nodeStart.assign(nodes + 1, 0);
    for (std::size_t e = 0; e < edges; ++e) {
        if (ws.edgeA[e] == ws.edgeB[e])
            continue;
        ++ws.nodeStart[std::size_t(ws.edgeA[e]) + 1];
        ++ws.nodeStart[std::size_t(ws.edgeB[e]) + 1];
    }
    for (std::size_t n = 0; n < nodes; ++n)
        ws.nodeStart[n + 1] += ws.nodeStart[n];
    ws.adjacency.resize(std::size_t(ws.nodeStart[nodes]));
    ws.chain.assign(ws.nodeStart.begin(), ws.nodeStart.end() - 1); // fill cursor per node
    for (std::size_t e = 0; e < edges; ++e) {
        if (ws.edgeA[e] == ws.edgeB[e])
            continue;
        ws.adjacency[std::size_t(ws.chain[std::size_t(ws.edgeA[e])]++)] = std::int32_t(e);
        ws.adjacency[std::size_t(ws.chain[std::size_t(ws.edgeB[e])]++)] = std::int32_t(e);
    }
    auto degree = [&](std::int32_t n) { return ws.nodeStart[std::size_t(n) + 1] - ws.nodeStart[std::size_t(n)]; };
    auto other = [&](std::int32_t e, std::int32_t n) {
        const std::int32_t a = ws.edgeA[std::size_t(e)];
        return a == n ? ws.edgeB[std::size_t(e)] : a;
    };
    auto nextUnused = [&](std::int32_t n) -> std::int32_t {
        for (std::int32_t k = ws.nodeStart[std::size_t(n)]; k < ws.nodeStart[std::size_t(n) + 1]; ++k)
            if (!ws.edgeUsed[std::size_t(ws.adjacency[std::size_t(k)])])
                return ws.adjacency[std::size_t(k)];
        return -1;
    };
    ws.edgeUsed.assign(edges, 0);

    auto emit = [&](bool closed) {
        const std::size_t m = ws.chain.size();
        if (m < std::size_t(std::max(options.minVertices, 2)))
            return;
        Stroke stroke;
        stroke.kinds = kRidge;
        stroke.closed = closed;
        stroke.vertices.resize(m);
        const std::size_t base = out.points.size();
        for (std::size_t i = 0; i < m; ++i) {
            const auto n = std::size_t(ws.chain[i]);
            Eigen::Vector3f p = ws.nodePoint[n];
            // Paper 3, section 4.2.1: one Laplacian pass, each interior vertex to the mean of its
            // two neighbours before smoothing (every vertex of a closed snake is interior).
            if (options.smooth && (closed || (i > 0 && i + 1 < m)))
                p = 0.5f
                    * (ws.nodePoint[std::size_t(ws.chain[(i + m - 1) % m])]
                        + ws.nodePoint[std::size_t(ws.chain[(i + 1) % m])]);
            out.points.push_back(p);
            out.keys.push_back(ws.nodeKey[n]);
            stroke.vertices[i] = std::int32_t(base + i);
        }
        out.strokes.push_back(std::move(stroke));
    };

    // Walks from start along connection e through interior vertices (two connections) into
    // ws.chain; true when it comes back to start (a closed snake).
    auto walk = [&](std::int32_t start, std::int32_t e) {
        ws.chain.clear();
        ws.chain.push_back(start);
        std::int32_t node = start;
        while (e >= 0) {
            ws.edgeUsed[std::size_t(e)] = 1;
            node = other(e, node);
            if (node == start)
                return true;
            ws.chain.push_back(node);
            e = degree(node) == 2 ? nextUnused(node) : -1;
        }
        return false;
    };
    // 3. Snakes: from every node that is not a chain interior (a free end, or a junction of three
    // or more), along each unused connection; what is left after that are cycles of interior
    // nodes: closed snakes, out of the pool (listing 4.4).
    for (std::size_t n0 = 0; n0 < nodes; ++n0) {
        const auto start = std::int32_t(n0);
        if (degree(start) == 2 || degree(start) == 0)
            continue;
        for (std::int32_t e = nextUnused(start); e >= 0; e = nextUnused(start))
            emit(walk(start, e));
    }
    for (std::size_t n0 = 0; n0 < nodes; ++n0)
        if (const std::int32_t e = nextUnused(std::int32_t(n0)); e >= 0)
            emit(walk(std::int32_t(n0), e));
}

void computeRidgeShapeData(const Positions& shape, const Faces& faces, RidgeShapeData& out)
{
    computeCurvatures(shape, faces, out.curvatures);
    out.featureSize = ridgeFeatureSize(shape, faces);
}

void extractRidgeSnakes(const Positions& shape, const Faces& faces, const VertexFaces& around,
    const RidgeShapeData& data, const RasterCamera& lineCamera, float threshold, RidgeScratch& scratch,
    RidgeSnakes& out, const std::vector<float>* thresholdScale, const SnakeOptions& snakeOptions)
{
    LineView view;
    view.eye = lineCamera.eye.cast<float>();
    view.direction = lineCamera.forward().cast<float>();
    view.orthographic = lineCamera.orthographic;
    ApparentRidgeOptions options;
    options.threshold = threshold;
    options.featureSize = data.featureSize;
    options.thresholdScale = thresholdScale;
    computeApparentRidges(shape, faces, around, data.curvatures, view, options, scratch.ridges, scratch.segments);
    clusterSnakes(scratch.segments, lineCamera, snakeOptions, scratch.snakes, out);
}

} // namespace celform::algo
