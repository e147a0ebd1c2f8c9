// The exact table-driven sRGB quantiser (srgb_encode.h).
#include "celform/algorithms/srgb_encode.h"

#include "celform/algorithms/image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace celform::algo {
namespace {

constexpr int kBuckets = 4096; // a power of two: v * kBuckets is exact in float
/// The most codes a bucket spans, which encode() steps through without a branch.
constexpr int kMaxSteps = 2;

struct Tables {
    /// threshold[k]: the least float v in [0, 1] whose reference code is at least k (k >= 1);
    /// threshold[256] is above every value.
    std::array<float, 257> threshold{};
    /// The reference code at the start of each bucket [i, i + 1) / kBuckets, and at 1 itself.
    std::array<std::uint8_t, kBuckets + 1> bucket{};
};

float fromBits(std::uint32_t bits)
{
    float v = 0.f;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

std::uint32_t toBits(float v)
{
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

const Tables& tables()
{
    static const Tables t = [] {
        Tables made;
        // The reference is non-decreasing in v, and so in the bit pattern of a non-negative float:
        // each threshold is a binary search over the patterns of [0, 1].
        const std::uint32_t one = toBits(1.f);
        made.threshold[0] = 0.f;
        for (int k = 1; k <= 255; ++k) {
            std::uint32_t lo = 0, hi = one; // the code at hi (1.0) is 255 >= k
            while (lo < hi) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                if (srgbEncode8Reference(fromBits(mid)) >= k)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            made.threshold[std::size_t(k)] = fromBits(lo);
        }
        made.threshold[256] = 2.f;
        for (int i = 0; i <= kBuckets; ++i)
            made.bucket[std::size_t(i)] = srgbEncode8Reference(float(i) / float(kBuckets));
        // encode() passes at most kMaxSteps thresholds from a bucket's start: no bucket may hold
        // more (the steepest part of the curve, slope 12.92 at 0, puts 0.8 codes in a bucket).
        for (int i = 0; i < kBuckets; ++i) {
            const int first = made.bucket[std::size_t(i)], last = made.bucket[std::size_t(i) + 1];
            if (last - first > kMaxSteps)
                std::abort();
        }
        return made;
    }();
    return t;
}

/// round(255 * clamp(v, 0, 1)) as std::lround(c * 255.f) gives it, without the libm call: the
/// product is a float below 256, so adding one half in double is exact and truncation rounds half
/// away from zero. NaN gives 0.
std::uint8_t linear8(float v)
{
    const float c = v > 0.f ? std::min(v, 1.f) : 0.f; // NaN fails v > 0
    return static_cast<std::uint8_t>(double(c * 255.f) + 0.5);
}

/// The code of v: the bucket's code, then at most kMaxSteps thresholds passed within the bucket
/// (checked when the tables are made), taken without a branch on the data.
std::uint8_t encode(const Tables& t, float v)
{
    const float c = v > 0.f ? std::min(v, 1.f) : 0.f; // NaN fails v > 0
    std::uint32_t code = t.bucket[std::size_t(c * float(kBuckets))];
    for (int step = 0; step < kMaxSteps; ++step)
        code += c >= t.threshold[code + 1] ? 1u : 0u;
    return static_cast<std::uint8_t>(code);
}

} // namespace

std::uint8_t srgbEncode8Reference(float linear)
{
    const float c = std::clamp(linear, 0.f, 1.f);
    if (!(c == c))
        return 0;
    return static_cast<std::uint8_t>(std::lround(linearToSrgb(c) * 255.f));
}

std::uint8_t srgbEncode8(float linear)
{
    return encode(tables(), linear);
}

void quantise8(
    const float* in, std::uint8_t* out, std::size_t count, int channels, int colourChannels, bool encodeColour)
{
    const Tables& t = tables();
    const int colour = encodeColour ? std::clamp(colourChannels, 0, channels) : 0;
    const auto stride = std::size_t(channels);
    if (channels == 4 && colour == 3) {
        // Rendered frames (RGBA): fixed trip counts, so the compiler unrolls the pixel. A toon
        // frame is mostly runs of equal pixels (flat tones, the background): a pixel whose four
        // floats have the bits of the one before it takes that one's codes (the dragon frame at
        // 1920x1080: 9.3 -> 1.8 ms; random values, where no run forms, pay the comparison).
        const float* before = nullptr;
        for (std::size_t i = 0; i + 4 <= count; i += 4) {
            if (before && std::memcmp(before, in + i, 4 * sizeof(float)) == 0) {
                std::memcpy(out + i, out + i - 4, 4);
                continue;
            }
            out[i] = encode(t, in[i]);
            out[i + 1] = encode(t, in[i + 1]);
            out[i + 2] = encode(t, in[i + 2]);
            out[i + 3] = linear8(in[i + 3]);
            before = in + i;
        }
    } else {
        for (std::size_t i = 0; i + stride <= count; i += stride) {
            for (int c = 0; c < colour; ++c)
                out[i + std::size_t(c)] = encode(t, in[i + std::size_t(c)]);
            for (int c = colour; c < channels; ++c)
                out[i + std::size_t(c)] = linear8(in[i + std::size_t(c)]);
        }
    }
    for (std::size_t i = count - count % stride; i < count; ++i) // a trailing partial pixel
        out[i] = linear8(in[i]);
}

} // namespace celform::algo
