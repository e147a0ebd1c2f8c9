// Segmentation of the analysis G-buffer into parts of salient shape (paper 3, sections 4.1.3 and
// 4.5.3): connected components of pixels whose Gaussian curvature has the same sign and whose
// depths are close, by the Hoshen-Kopelman scan with a union-find (listings 4.6 and 4.7), over
// 8-connected neighbours. Small components are dropped as noise.
#pragma once

#include <cstdint>
#include <vector>

namespace celform::algo {

/// Thesis 4.5.3: "segments with a size under a threshold of 64 pixels will be deleted".
constexpr int kMinSegmentPixels = 64;

/// The sign class of a Gaussian curvature value: +1 positive, -1 negative, 0 exactly flat.
inline std::int8_t curvatureSign(float k)
{
    return k > 0.f ? std::int8_t(1) : (k < 0.f ? std::int8_t(-1) : std::int8_t(0));
}

struct SegmentLabels {
    int width = 0;
    int height = 0;
    /// Per pixel, row-major from the top-left: the segment, 0 .. sizes.size() - 1, or -1 where the
    /// pixel is transparent (off the model, or in a dropped component).
    std::vector<std::int32_t> labels;
    /// Pixels per segment. Segments are numbered in the order their first pixel comes in the scan.
    std::vector<std::int32_t> sizes;
    /// Working memory (the union-find's parents), kept so that repeated calls do not allocate.
    std::vector<std::int32_t> scratch;
};

/// Labels the covered pixels (covered[i] non-zero) of a width x height buffer. Two neighbours
/// (left, upper-left, up, upper-right and, by symmetry, the rest) join when their curvatures have
/// the same sign (curvatureSign) and |depth difference| < depthThreshold. Components smaller than
/// minPixels become transparent; the rest are renumbered 0..k-1 (thesis: "each label is renamed to
/// the lowest number that is not yet used").
void labelSegments(const std::uint8_t* covered, const float* curvature, const float* depth, int width, int height,
    float depthThreshold, int minPixels, SegmentLabels& out);

} // namespace celform::algo
