// Linear light to 8-bit sRGB codes without a power function per channel (issue 29: std::pow per
// channel per pixel was 13 % of a shot's render time). The result is exactly the code of the
// reference quantisation, lround(255 * linearToSrgb(clamp(v, 0, 1))) in float, for every float:
// the 255 thresholds where the code steps up are found once, and a 4096-bucket table gives the
// code at each bucket's start, from which at most a step or two of comparisons remain.
#pragma once

#include <cstddef>
#include <cstdint>

namespace celform::algo {

/// The 8-bit sRGB code of a linear value; values are clamped to [0, 1] and NaN gives 0.
[[nodiscard]] std::uint8_t srgbEncode8(float linear);

/// The same code by the reference formula (a power function): what srgbEncode8 must equal.
[[nodiscard]] std::uint8_t srgbEncode8Reference(float linear);

/// Quantises count interleaved channels of channels per pixel to 8 bits: the first colourChannels
/// of each pixel are sRGB-encoded (when encode), the others (alpha, data) are scaled linearly with
/// the same rounding. out holds count bytes.
void quantise8(const float* in, std::uint8_t* out, std::size_t count, int channels, int colourChannels, bool encode);

} // namespace celform::algo
