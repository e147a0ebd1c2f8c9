// Exact Euclidean distance transform that also tells which feature pixel is the nearest, for the
// depth-error metric of paper 3 (section 4.4.1): every pixel takes the depth of its nearest
// feature pixel. Meijster, Roerdink and Hesselink, "A general algorithm for computing distance
// transforms in linear time" (2002): a pass down the columns, then a pass along the rows that
// keeps the lower envelope of the columns' parabolas. Linear in the pixel count.
#pragma once

#include <cstdint>
#include <vector>

namespace celform::algo {

/// Working memory of nearestFeatureTransform, kept by the caller so that repeated calls (an
/// overlay following the camera) do not allocate.
struct DistanceTransformScratch {
    std::vector<std::int32_t> columnRow; ///< per pixel: row of the nearest feature in its column, -1 none
    std::vector<std::int32_t> envelope; ///< s: columns of the parabolas on the lower envelope
    std::vector<std::int32_t> starts; ///< t: where each parabola starts being the lowest
    std::vector<std::int32_t> nearest; ///< distanceTransform's nearest features
    std::vector<std::uint32_t> squared; ///< distanceTransform's squared distances
};

/// For a width x height mask (row-major, non-zero = feature pixel), writes for every pixel the
/// row-major index of its nearest feature pixel (Euclidean distance between pixel centres; -1 when
/// the image has no feature) and, when distanceSquared is not null, the squared distance to it
/// (0 on feature pixels, unchanged where the index is -1). Between equally near features the lower
/// column wins, within a column the upper row. nearest and distanceSquared hold width * height
/// entries.
void nearestFeatureTransform(const std::uint8_t* feature, int width, int height, std::int32_t* nearest,
    std::uint32_t* distanceSquared, DistanceTransformScratch& scratch);

/// The Euclidean distance (in pixels) of every pixel to the nearest feature pixel: +infinity
/// where there is none.
void distanceTransform(
    const std::uint8_t* feature, int width, int height, float* distance, DistanceTransformScratch& scratch);

} // namespace celform::algo
