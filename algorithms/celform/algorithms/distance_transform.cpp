// Meijster et al. 2002 with the nearest feature carried along (distance_transform.h).
#include "celform/algorithms/distance_transform.h"

#include <cmath>
#include <cstddef>
#include <limits>

namespace celform::algo {

void nearestFeatureTransform(const std::uint8_t* feature, int width, int height, std::int32_t* nearest,
    std::uint32_t* distanceSquared, DistanceTransformScratch& scratch)
{
    if (width <= 0 || height <= 0)
        return;
    const std::size_t w = std::size_t(width);
    const std::size_t count = w * std::size_t(height);
    scratch.columnRow.resize(count);
    scratch.envelope.resize(w);
    scratch.starts.resize(w);
    std::int32_t* row = scratch.columnRow.data();

    // Phase 1, the columns (Meijster's g): the nearest feature above or at each pixel, then below
    // it. Walking whole rows at a time keeps the memory access sequential.
    for (std::size_t x = 0; x < w; ++x)
        row[x] = feature[x] ? 0 : -1;
    for (int y = 1; y < height; ++y) {
        const std::uint8_t* f = feature + std::size_t(y) * w;
        std::int32_t* r = row + std::size_t(y) * w;
        const std::int32_t* above = r - w;
        for (std::size_t x = 0; x < w; ++x)
            r[x] = f[x] ? y : above[x];
    }
    for (int y = height - 2; y >= 0; --y) {
        std::int32_t* r = row + std::size_t(y) * w;
        const std::int32_t* below = r + w;
        for (std::size_t x = 0; x < w; ++x) {
            // A feature below wins only when strictly nearer (ties keep the feature above).
            if (below[x] >= 0 && (r[x] < 0 || below[x] - y < y - r[x]))
                r[x] = below[x];
        }
    }

    // Phase 2, the rows: the lower envelope of the parabolas (x - u)^2 + g(u)^2 of the columns u
    // that have a feature, with Meijster's integer separator
    // Sep(i, u) = (u^2 - i^2 + g(u)^2 - g(i)^2) div (2 (u - i)).
    std::int32_t* s = scratch.envelope.data();
    std::int32_t* t = scratch.starts.data();
    for (int y = 0; y < height; ++y) {
        const std::int32_t* r = row + std::size_t(y) * w;
        std::int32_t* out = nearest + std::size_t(y) * w;
        auto g2 = [&](std::int64_t u) {
            const std::int64_t d = std::int64_t(y) - r[u];
            return d * d;
        };
        auto f = [&](std::int64_t x, std::int64_t u) { return (x - u) * (x - u) + g2(u); };
        int q = -1;
        for (int u = 0; u < width; ++u) {
            if (r[u] < 0)
                continue;
            while (q >= 0 && f(t[q], s[q]) > f(t[q], u))
                --q;
            if (q < 0) {
                q = 0;
                s[0] = u;
                t[0] = 0;
            } else {
                const std::int64_t i = s[q];
                const std::int64_t sep = (std::int64_t(u) * u - i * i + g2(u) - g2(i)) / (2 * (std::int64_t(u) - i));
                const std::int64_t start = 1 + sep;
                if (start < width) {
                    ++q;
                    s[q] = u;
                    t[q] = std::int32_t(start);
                }
            }
        }
        if (q < 0) {
            for (std::size_t x = 0; x < w; ++x)
                out[x] = -1;
            continue;
        }
        for (int x = width - 1; x >= 0; --x) {
            const std::int32_t u = s[q];
            out[x] = r[u] * width + u;
            if (distanceSquared)
                distanceSquared[std::size_t(y) * w + std::size_t(x)] = std::uint32_t(f(x, u));
            if (x == t[q])
                --q;
        }
    }
}

void distanceTransform(
    const std::uint8_t* feature, int width, int height, float* distance, DistanceTransformScratch& scratch)
{
    if (width <= 0 || height <= 0)
        return;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    scratch.nearest.resize(count);
    scratch.squared.resize(count);
    nearestFeatureTransform(feature, width, height, scratch.nearest.data(), scratch.squared.data(), scratch);
    for (std::size_t i = 0; i < count; ++i)
        distance[i]
            = scratch.nearest[i] < 0 ? std::numeric_limits<float>::infinity() : std::sqrt(float(scratch.squared[i]));
}

} // namespace celform::algo
