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
// Gooch-like lighting (paper 1, section 3.2.4). GoochParams on the CPU: one material's
// coefficients (the "auto" preset gives each material its own, so the viewport passes the face's
// material's set to cfGoochShadeWith); the uniforms are the look's single set for cfGoochShade.
struct CfGoochParams {
    float ka, k1, k2, k3, k4;
    vec3 warm, cool;
};
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

// toneCoverage (issue 25, "Shading without stair steps"): the share of the pixel at or above the
// threshold when lambert varies across it by width = fwidth(lambert), a one-pixel linear ramp
// (the box filter's coverage of a straight boundary); width 0 is the hard step. NaN covers none.
float cfToneCoverage(float lambert, float threshold, float width)
{
    if (!(width > 0.0))
        return lambert >= threshold ? 1.0 : 0.0;
    if (!(lambert == lambert))
        return 0.0;
    return clamp((lambert - threshold) / width + 0.5, 0.0, 1.0);
}

// toonIntensityAntialiased: the darkest intensity plus each threshold's coverage times the step
// to the next tone's intensity.
float cfToonIntensityAntialiased(float lambert, float width)
{
    float intensity = cfIntensities[0];
    for (int i = 0; i < 7; ++i)
        if (i < cfToneCount - 1)
            intensity += cfToneCoverage(lambert, cfThresholds[i], width) * (cfIntensities[i + 1] - cfIntensities[i]);
    return intensity;
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
vec3 cfGoochShadeWith(vec3 base, vec3 n, vec3 l1, CfGoochParams params)
{
    float d1 = dot(n, l1);
    float w1 = max(0.0, d1);
    float w2 = max(0.0, -d1);
    vec3 warmTerm = (params.warm - base * params.k1) * params.k2;
    vec3 coolTerm = (params.cool - base * params.k3) * params.k4;
    vec3 c = params.ka * base + w1 * warmTerm + w2 * coolTerm;
    return min(max(c, 0.0), 1.0);
}

// goochShade with the uniforms' coefficients.
vec3 cfGoochShade(vec3 base, vec3 n, vec3 l1)
{
    return cfGoochShadeWith(base, n, l1, CfGoochParams(cfKa, cfK1, cfK2, cfK3, cfK4, cfWarm, cfCool));
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

// ---------------------------------------------------------------------------------------------
// Stylized highlights (Anjyo & Hiramitsu 2003): mirror of algorithms/celform/algorithms/
// highlights.cpp (makeTangentFrame, halfwayVector, applyHighlightOperations, highlightFunction,
// layerCoverage) and of render.cpp's highlightAt. Change both together.
//
// Up to 4 layers (the visible tracks resolved at the viewport's frame by renderHighlightsFor),
// each with its own normal (cfHighlightNormal), its own shape and up to 2 combinations whose
// operand shapes are stored beside it:
// shape index layer * 3 + 0 is the layer's own, layer * 3 + 1 + k the k-th combination's.
// Each shape has up to 8 operations at shape * 8 + i: type (HighlightOperationType order:
// 0 translation, 1 rotation, 2 directional scaling, 3 split, 4 squaring) and the two floats a, b.
uniform int cfHlLayerCount;
uniform vec3 cfHlColor[4];
uniform float cfHlCut[4];      // offSpecularCut; -1 = off
uniform int cfHlCombCount[4];  // <= 2
uniform int cfHlCombMode[8];   // layer * 2 + k: 0 union, 1 subtraction (HighlightBoolean)
uniform float cfHlEpsilon[12];
uniform int cfHlOpCount[12];
uniform int cfHlOpType[96];
uniform float cfHlOpA[96];
uniform float cfHlOpB[96];

// safeNormalized: zero for squared lengths at or below kTiny.
vec3 cfSafeNormalized(vec3 v)
{
    float n2 = dot(v, v);
    return n2 > 1e-12 ? v / sqrt(n2) : vec3(0.0);
}

// paperSign: sgn[0] = 1.
float cfPaperSign(float x)
{
    return x >= 0.0 ? 1.0 : -1.0;
}

vec3 cfLeastAlignedAxis(vec3 n)
{
    vec3 a = abs(n);
    if (a.x <= a.y && a.x <= a.z)
        return vec3(1.0, 0.0, 0.0);
    return a.y <= a.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
}

vec3 cfTowardsLight(vec3 position, vec3 light, bool pointLight)
{
    return cfSafeNormalized(pointLight ? light - position : light);
}

// makeTangentFrame: du projected on the tangent plane (else from dv, else the least aligned
// axis), dv = n x du turned to dv's side.
void cfMakeTangentFrame(vec3 normal, vec3 du, vec3 dv, out vec3 frameU, out vec3 frameV)
{
    vec3 n = cfSafeNormalized(normal);
    vec3 u = du - dot(du, n) * n;
    if (dot(u, u) <= 1e-12) {
        vec3 w = dv - dot(dv, n) * n;
        u = dot(w, w) > 1e-12 ? cross(w, n) : vec3(0.0);
    }
    if (dot(u, u) <= 1e-12) {
        vec3 axis = cfLeastAlignedAxis(n);
        u = axis - dot(axis, n) * n;
    }
    u = normalize(u);
    vec3 c = cross(n, u);
    frameU = u;
    frameV = dot(c, dv) < 0.0 ? -c : c;
}

// halfwayVector: H = (L + V) / |L + V|.
vec3 cfHalfwayVector(vec3 position, vec3 light, bool pointLight, vec3 eye)
{
    vec3 l = cfTowardsLight(position, light, pointLight);
    vec3 v = cfSafeNormalized(eye - position);
    return cfSafeNormalized(l + v);
}

// applyHighlightOperations for shape `shape`.
vec3 cfApplyHighlightOperations(vec3 halfway, vec3 frameU, vec3 frameV, int shape)
{
    vec3 h = halfway;
    vec3 du = frameU;
    vec3 dv = frameV;
    for (int i = 0; i < 8; ++i) {
        if (i >= cfHlOpCount[shape])
            break;
        int k = shape * 8 + i;
        int type = cfHlOpType[k];
        float a = cfHlOpA[k];
        float b = cfHlOpB[k];
        if (type == 0) {
            // Translation.
            h = cfSafeNormalized(h + a * du + b * dv);
        } else if (type == 1) {
            // Rotation of the frame of later operations.
            float c = cos(a * 0.0174532925);
            float s = sin(a * 0.0174532925);
            vec3 u = c * du + s * dv;
            dv = c * dv - s * du;
            du = u;
        } else if (type == 2) {
            // Directional scaling (eq. 4).
            h = cfSafeNormalized(h - a * dot(h, du) * du);
        } else if (type == 3) {
            // Split.
            h = cfSafeNormalized(h - a * cfPaperSign(dot(h, du)) * du - b * cfPaperSign(dot(h, dv)) * dv);
        } else {
            // Squaring.
            float hu = dot(h, du);
            float hv = dot(h, dv);
            float t2 = hu * hu + hv * hv;
            float sin2 = t2 > 1e-12 ? 2.0 * abs(hu * hv) / t2 : 0.0;
            float sqrnorm = pow(sin2, max(b, 1.0));
            h = cfSafeNormalized(h - a * sqrnorm * (hu * du + hv * dv));
        }
    }
    return h;
}

// highlightFunction (eq. 2): Phi = (N, H').
float cfHighlightFunction(vec3 halfway, vec3 normal, vec3 frameU, vec3 frameV, int shape)
{
    return dot(normal, cfApplyHighlightOperations(halfway, frameU, frameV, shape));
}

// edgeCoverage: "value > threshold" box-filtered over the value's change across the pixel
// (width = fwidth(value), the CPU's |value_x - value| + |value_y - value|); a step at width 0.
float cfEdgeCoverage(float value, float width, float threshold)
{
    float margin = value - threshold;
    if (!(width > 0.0))
        return margin > 0.0 ? 1.0 : 0.0;
    return clamp(margin / width + 0.5, 0.0, 1.0);
}

// shapeCoverage (eq. 3: threshold 1 - epsilon). Called in uniform control flow (fwidth).
float cfShapeCoverage(int shape, vec3 halfway, vec3 normal, vec3 frameU, vec3 frameV)
{
    float threshold = 1.0 - cfHlEpsilon[shape];
    float phi = cfHighlightFunction(halfway, normal, frameU, frameV, shape);
    return cfEdgeCoverage(phi, fwidth(phi), threshold);
}

// render.cpp's highlightAt: a layer's normal at the fragment, its interpolated smoothed normal
// (zero where it has none) made unit and turned to n's side (n faces the viewer); n where the
// corners' normals cancel or are zero.
vec3 cfHighlightNormal(vec3 layerNormal, vec3 n)
{
    vec3 m = cfSafeNormalized(layerNormal);
    if (!(dot(m, m) > 0.0))
        return n;
    return dot(m, n) < 0.0 ? -m : m;
}

// layerCoverage: the layer's shape, its combinations (union max, subtraction min(a, 1 - b)),
// then the off-specular cut on (N, L).
float cfLayerCoverage(int layer, vec3 position, vec3 normal, vec3 du, vec3 dv, vec3 light, bool pointLight, vec3 eye)
{
    // makeSample
    vec3 n = cfSafeNormalized(normal);
    vec3 frameU;
    vec3 frameV;
    cfMakeTangentFrame(n, du, dv, frameU, frameV);
    vec3 halfway = cfHalfwayVector(position, light, pointLight, eye);
    float lambert = dot(n, cfTowardsLight(position, light, pointLight));

    float coverage = cfShapeCoverage(layer * 3, halfway, n, frameU, frameV);
    for (int k = 0; k < 2; ++k) {
        if (k >= cfHlCombCount[layer])
            break;
        float other = cfShapeCoverage(layer * 3 + 1 + k, halfway, n, frameU, frameV);
        coverage = cfHlCombMode[layer * 2 + k] == 0 ? max(coverage, other) : min(coverage, 1.0 - other);
    }
    if (cfHlCut[layer] > -1.0)
        coverage = min(coverage, cfEdgeCoverage(lambert, fwidth(lambert), cfHlCut[layer]));
    return coverage;
}
