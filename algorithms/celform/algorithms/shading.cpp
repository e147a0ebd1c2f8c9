// Cartoon shading for the offline renderer. resources/shaders/celform_shading.glsl mirrors every
// function here line for line (same order of operations, same constants) so the viewport and the
// offline renderer produce the same pictures: change both files together.
//
// Semantics (the contract tests and the viewport rely on):
// - Toon tone (paper 3, section 3.3; equation 4.3 gives s = N.L + offset): the number of
//   thresholds t with s >= t, so a value exactly at a threshold takes the brighter tone, clamped
//   to [0, tones - 1]. NaN counts no threshold (darkest tone).
// - 32-entry table (comic paper, "Shading"): entry i is the ramp at the centre of the i-th of 32
//   equal steps of [-1, 1]; a look-up clamps s to [-1, 1] (NaN to -1) and reads
//   min(31, floor((s + 1) * 16)), so s = 1 reads the last entry.
// - Gooch-like shading (paper 1, section 3.2.4): see goochShade.
// - Hatching (comic paper, "Shading": "single lines for light shadow, double-crossed lines for
//   darker shadow"): see hatchCoverage.
#include "celform/algorithms/shading.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace celform::algo {

namespace {

constexpr float kDegToRad = 0.0174532925f; // pi / 180; the viewport passes cfHatchAngle in radians
constexpr float kHalfPi = 1.57079633f; // the cross-hatching set is at angle + 90 degrees
constexpr int kLutSize = 32;
/// Below this edge ramp width (in units of the spacing) the stripes get hard edges: the box
/// filter would divide by almost nothing.
constexpr float kMinRamp = 1e-4f;

/// Antiderivative of the pulse train "1 where frac(y) < width": the ink along a stripe
/// coordinate from 0 to y.
float pulseIntegral(float y, float width)
{
    const float cell = std::floor(y);
    return cell * width + std::min(y - cell, width);
}

/// Coverage of one set of parallel stripes at tri-planar coordinates (u, v), strokes running
/// along angle (radians). Stripes are centred on integer multiples of the spacing across the
/// strokes, width (fraction of the spacing) wide.
float stripeCoverage(float u, float v, float angle, float spacing, float width, float footprint)
{
    // Coordinate across the strokes, in units of the spacing: strokes run along (cos a, sin a).
    const float c = -u * std::sin(angle) + v * std::cos(angle);
    const float s = c / spacing;
    // Width of the pixel footprint in units of the spacing.
    const float a = footprint / spacing;
    // Past the Nyquist limit (a > 1/2: fewer than two pixels per stroke period) fade to the
    // average coverage, fully at a >= 1, so distant hatching becomes flat grey, not moire.
    const float fade = std::clamp(2.0f * a - 1.0f, 0.0f, 1.0f);
    if (fade >= 1.0f)
        return width;
    if (!(a >= kMinRamp)) {
        // Hard edge: ink where the distance to the nearest stroke centre is below width / 2.
        const float dist = std::abs(s - std::floor(s + 0.5f));
        return dist < 0.5f * width ? 1.0f : 0.0f;
    }
    // Box filter of the pulse train over the footprint: a linear ramp of width a across each
    // stroke edge (exact while a <= min(width, 1 - width)), and the exact mean for wider boxes.
    // x0 is reduced to [0, 1) first so the difference of integrals keeps float precision.
    const float x = s + 0.5f * width;
    const float x0 = x - std::floor(x);
    const float h = 0.5f * a;
    const float box = std::clamp((pulseIntegral(x0 + h, width) - pulseIntegral(x0 - h, width)) / a, 0.0f, 1.0f);
    return box + (width - box) * fade;
}

} // namespace

bool ToonRamp::isValid() const
{
    if (intensities.size() < 2 || thresholds.size() != intensities.size() - 1)
        return false;
    for (std::size_t i = 0; i < thresholds.size(); ++i) {
        if (!std::isfinite(thresholds[i]))
            return false;
        if (i > 0 && !(thresholds[i - 1] < thresholds[i]))
            return false;
    }
    return std::all_of(intensities.begin(), intensities.end(), [](float v) { return std::isfinite(v); });
}

