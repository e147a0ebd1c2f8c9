// Cartoon shading functions shared by the offline renderer and (mirrored in GLSL) the viewport:
// toon tones (paper 3, section 3.3; comic paper's 32-entry table), Gooch-like warm/cool shading
// (paper 1, section 3.2.4) and comic hatching (comic paper, "Shading").
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace celform::algo {

using Color = Eigen::Vector3f; ///< linear RGB in [0, 1]

/// Tones of a toon ramp: a Lambert value s = N.L + offset (paper 3, equation 4.3) at or above
/// thresholds[i] gives at least tone i + 1; tone intensities multiply the base colour.
struct ToonRamp {
    std::vector<float> thresholds{0.5f}; ///< ascending; tones.size() - 1 of them
    std::vector<float> intensities{0.25f, 0.75f}; ///< darkest first (paper 3, section 3.3 defaults)
    [[nodiscard]] bool isValid() const;
    bool operator==(const ToonRamp& o) const { return thresholds == o.thresholds && intensities == o.intensities; }
};

/// How the toon tone is evaluated, so artists can compare them (comic paper, "Shading").
enum class ToonEvaluation {
    PerPixel, ///< N.L per pixel, hard tone boundaries
    PerVertexLut, ///< the comic paper: N.L per vertex through a 32-entry table, interpolated
    PerFace, ///< N.L per triangle (face normal): the comic paper's first, blocky attempt
};

/// Index of the tone for a Lambert value (0 = darkest).
int toonTone(const ToonRamp& ramp, float lambert);
/// The tone's intensity.
float toonIntensity(const ToonRamp& ramp, float lambert);
/// Issue 25, "Shading without stair steps": how much of a pixel lies at or above a threshold t
/// when the Lambert value s varies linearly across it with screen-space derivative width
/// fwidth = |ds/dx| + |ds/dy| (as GLSL's fwidth): clamp((s - t) / fwidth + 1/2, 0, 1), the box
/// filter's coverage of a straight boundary (exact when the boundary is axis-aligned). fwidth = 0
/// gives the hard step of toonTone. The viewport's GLSL (look_shading.cpp) uses the same ramp.
float toneCoverage(float lambert, float threshold, float fwidth);
/// The tone's intensity with anti-aliased boundaries: the darkest intensity plus, per threshold,
/// its coverage times the step to the next intensity. Equals toonIntensity where fwidth = 0 or
/// no boundary lies within half a pixel.
float toonIntensityAntialiased(const ToonRamp& ramp, float lambert, float fwidth);
/// The comic paper's 32-entry table: entry i holds the ramp's intensity at the centre of the
/// i-th of 32 equal steps of N.L over [-1, 1].
std::array<float, 32> toonLookupTable(const ToonRamp& ramp);
/// Table look-up of a Lambert value (clamped to [-1, 1]).
float lookupIntensity(const std::array<float, 32>& table, float lambert);

/// Paper 1, section 3.2.4: C = ka*Cbase + (l1.n)(Cwarm - Cbase*k1)*k2 + (l2.n)(Ccool - Cbase*k3)*k4,
/// with l2 = -l1 (two lights on opposite sides) and negative dot products clamped to 0.
struct GoochParams {
    std::string preset = "default";
    float ka = 0.9f;
    float k1 = 1.0f;
    float k2 = 1.0f;
    float k3 = 1.0f;
    float k4 = 1.0f;
    Color warm{1.0f, 0.55f, 0.1f}; ///< orange
    Color cool{0.1f, 0.25f, 1.0f}; ///< blue
    bool operator==(const GoochParams& o) const
    {
        return preset == o.preset && ka == o.ka && k1 == o.k1 && k2 == o.k2 && k3 == o.k3 && k4 == o.k4
            && warm == o.warm && cool == o.cool;
    }
};

/// The paper's hue-adaptive rules as named presets: "white" (warm light off for whitish bases),
/// "purple" (k4 = 2), "red" (more cool, less warm), "default" otherwise.
GoochParams goochPreset(const std::string& name);
/// The preset the paper's rules pick for a base colour.
GoochParams goochPresetForColor(const Color& base);
/// Shaded colour, clamped to [0, 1]. n and l1 are unit vectors.
Color goochShade(const Color& base, const Eigen::Vector3f& n, const Eigen::Vector3f& l1, const GoochParams& params);

/// Comic hatching: shadow tones drawn as strokes, single strokes for the lighter shadow tone and
/// cross-hatching below it. Strokes are parallel stripes in object space (tri-planar, chosen by
/// the normal's dominant axis), so they stay on the surface while the camera moves.
struct HatchParams {
    float spacing = 0.02f; ///< distance between strokes, model units
    float angleDegrees = 45.0f; ///< stroke direction in the projection plane
    float width = 0.35f; ///< stroke width as a fraction of the spacing, (0, 1)
    bool operator==(const HatchParams& o) const
    {
        return spacing == o.spacing && angleDegrees == o.angleDegrees && width == o.width;
    }
};

/// Ink coverage in [0, 1] at a surface point for a toon tone (0 = darkest of toneCount):
/// the brightest tone gets none, the next single strokes, darker ones cross-hatching.
/// footprint is the size of a pixel in model units at that point, for anti-aliased stroke edges.
float hatchCoverage(const Eigen::Vector3f& position, const Eigen::Vector3f& normal, int tone, int toneCount,
    const HatchParams& params, float footprint);

} // namespace celform::algo
