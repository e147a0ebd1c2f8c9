// Linear light to 8-bit sRGB for pictures made every frame (the line overlay, the depth overlays):
// one table look-up instead of a power function per channel.
#pragma once

#include <cstdint>

namespace celform::views {

/// The 8-bit sRGB code of a linear value (clamped to [0, 1]; NaN gives 0), from a 16384-entry
/// table fine enough that every 8-bit value decoded to linear encodes back to itself (the
/// steepest step of the sRGB curve is 12.92, a sixth of a code value here).
std::uint8_t srgbByte(float linear);

} // namespace celform::views