int toonTone(const ToonRamp& ramp, float lambert)
{
    assert(ramp.isValid());
    // Count every threshold at or below s (not stop at the first above it): the GLSL loop over a
    // fixed-size array does the same, and with ascending thresholds both give the same tone.
    int tone = 0;
    for (const float t : ramp.thresholds)
        if (lambert >= t)
            ++tone;
    const int last = std::max(0, static_cast<int>(ramp.intensities.size()) - 1);
    return std::clamp(tone, 0, last);
}

float toonIntensity(const ToonRamp& ramp, float lambert)
{
    if (ramp.intensities.empty())
        return 1.0f; // programmer error (asserted in toonTone): leave the base colour unshaded
    return ramp.intensities[static_cast<std::size_t>(toonTone(ramp, lambert))];
}

float toneCoverage(float lambert, float threshold, float fwidth)
{
    if (!(fwidth > 0.0f))
        return lambert >= threshold ? 1.0f : 0.0f;
    if (std::isnan(lambert))
        return 0.0f; // as the hard step: NaN counts no threshold
    return std::clamp((lambert - threshold) / fwidth + 0.5f, 0.0f, 1.0f);
}

float toonIntensityAntialiased(const ToonRamp& ramp, float lambert, float fwidth)
{
    if (ramp.intensities.empty())
        return 1.0f;
    const std::size_t steps = std::min(ramp.thresholds.size(), ramp.intensities.size() - 1);
    float intensity = ramp.intensities[0];
    for (std::size_t i = 0; i < steps; ++i)
        intensity
            += toneCoverage(lambert, ramp.thresholds[i], fwidth) * (ramp.intensities[i + 1] - ramp.intensities[i]);
    return intensity;
}

std::array<float, 32> toonLookupTable(const ToonRamp& ramp)
{
    std::array<float, kLutSize> table{};
    for (int i = 0; i < kLutSize; ++i)
        table[static_cast<std::size_t>(i)]
            = toonIntensity(ramp, -1.0f + (static_cast<float>(i) + 0.5f) * (2.0f / static_cast<float>(kLutSize)));
    return table;
}

float lookupIntensity(const std::array<float, 32>& table, float lambert)
{
    // Written as comparisons (not std::clamp) so NaN reads entry 0, as in the shader.
    const float s = lambert > 1.0f ? 1.0f : (lambert >= -1.0f ? lambert : -1.0f);
    const int index = std::min(kLutSize - 1, static_cast<int>(std::floor((s + 1.0f) * 16.0f)));
    return table[static_cast<std::size_t>(index)];
}

GoochParams goochPreset(const std::string& name)
{
    // Paper 1, section 3.2.4: ka = .9 and k1..k4 = 1 by default, varied by the hue of Cbase.
    GoochParams p;
    if (name == "white") {
        // "we disable the warm (orange) light when rendering white-ish surfaces"
        p.preset = name;
        p.k2 = 0.0f;
    } else if (name == "purple") {
        // "For purple surfaces, we set k4 to 2.0 (intensifying the cool light component)"
        p.preset = name;
        p.k4 = 2.0f;
    } else if (name == "red") {
        // "for red colors we increase the cool light while also decreasing the warm light": the
        // paper gives no numbers. Halving the warm light and adding half again of the cool one
        // keeps the lit side red rather than orange and the shadow side a rich crimson, short of
        // the purple preset's k4 = 2, which would pull reds into purple.
        p.preset = name;
        p.k2 = 0.5f;
        p.k4 = 1.5f;
    }
    return p; // "default", and any unknown name
}

