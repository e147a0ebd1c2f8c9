// The analysis G-buffer, segments and depth error (depth_analysis.h).
#include "celform/algorithms/depth_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace celform::algo {
namespace {

/// Thesis 4.4: toon shading has no gradients, "it suffices to simply look for any difference in
/// RGB values between neighbouring pixels". Differences below this (linear light, far below one
/// 8-bit step) are rounding, not edges.
constexpr float kColourTolerance = 1.f / 4096.f;

bool differs(const float* a, const float* b)
{
    return std::abs(a[0] - b[0]) > kColourTolerance || std::abs(a[1] - b[1]) > kColourTolerance
        || std::abs(a[2] - b[2]) > kColourTolerance;
}

template <class T> void resizeTo(std::vector<T>& v, std::size_t n, const T& value)
{
    v.resize(n);
    std::fill(v.begin(), v.end(), value);
}

} // namespace

Eigen::Vector3f shadingLightDerivative(const Eigen::Vector3f& l, const Eigen::Vector3f& n)
{
    const float ll = l.squaredNorm();
    if (!(ll > 0.f))
        return Eigen::Vector3f::Zero();
    return (-(l.dot(n)) / ll * l + n) / std::sqrt(ll);
}

void computeDepthError(const std::vector<float>& depth, const ImageRGBA& beauty, DepthAnalysis& out)
{
    const int w = beauty.width, h = beauty.height;
    const std::size_t count = std::size_t(w) * std::size_t(h);
    out.width = w;
    out.height = h;
    resizeTo(out.feature, count, std::uint8_t(0));
    resizeTo(out.depthError, count, 0.f);
    out.nearestFeature.resize(count);
    out.modelPixels = 0;
    out.featurePixels = 0;
    out.meanSquaredError = 0.0;
    out.maxAbsError = 0.0;
    if (count == 0 || depth.size() != count)
        return;

    // Feature pixels (4.4): model pixels whose colour differs from the left or the right pixel.
    // Only horizontal changes give disparities, the eyes being side by side.
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (!std::isfinite(depth[i]))
                continue;
            ++out.modelPixels;
            const float* p = beauty.at(x, y);
            const bool edge = (x > 0 && differs(p, p - 4)) || (x + 1 < w && differs(p, p + 4));
            if (edge) {
                out.feature[i] = 1;
                ++out.featurePixels;
            }
        }
    }
    if (out.featurePixels == 0)
        return;

    // Perceived depth: the depth of the nearest feature pixel (4.4.1, Meijster's transform with the
    // nearest feature carried along instead of the thesis's quadratic row pass).
    nearestFeatureTransform(out.feature.data(), w, h, out.nearestFeature.data(), nullptr, out.scratch);
    double sum = 0.0;
    double maxAbs = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!std::isfinite(depth[i])) {
            out.nearestFeature[i] = -1;
            continue;
        }
        const float error = depth[std::size_t(out.nearestFeature[i])] - depth[i];
        out.depthError[i] = error;
        sum += double(error) * double(error);
        maxAbs = std::max(maxAbs, double(std::abs(error)));
    }
    out.meanSquaredError = sum / double(out.modelPixels);
    out.maxAbsError = maxAbs;
}

