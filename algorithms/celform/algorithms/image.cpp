// The sRGB transfer curves (IEC 61966-2-1), applied when a linear-light image is written to or read
// from an 8-bit file.
#include "celform/algorithms/image.h"

#include <cmath>

namespace celform::algo {

// IEC 61966-2-1, section 5.2: linear segment below 0.0031308, then 1.055 * L^(1/2.4) - 0.055.
// Evaluated in double so the float result is the correctly rounded value of the exact curve.
float linearToSrgb(float linear)
{
    const double l = double(linear);
    if (!(l > 0.0031308)) // also NaN and negatives: the linear segment, no clamping here
        return float(12.92 * l);
    return float(1.055 * std::pow(l, 1.0 / 2.4) - 0.055);
}

// The exact inverse: linear segment up to 0.04045 (= 12.92 * 0.0031308 to four digits).
float srgbToLinear(float encoded)
{
    const double e = double(encoded);
    if (!(e > 0.04045))
        return float(e / 12.92);
    return float(std::pow((e + 0.055) / 1.055, 2.4));
}

} // namespace celform::algo