GoochParams goochPresetForColor(const Color& base)
{
    if (!base.allFinite())
        return goochPreset("default");
    // HSV of the base colour (hue in degrees, [0, 360)).
    const float maxC = base.maxCoeff();
    const float minC = base.minCoeff();
    const float chroma = maxC - minC;
    const float value = maxC;
    const float saturation = maxC > 0.0f ? chroma / maxC : 0.0f;
    float hue = 0.0f;
    if (chroma > 0.0f) {
        if (maxC == base.x())
            hue = 60.0f * std::fmod((base.y() - base.z()) / chroma + 6.0f, 6.0f);
        else if (maxC == base.y())
            hue = 60.0f * ((base.z() - base.x()) / chroma + 2.0f);
        else
            hue = 60.0f * ((base.x() - base.y()) / chroma + 4.0f);
    }
    // Thresholds (the paper names the hues only):
    // - white-ish: saturation < 0.2 and value > 0.75 (light greys and tinted whites; mid greys
    //   keep the warm light, or they would turn blue-grey);
    // - purple: hue in [260, 320] degrees (violet to purple, short of magenta-pink) and
    //   saturation > 0.25 so greyish lilacs stay default;
    // - red: hue within 20 degrees of pure red (<= 20 or >= 340) and saturation > 0.4, so pinks
    //   and browns-to-greys (low saturation) stay default.
    if (saturation < 0.2f && value > 0.75f)
        return goochPreset("white");
    if (hue >= 260.0f && hue <= 320.0f && saturation > 0.25f)
        return goochPreset("purple");
    if ((hue <= 20.0f || hue >= 340.0f) && saturation > 0.4f)
        return goochPreset("red");
    return goochPreset("default");
}

Color goochShade(const Color& base, const Eigen::Vector3f& n, const Eigen::Vector3f& l1, const GoochParams& params)
{
    // Paper 1, section 3.2.4:
    //   C = ka*Cbase + (l1.n)(Cwarm - Cbase*k1)*k2 + (l2.n)(Ccool - Cbase*k3)*k4,
    // with l2 = -l1 ("two lights on opposite sides of the surface") and each light's term only on
    // the side it faces (negative dot products clamped to 0, as OpenGL's diffuse lights do).
    const float d1 = n.dot(l1);
    const float w1 = std::max(0.0f, d1);
    const float w2 = std::max(0.0f, -d1);
    const Color warmTerm = (params.warm - base * params.k1) * params.k2;
    const Color coolTerm = (params.cool - base * params.k3) * params.k4;
    const Color c = params.ka * base + w1 * warmTerm + w2 * coolTerm;
    return c.cwiseMax(0.0f).cwiseMin(1.0f);
}

float hatchCoverage(const Eigen::Vector3f& position, const Eigen::Vector3f& normal, int tone, int toneCount,
    const HatchParams& params, float footprint)
{
    // Comic paper, "Shading": no strokes on the brightest tone, single strokes on the next one,
    // double-crossed strokes on all darker ones.
    if (toneCount < 2 || tone >= toneCount - 1)
        return 0.0f;
    if (!(params.spacing > 0.0f) || !std::isfinite(params.spacing))
        return 0.0f;
    // Written as comparisons so NaN width and footprint read 0, as in the shader.
    const float width = params.width > 0.0f ? std::min(params.width, 1.0f) : 0.0f;
    const float fp = footprint > 0.0f ? footprint : 0.0f;
    // Tri-planar object-space projection: the plane across the normal's dominant axis
    // (x -> (y, z), y -> (z, x), z -> (x, y); ties prefer x, then y).
    const Eigen::Vector3f an = normal.cwiseAbs();
    float u = position.x();
    float v = position.y();
    if (an.x() >= an.y() && an.x() >= an.z()) {
        u = position.y();
        v = position.z();
    } else if (an.y() >= an.z()) {
        u = position.z();
        v = position.x();
    }
    const float angle = params.angleDegrees * kDegToRad;
    const float first = stripeCoverage(u, v, angle, params.spacing, width, fp);
    if (tone == toneCount - 2)
        return first;
    const float second = stripeCoverage(u, v, angle + kHalfPi, params.spacing, width, fp);
    // Ink over ink: 1 - (1 - a)(1 - b), which is also the right grey far away (two orthogonal
    // stripe sets cover 1 - (1 - width)^2 of the plane). Written as a + b (1 - a) so that it is
    // exactly a where b = 0 and never below a in float.
    return first + second * (1.0f - first);
}

} // namespace celform::algo
