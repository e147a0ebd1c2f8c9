// Hoshen-Kopelman connected-component labelling (segments.h).
#include "celform/algorithms/segments.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace celform::algo {
namespace {

/// The root of i's set (listing 4.6 "find"), halving the path on the way. Roots are the lowest
/// index of their set, as in the thesis, so the first pixel of a segment in the scan is its root.
std::int32_t findRoot(std::int32_t* parent, std::int32_t i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

/// Listing 4.6 "union": the higher root becomes a child of the lower one.
std::int32_t unite(std::int32_t* parent, std::int32_t a, std::int32_t b)
{
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a == b)
        return a;
    if (a < b) {
        parent[b] = a;
        return a;
    }
    parent[a] = b;
    return b;
}

} // namespace

void labelSegments(const std::uint8_t* covered, const float* curvature, const float* depth, int width, int height,
    float depthThreshold, int minPixels, SegmentLabels& out)
{
    out.width = std::max(width, 0);
    out.height = std::max(height, 0);
    const std::size_t w = std::size_t(out.width);
    const std::size_t count = w * std::size_t(out.height);
    out.labels.resize(count);
    out.scratch.resize(count);
    out.sizes.clear();
    std::int32_t* parent = out.scratch.data();
    constexpr std::int32_t kTransparent = -1;

    auto joins = [&](std::size_t i, std::size_t j) {
        return parent[j] != kTransparent && curvatureSign(curvature[i]) == curvatureSign(curvature[j])
            && std::abs(depth[i] - depth[j]) < depthThreshold;
    };

    // The scan of listing 4.7, with the diagonal neighbours above as well (thesis 4.5.3: "diagonal
    // neighbouring pixels are also considered"); pixels outside the image or transparent never join.
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            const std::size_t i = std::size_t(y) * w + std::size_t(x);
            if (!covered[i] || !std::isfinite(depth[i]) || !std::isfinite(curvature[i])) {
                parent[i] = kTransparent;
                continue;
            }
            std::int32_t root = -1;
            auto consider = [&](int nx, int ny) {
                if (nx < 0 || ny < 0 || nx >= out.width)
                    return;
                const std::size_t j = std::size_t(ny) * w + std::size_t(nx);
                if (!joins(i, j))
                    return;
                root = root < 0 ? findRoot(parent, std::int32_t(j)) : unite(parent, root, std::int32_t(j));
            };
            consider(x - 1, y);
            consider(x - 1, y - 1);
            consider(x, y - 1);
            consider(x + 1, y - 1);
            parent[i] = root < 0 ? std::int32_t(i) : root;
        }
    }

    // Sizes per root, counted in labels (free until the renumbering), then one pass in scan order:
    // a root comes before every other pixel of its set (it is the lowest index), so it gets its
    // compact number (or -1 when too small) first and the others copy it.
    std::int32_t* label = out.labels.data();
    for (std::size_t i = 0; i < count; ++i)
        label[i] = 0;
    for (std::size_t i = 0; i < count; ++i)
        if (parent[i] != kTransparent)
            ++label[findRoot(parent, std::int32_t(i))];
    for (std::size_t i = 0; i < count; ++i) {
        if (parent[i] == kTransparent) {
            label[i] = kTransparent;
        } else if (parent[i] == std::int32_t(i)) {
            if (label[i] >= minPixels) {
                out.sizes.push_back(label[i]);
                label[i] = std::int32_t(out.sizes.size()) - 1;
            } else {
                label[i] = kTransparent;
            }
        } else {
            label[i] = label[findRoot(parent, std::int32_t(i))];
        }
    }
}

} // namespace celform::algo
