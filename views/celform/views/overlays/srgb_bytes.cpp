// The sRGB encoding table (srgb_bytes.h).
#include "celform/views/overlays/srgb_bytes.h"

#include "celform/algorithms/image.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace celform::views {
namespace {

constexpr int kEncodeTableSize = 16384;

const std::vector<std::uint8_t>& encodeTable()
{
    static const std::vector<std::uint8_t> table = [] {
        std::vector<std::uint8_t> t(kEncodeTableSize);
        for (int i = 0; i < kEncodeTableSize; ++i) {
            const float v = algo::linearToSrgb(float(i) / float(kEncodeTableSize - 1));
            t[std::size_t(i)] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.f, 1.f) * 255.f));
        }
        return t;
    }();
    return table;
}

} // namespace

std::uint8_t srgbByte(float linear)
{
    const float clamped = std::clamp(linear, 0.f, 1.f);
    if (!(clamped == clamped))
        return 0;
    return encodeTable()[std::size_t(std::lround(clamped * float(kEncodeTableSize - 1)))];
}

} // namespace celform::views