void faceSegmentVote(
    const SegmentLabels& labels, const std::int32_t* faceId, std::int32_t faceCount, std::vector<std::int32_t>& owner)
{
    owner.assign(std::size_t(std::max(0, faceCount)), -1);
    const std::size_t count = labels.labels.size();
    if (!faceId || faceCount <= 0 || count == 0)
        return;
    // A counting sort of the segment pixels by face (O(pixels + faces)), then each face's most
    // frequent segment among its own pixels (nearly always a single one).
    std::vector<std::int32_t> start(std::size_t(faceCount) + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
        if (labels.labels[i] >= 0 && faceId[i] >= 0 && faceId[i] < faceCount)
            ++start[std::size_t(faceId[i]) + 1];
    for (std::size_t f = 0; f < std::size_t(faceCount); ++f)
        start[f + 1] += start[f];
    std::vector<std::int32_t> bySegment(std::size_t(start.back()));
    std::vector<std::int32_t> cursor(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < count; ++i)
        if (labels.labels[i] >= 0 && faceId[i] >= 0 && faceId[i] < faceCount)
            bySegment[std::size_t(cursor[std::size_t(faceId[i])]++)] = labels.labels[i];
    for (std::size_t f = 0; f < std::size_t(faceCount); ++f) {
        const auto begin = bySegment.begin() + start[f], end = bySegment.begin() + start[f + 1];
        if (begin == end)
            continue;
        std::sort(begin, end);
        std::int32_t best = *begin, bestRun = 0;
        for (auto it = begin; it != end;) {
            const auto next = std::upper_bound(it, end, *it);
            if (next - it > bestRun) {
                bestRun = std::int32_t(next - it);
                best = *it;
            }
            it = next;
        }
        owner[f] = best;
    }
}

void segmentFaceMeans(const SegmentLabels& labels, const std::int32_t* faceId, const std::vector<std::int32_t>& owner,
    const std::vector<float>& perFace, std::vector<float>& out)
{
    const std::size_t segments = labels.sizes.size();
    auto value = [&](std::int32_t f) {
        return f >= 0 && std::size_t(f) < perFace.size() ? double(perFace[std::size_t(f)]) : 1.0;
    };
    std::vector<double> sum(segments, 0.0);
    std::vector<std::int64_t> faces(segments, 0);
    for (std::size_t f = 0; f < owner.size(); ++f)
        if (owner[f] >= 0 && std::size_t(owner[f]) < segments) {
            sum[std::size_t(owner[f])] += value(std::int32_t(f));
            ++faces[std::size_t(owner[f])];
        }
    // Segments that won no face's vote (slivers over faces mostly elsewhere): their pixels' faces.
    std::vector<double> pixelSum(segments, 0.0);
    std::vector<std::int64_t> pixels(segments, 0);
    bool slivers = false;
    for (std::size_t s = 0; s < segments; ++s)
        slivers = slivers || faces[s] == 0;
    if (slivers && faceId)
        for (std::size_t i = 0; i < labels.labels.size(); ++i) {
            const std::int32_t s = labels.labels[i];
            if (s >= 0 && std::size_t(s) < segments && faces[std::size_t(s)] == 0) {
                pixelSum[std::size_t(s)] += value(faceId[i]);
                ++pixels[std::size_t(s)];
            }
        }
    out.assign(segments, 1.f);
    for (std::size_t s = 0; s < segments; ++s) {
        if (faces[s] > 0)
            out[s] = float(sum[s] / double(faces[s]));
        else if (pixels[s] > 0)
            out[s] = float(pixelSum[s] / double(pixels[s]));
    }
}

void applySegmentOverrides(
    const std::int32_t* faceId, const std::vector<std::int32_t>& overrides, int minPixels, SegmentLabels& labels)
{
    const std::size_t count = labels.labels.size();
    if (!faceId || overrides.empty() || count == 0)
        return;
    const std::int32_t scanned = std::int32_t(labels.sizes.size());
    // Provisional numbers: the scan's segments keep theirs, each override label gets one after
    // them (in the order its first pixel comes).
    std::unordered_map<std::int32_t, std::int32_t> byLabel;
    std::vector<std::int32_t>& provisional = labels.scratch;
    provisional.assign(count, -1);
    bool any = false;
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t f = faceId[i];
        const std::int32_t label = f >= 0 && std::size_t(f) < overrides.size() ? overrides[std::size_t(f)] : -1;
        if (label >= 0) {
            const auto it = byLabel.emplace(label, scanned + std::int32_t(byLabel.size())).first;
            provisional[i] = it->second;
            any = true;
        } else {
            provisional[i] = labels.labels[i];
        }
    }
    if (!any)
        return;
    // A scan segment that lost most of its pixels to overrides goes with them whole: its rest
    // (pixels on faces whose vote went to a neighbour, which carry no label of their own) joins
    // the override next to it, grown over the segment's own pixels; a rest out of reach joins the
    // override that took most of it. A merge leaves no sliver of its segments behind.
    std::vector<std::int64_t> kept(std::size_t(scanned), std::int64_t(0));
    std::vector<std::unordered_map<std::int32_t, std::int64_t>> moved;
    moved.resize(std::size_t(scanned));
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t s = labels.labels[i];
        if (s < 0)
            continue;
        if (provisional[i] == s)
            ++kept[std::size_t(s)];
        else
            ++moved[std::size_t(s)][provisional[i]];
    }
    std::vector<std::int32_t> heir(std::size_t(scanned), -1);
    for (std::size_t s = 0; s < heir.size(); ++s) {
        std::int64_t total = 0, most = 0;
        for (const auto& [to, n] : moved[s]) {
            total += n;
            if (n > most || (n == most && to < heir[s])) {
                most = n;
                heir[s] = to;
            }
        }
        if (total <= kept[s])
            heir[s] = -1;
    }
    std::vector<std::size_t> queue;
    for (std::size_t i = 0; i < count; ++i)
        if (labels.labels[i] >= 0 && provisional[i] >= scanned && heir[std::size_t(labels.labels[i])] >= 0)
            queue.push_back(i);
    const int w = labels.width, h = labels.height;
    for (std::size_t q = 0; q < queue.size() && std::size_t(w) * std::size_t(h) == count; ++q) {
        const std::size_t i = queue[q];
        const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h)
                    continue;
                const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                if (labels.labels[j] == labels.labels[i] && provisional[j] == labels.labels[j]) {
                    provisional[j] = provisional[i];
                    queue.push_back(j);
                }
            }
    }
    for (std::size_t i = 0; i < count; ++i)
        if (labels.labels[i] >= 0 && provisional[i] == labels.labels[i] && heir[std::size_t(labels.labels[i])] >= 0)
            provisional[i] = heir[std::size_t(labels.labels[i])];
    // Sizes, then numbers in the order of the first pixel, the small dropped (thesis 4.5.3).
    std::vector<std::int32_t> sizes(std::size_t(scanned) + byLabel.size(), 0);
    for (std::size_t i = 0; i < count; ++i)
        if (provisional[i] >= 0)
            ++sizes[std::size_t(provisional[i])];
    std::vector<std::int32_t> number(sizes.size(), -1);
    labels.sizes.clear();
    for (std::size_t i = 0; i < count; ++i) {
        const std::int32_t p = provisional[i];
        if (p < 0 || sizes[std::size_t(p)] < minPixels) {
            labels.labels[i] = -1;
            continue;
        }
        if (number[std::size_t(p)] < 0) {
            number[std::size_t(p)] = std::int32_t(labels.sizes.size());
            labels.sizes.push_back(sizes[std::size_t(p)]);
        }
        labels.labels[i] = number[std::size_t(p)];
    }
}

