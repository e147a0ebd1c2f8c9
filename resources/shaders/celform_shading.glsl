// Celform cartoon shading for the viewport: a GLSL 1.50 snippet (without a version directive)
// inserted into VTK's fragment shader. It mirrors algorithms/celform/algorithms/shading.cpp line
// for line (same order of operations, same constants) so the viewport and the offline renderer
// produce the same pictures: change both files together. Paper references are those of shading.h.

// Toon ramp (paper 3, section 3.3): up to 8 tones, darkest first; cfThresholds[i] ascending,
// cfToneCount - 1 of them used. ToonRamp on the CPU.
uniform int cfToneCount;
uniform float cfThresholds[7];
uniform float cfIntensities[8];
// The comic paper's 32-entry table, filled from toonLookupTable().
uniform float cfLut[32];
// Gooch-like lighting (paper 1, section 3.2.4). GoochParams on the CPU.
uniform float cfKa, cfK1, cfK2, cfK3, cfK4;
uniform vec3 cfWarm, cfCool;
// Hatching. HatchParams on the CPU; the angle here is in radians (angleDegrees * 0.0174532925).
uniform float cfHatchSpacing, cfHatchAngle, cfHatchWidth;

// toonTone + toonIntensity: the number of thresholds t with lambert >= t (a value exactly at a
// threshold takes the brighter tone; NaN counts none), clamped to [0, tones - 1].
float cfToonIntensity(float lambert)
{
    int tone = 0;
    for (int i = 0; i < 7; ++i)
        if (i < cfToneCount - 1 && lambert >= cfThresholds[i])
            ++tone;
    tone = clamp(tone, 0, max(0, cfToneCount - 1));
    return cfIntensities[tone];
}

// lookupIntensity (comic paper, "Shading"): clamp to [-1, 1] (NaN to -1), entry
// min(31, floor((s + 1) * 16)).
float cfLookupIntensity(float lambert)
{
    float s = lambert > 1.0 ? 1.0 : (lambert >= -1.0 ? lambert : -1.0);
    int index = min(32 - 1, int(floor((s + 1.0) * 16.0)));
    return cfLut[index];
}

// goochShade (paper 1, section 3.2.4):
//   C = ka*Cbase + (l1.n)(Cwarm - Cbase*k1)*k2 + (l2.n)(Ccool - Cbase*k3)*k4, l2 = -l1,
// negative dot products clamped to 0, result clamped to [0, 1]. n and l1 are unit vectors.
vec3 cfGoochShade(vec3 base, vec3 n, vec3 l1)
{
    float d1 = dot(n, l1);
    float w1 = max(0.0, d1);
    float w2 = max(0.0, -d1);
    vec3 warmTerm = (cfWarm - base * cfK1) * cfK2;
    vec3 coolTerm = (cfCool - base * cfK3) * cfK4;
    vec3 c = cfKa * base + w1 * warmTerm + w2 * coolTerm;
    return min(max(c, 0.0), 1.0);
}

// pulseIntegral: ink of the pulse train "1 where fract(y) < width" from 0 to y.
float cfPulseIntegral(float y, float width)
{
    float cell = floor(y);
    return cell * width + min(y - cell, width);
}

// stripeCoverage: one set of strokes along angle (radians), centred on multiples of the spacing,
// box-filtered over the footprint and faded to the mean width past the Nyquist limit.
float cfStripeCoverage(float u, float v, float angle, float spacing, float width, float footprint)
{
    float c = -u * sin(angle) + v * cos(angle);
    float s = c / spacing;
    float a = footprint / spacing;
    float fade = clamp(2.0 * a - 1.0, 0.0, 1.0);
    if (fade >= 1.0)
        return width;
    if (!(a >= 1e-4)) {
        float dist = abs(s - floor(s + 0.5));
        return dist < 0.5 * width ? 1.0 : 0.0;
    }
    float x = s + 0.5 * width;
    float x0 = x - floor(x);
    float h = 0.5 * a;
    float box = clamp((cfPulseIntegral(x0 + h, width) - cfPulseIntegral(x0 - h, width)) / a, 0.0, 1.0);
    return box + (width - box) * fade;
}

// hatchCoverage (comic paper, "Shading"): no ink on the brightest tone, single strokes on the
// next, cross-hatching (second set at angle + 90 degrees) below, combined as 1 - (1 - a)(1 - b);
// tri-planar object-space stripes.
float cfHatchCoverage(vec3 position, vec3 normal, int tone, int toneCount, float footprint)
{
    if (toneCount < 2 || tone >= toneCount - 1)
        return 0.0;
    if (!(cfHatchSpacing > 0.0) || isinf(cfHatchSpacing))
        return 0.0;
    float width = cfHatchWidth > 0.0 ? min(cfHatchWidth, 1.0) : 0.0;
    float fp = footprint > 0.0 ? footprint : 0.0;
    vec3 an = abs(normal);
    float u = position.x;
    float v = position.y;
    if (an.x >= an.y && an.x >= an.z) {
        u = position.y;
        v = position.z;
    } else if (an.y >= an.z) {
        u = position.z;
        v = position.x;
    }
    float angle = cfHatchAngle;
    float first = cfStripeCoverage(u, v, angle, cfHatchSpacing, width, fp);
    if (tone == toneCount - 2)
        return first;
    float second = cfStripeCoverage(u, v, angle + 1.57079633, cfHatchSpacing, width, fp);
    return first + second * (1.0 - first);
}
