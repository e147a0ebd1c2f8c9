// The analysis G-buffer, segments and depth error (depth_analysis.h).
#include "celform/algorithms/depth_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

    // Depth error (4.4) of the picture.
    computeDepthError(out.depth, beauty, out);
}

} // namespace celform::algo