int segmentsInWindow(const std::vector<SegmentStats>& stats)
{
    int n = 0;
    for (const SegmentStats& s : stats)
        n += s.inWindow ? 1 : 0;
    return n;
}

void analyseDepth(const GBuffer& g, const std::vector<Eigen::Vector3f>& normals, const ImageRGBA& beauty,
    const Faces& faces, const std::vector<float>& vertexCurvature, const DepthAnalysisSettings& settings,
    DepthAnalysis& out)
{
    const int w = g.width, h = g.height;
    const std::size_t count = std::size_t(w) * std::size_t(h);
    out.width = w;
    out.height = h;
    resizeTo(out.curvature, count, 0.f);
    resizeTo(out.lambert, count, 0.f);
    resizeTo(out.lightGradient, count, Eigen::Vector3f(Eigen::Vector3f::Zero()));
    const bool sized = normals.size() == count && g.faceId.size() == count && g.depth.size() == count
        && beauty.width == w && beauty.height == h;
    if (sized)
        out.depth = g.depth;
    else
        resizeTo(out.depth, count, std::numeric_limits<float>::infinity());
    auto vertexValue = [](const std::vector<float>* values, std::int32_t v) {
        return values && std::size_t(v) < values->size() ? (*values)[std::size_t(v)] : 0.f;
    };

    // The analysis G-buffer (4.5.2): curvature interpolated from the vertices, N.L with the
    // painted offset (eq. 4.3), and the shading's derivative with respect to the light (eq. 4.2).
    std::vector<std::uint8_t>& covered = out.feature; // borrowed until the depth error refills it
    resizeTo(covered, count, std::uint8_t(0));
    if (sized) {
        for (std::size_t i = 0; i < count; ++i) {
            const std::int32_t f = g.faceId[i];
            if (f < 0 || f >= faces.rows())
                continue;
            covered[i] = 1;
            const Eigen::Vector3f b = g.barycentric[i];
            const std::int32_t a = faces(f, 0), c1 = faces(f, 1), c2 = faces(f, 2);
            out.curvature[i] = b.x() * vertexValue(&vertexCurvature, a) + b.y() * vertexValue(&vertexCurvature, c1)
                + b.z() * vertexValue(&vertexCurvature, c2);
            const Eigen::Vector3f& n = normals[i];
            const Eigen::Vector3f l = settings.pointLight ? Eigen::Vector3f(settings.light - g.position[i])
                                                          : Eigen::Vector3f(settings.light);
            const float ln = l.norm();
            const float offset = b.x() * vertexValue(settings.shadingOffsets, a)
                + b.y() * vertexValue(settings.shadingOffsets, c1) + b.z() * vertexValue(settings.shadingOffsets, c2);
            out.lambert[i] = (ln > 0.f ? n.dot(l) / ln : 0.f) + offset;
            out.lightGradient[i] = shadingLightDerivative(l, n);
        }
    }

    // Segments (4.1.3) and their bright/dark ratios under the look.
    labelSegments(covered.data(), out.curvature.data(), out.depth.data(), w, h, settings.depthThreshold,
        settings.minSegmentPixels, out.segments);
    // The segment brush's merges and splits (issue 26), by the faces' override labels.
    if (sized && settings.segmentOverrides && !settings.segmentOverrides->empty())
        applySegmentOverrides(g.faceId.data(), *settings.segmentOverrides, settings.minSegmentPixels, out.segments);
    out.stats.assign(out.segments.sizes.size(), SegmentStats{});
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const std::int32_t s = out.segments.labels[i];
            if (s < 0)
                continue;
            SegmentStats& st = out.stats[std::size_t(s)];
            ++st.pixels;
            if (out.lambert[i] >= settings.toonThreshold)
                ++st.bright;
            st.meanCurvature += out.curvature[i];
            st.lightGradient += out.lightGradient[i].cast<double>();
            st.centroid += Eigen::Vector2f(float(x) + 0.5f, float(y) + 0.5f);
        }
    }
    for (SegmentStats& st : out.stats) {
        if (st.pixels == 0)
            continue;
        st.ratio = float(st.bright) / float(st.pixels);
        st.inWindow = settings.window.contains(st.ratio);
        st.meanCurvature /= float(st.pixels);
        st.centroid /= float(st.pixels);
    }
    // Focal points (paper 3, 6.2): each segment's importance, the mean over its faces by the vote.
    if (sized && settings.faceImportance && !settings.faceImportance->empty()) {
        std::vector<std::int32_t> owner;
        std::vector<float> means;
        faceSegmentVote(out.segments, g.faceId.data(), std::int32_t(faces.rows()), owner);
        segmentFaceMeans(out.segments, g.faceId.data(), owner, *settings.faceImportance, means);
        for (std::size_t s = 0; s < out.stats.size() && s < means.size(); ++s)
            out.stats[s].importance = means[s];
    }

    // Depth error (4.4) of the picture.
    computeDepthError(out.depth, beauty, out);
}

} // namespace celform::algo
