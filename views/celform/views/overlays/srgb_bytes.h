// Linear light to 8-bit sRGB for pictures made every frame (the line overlay, the depth overlays):
// one table look-up instead of a power function per channel.
#pragma once

#include <cstdint>

namespace celform::views {

/// The 8-bit sRGB code of a linear value (clamped to [0, 1]; NaN gives 0): algo::srgbEncode8, the
/// code the offline renderer writes, from a table.
std::uint8_t srgbByte(float linear);

} // namespace celform::views
