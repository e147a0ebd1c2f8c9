// Visible runs of styled strokes (stroke_visibility.h).
#include "celform/algorithms/stroke_visibility.h"

#include <algorithm>
#include <cmath>

namespace celform::algo {
namespace {

/// drawStrokes's depth test (raster.cpp, drawSegment) at the pixel under p.
bool visibleAt(const Eigen::Vector2f& p, float d, const std::vector<float>& depth,
    const std::vector<std::int32_t>& faceId, int width, int height, float depthBias)
{
    constexpr float kDepthEpsilon = 1e-6f;
    if (!(p.x() >= 0.f && p.y() >= 0.f && p.x() < float(width) && p.y() < float(height)))
        return true;
    const std::size_t i = std::size_t(int(p.y())) * std::size_t(width) + std::size_t(int(p.x()));
    if (faceId[i] < 0)
        return true;
    return d <= depth[i] * (1.f + depthBias) + kDepthEpsilon;
}

/// A point of a stroke: position, depth and width.
struct Sample {
    Eigen::Vector2f p;
    float depth = 0.f, width = 0.f;
};

Sample lerp(const Sample& a, const Sample& b, float t)
{
    return {a.p + t * (b.p - a.p), a.depth + t * (b.depth - a.depth), a.width + t * (b.width - a.width)};
}

void append(StyledStroke& s, const Sample& x)
{
    s.points.push_back(x.p);
    s.depths.push_back(x.depth);
    s.widths.push_back(x.width);
}

/// The pass hides a line's pixels one by one, so where a stroke runs along a surface nearer
/// than itself on one side (the inside of a silhouette on a rounded body) only its other side
/// shows. Each point keeps, on each side, the largest of 1, 3/4, 1/2, 1/4 or none of its half
/// width whose edge passes the test; the point moves to the middle of what is kept.
void trimHiddenSides(StyledStroke& s, const std::vector<float>& depth, const std::vector<std::int32_t>& faceId,
    int width, int height, float depthBias)
{
    const std::size_t n = s.points.size();
    if (n < 2)
        return;
    const std::vector<Eigen::Vector2f> centre = s.points;
    for (std::size_t k = 0; k < n; ++k) {
        const Eigen::Vector2f along = centre[std::min(k + 1, n - 1)] - centre[k == 0 ? 0 : k - 1];
        const float length = along.norm();
        if (!(length > 0.f))
            continue;
        const Eigen::Vector2f normal(along.y() / length, -along.x() / length);
        const float half = 0.5f * s.widths[k];
        float kept[2] = {0.f, 0.f};
        for (int side = 0; side < 2; ++side) {
            const Eigen::Vector2f dir = side == 0 ? normal : Eigen::Vector2f(-normal);
            for (const float f : {1.f, 0.75f, 0.5f, 0.25f})
                if (visibleAt(centre[k] + f * half * dir, s.depths[k], depth, faceId, width, height, depthBias)) {
                    kept[side] = f * half;
                    break;
                }
        }
        s.points[k] = centre[k] + 0.5f * (kept[0] - kept[1]) * normal;
        s.widths[k] = kept[0] + kept[1];
    }
}

} // namespace

std::vector<StyledStroke> visibleStrokeParts(const std::vector<StyledStroke>& strokes, const std::vector<float>& depth,
    const std::vector<std::int32_t>& faceId, int width, int height, float depthBias)
{
    std::vector<StyledStroke> out;
    if (width <= 0 || height <= 0 || depth.size() != std::size_t(width) * std::size_t(height)
        || faceId.size() != depth.size())
        return out;
    for (const StyledStroke& stroke : strokes) {
        const std::size_t n = stroke.points.size();
        if (n == 0 || stroke.depths.size() != n || stroke.widths.size() != n)
            continue;
        auto sampleAt = [&](std::size_t k) { return Sample{stroke.points[k], stroke.depths[k], stroke.widths[k]}; };
        StyledStroke run;
        run.kinds = stroke.kinds;
        const std::size_t first = out.size();
        bool cut = false;
        auto finishRun = [&]() {
            if (!run.points.empty())
                out.push_back(std::move(run));
            run = StyledStroke{};
            run.kinds = stroke.kinds;
        };
        Sample previous = sampleAt(0);
        bool wasVisible = visibleAt(previous.p, previous.depth, depth, faceId, width, height, depthBias);
        if (wasVisible)
            append(run, previous);
        for (std::size_t k = 0; k + 1 < n; ++k) {
            const Sample a = sampleAt(k), b = sampleAt(k + 1);
            const int steps = std::max(1, int(std::ceil(2.f * (b.p - a.p).norm())));
            for (int s = 1; s <= steps; ++s) {
                const Sample x = lerp(a, b, float(s) / float(steps));
                const bool visible = visibleAt(x.p, x.depth, depth, faceId, width, height, depthBias);
                if (visible != wasVisible) {
                    cut = true;
                    const Sample middle = lerp(previous, x, 0.5f);
                    if (wasVisible) {
                        append(run, middle);
                        finishRun();
                    } else {
                        append(run, middle);
                    }
                }
                // The stroke's own points are kept; the samples between them only test.
                if (visible && s == steps)
                    append(run, x);
                previous = x;
                wasVisible = visible;
            }
        }
        finishRun();
        if (n == 1 || out.size() == first)
            continue;
        if (stroke.closed && !cut) {
            out.back().closed = true;
        } else if (stroke.closed && cut && out.size() - first >= 2 && out[first].points.front() == stroke.points.front()
            && out.back().points.back() == stroke.points.back()) {
            // A closed stroke cut somewhere: its last run continues into its first.
            StyledStroke& last = out.back();
            const StyledStroke& head = out[first];
            last.points.insert(last.points.end(), head.points.begin() + 1, head.points.end());
            last.depths.insert(last.depths.end(), head.depths.begin() + 1, head.depths.end());
            last.widths.insert(last.widths.end(), head.widths.begin() + 1, head.widths.end());
            out[first] = std::move(last);
            out.pop_back();
        }
    }
    for (StyledStroke& s : out)
        trimHiddenSides(s, depth, faceId, width, height, depthBias);
    return out;
}

} // namespace celform::algo
