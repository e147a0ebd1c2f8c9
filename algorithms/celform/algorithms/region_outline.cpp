// Outlines of pixel regions (region_outline.h): every edge between a pixel of the mask and one
// outside it, directed with the mask on its right (on screen, y down), chained into loops.
#include "celform/algorithms/region_outline.h"

#include <cstdint>
#include <unordered_map>

namespace celform::algo {
namespace {

struct Edge {
    Eigen::Vector2i from, to;
    bool used = false;
};

std::int64_t cornerKey(const Eigen::Vector2i& c, int width)
{
    return std::int64_t(c.y()) * std::int64_t(width + 1) + c.x();
}

/// Turning preference at a corner two loops touch at: the sharpest right turn first keeps
/// diagonal neighbours in separate loops.
int turnRank(const Eigen::Vector2i& in, const Eigen::Vector2i& out)
{
    const int cross = in.x() * out.y() - in.y() * out.x();
    const int dot = in.dot(out);
    if (cross > 0)
        return 0; // right turn on screen (y down)
    if (dot > 0)
        return 1; // straight on
    return 2; // left turn
}

} // namespace

std::vector<std::vector<Eigen::Vector2i>> traceRegionOutlines(const std::vector<char>& mask, int width, int height)
{
    std::vector<std::vector<Eigen::Vector2i>> loops;
    if (width <= 0 || height <= 0 || mask.size() != std::size_t(width) * std::size_t(height))
        return loops;
    auto inside = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < width && y < height
            && mask[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    };
    // Clockwise on screen around a pixel: top edge left to right, right edge down, bottom edge
    // right to left, left edge up; the pixel is on each edge's right.
    std::vector<Edge> edges;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!inside(x, y))
                continue;
            if (!inside(x, y - 1))
                edges.push_back({{x, y}, {x + 1, y}});
            if (!inside(x + 1, y))
                edges.push_back({{x + 1, y}, {x + 1, y + 1}});
            if (!inside(x, y + 1))
                edges.push_back({{x + 1, y + 1}, {x, y + 1}});
            if (!inside(x - 1, y))
                edges.push_back({{x, y + 1}, {x, y}});
        }
    std::unordered_multimap<std::int64_t, std::size_t> starting;
    starting.reserve(edges.size());
    for (std::size_t e = 0; e < edges.size(); ++e)
        starting.emplace(cornerKey(edges[e].from, width), e);
    for (std::size_t seed = 0; seed < edges.size(); ++seed) {
        if (edges[seed].used)
            continue;
        std::vector<Eigen::Vector2i> loop;
        std::size_t e = seed;
        Eigen::Vector2i lastDirection = Eigen::Vector2i::Zero();
        while (!edges[e].used) {
            edges[e].used = true;
            const Eigen::Vector2i direction = edges[e].to - edges[e].from;
            // A corner is kept only where the direction changes.
            if (direction != lastDirection)
                loop.push_back(edges[e].from);
            lastDirection = direction;
            // The next edge from this one's end: the sharpest right turn among the unused ones.
            const auto range = starting.equal_range(cornerKey(edges[e].to, width));
            std::size_t next = e;
            int best = 3;
            for (auto it = range.first; it != range.second; ++it) {
                const Edge& candidate = edges[it->second];
                if (candidate.used && it->second != seed)
                    continue;
                const int rank = turnRank(direction, candidate.to - candidate.from);
                if (rank < best) {
                    best = rank;
                    next = it->second;
                }
            }
            if (next == e)
                break;
            e = next;
        }
        // The seed's corner is dropped when the loop arrives at it straight on.
        if (loop.size() >= 3 && lastDirection == edges[seed].to - edges[seed].from)
            loop.erase(loop.begin());
        loops.push_back(std::move(loop));
    }
    return loops;
}

} // namespace celform::algo
