// The offline renderer: rasterise, shade every covered pixel with the look's style, draw the
// feature lines over it, and fill the passes. No threads and no globals: the same inputs give the
// same pixels on every machine (DESIGN.md, "Rendering").
#include "celform/algorithms/render.h"
#include "celform/algorithms/fresh_memory.h"

#include "celform/algorithms/stroke_refine.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <future>
#include <iterator>
#include <limits>
#include <system_error>
#include <utility>

namespace celform::algo {
namespace {

constexpr double kPi = 3.14159265358979323846;

float luminance(const Color& c)
{
    return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z();
}

Eigen::Vector3f lightDirection(const RenderLook& look, const Eigen::Vector3f& position)
{
    Eigen::Vector3f l = look.pointLight ? Eigen::Vector3f(look.light - position) : look.light;
    const float n = l.norm();
    return n > 0.f ? Eigen::Vector3f(l / n) : Eigen::Vector3f(0.f, 0.f, 1.f);
}

float offsetAt(const RenderLook& look, std::int32_t v)
{
    return (look.shadingOffsets && std::size_t(v) < look.shadingOffsets->size())
        ? (*look.shadingOffsets)[std::size_t(v)]
        : 0.f;
}

/// The pixel next to (x, y) in one direction that continues its surface (covered, depth within
/// 2 %), for screen-space differences: the next pixel (sign 1), else the previous one (sign -1,
/// its difference mirrored), else none (sign 0).
struct SurfaceNeighbour {
    std::size_t i = 0, j = 0;
    float sign = 0.f;
};
SurfaceNeighbour surfaceNeighbour(const GBuffer& g, int x, int y, int dx, int dy)
{
    SurfaceNeighbour n;
    n.i = std::size_t(y) * std::size_t(g.width) + std::size_t(x);
    for (const int sign : {1, -1}) {
        const int nx = x + sign * dx, ny = y + sign * dy;
        if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height)
            continue;
        const std::size_t j = std::size_t(ny) * std::size_t(g.width) + std::size_t(nx);
        if (g.faceId[j] >= 0 && std::abs(g.depth[j] - g.depth[n.i]) <= 0.02f * std::abs(g.depth[n.i])) {
            n.j = j;
            n.sign = float(sign);
            break;
        }
    }
    return n;
}

/// Position and normal change towards the neighbouring pixel in one direction (surfaceNeighbour),
/// for the highlight mask's box filter and the supersampled tone; zero without a neighbour.
void pixelDelta(const GBuffer& g, int x, int y, int dx, int dy, Eigen::Vector3f& dP, Eigen::Vector3f& dN)
{
    const SurfaceNeighbour n = surfaceNeighbour(g, x, y, dx, dy);
    dP.setZero();
    dN.setZero();
    if (n.sign == 0.f)
        return;
    dP = n.sign * (g.position[n.j] - g.position[n.i]);
    dN = n.sign * (g.normal[n.j] - g.normal[n.i]);
}

/// The same difference of a per-pixel value (the screen-space derivative of the tone's N.L).
float valueDelta(const GBuffer& g, const std::vector<float>& value, int x, int y, int dx, int dy)
{
    const SurfaceNeighbour n = surfaceNeighbour(g, x, y, dx, dy);
    return n.sign == 0.f ? 0.f : n.sign * (value[n.j] - value[n.i]);
}

/// Coverage and colour of the look's highlight layers at a covered pixel; n faces the viewer.
HighlightSample highlightAt(const RenderLook& look, const GBuffer& g, const Faces& faces, int x, int y,
    const Eigen::Vector3f& n, const Eigen::Vector3f& eye)
{
    const std::size_t i = std::size_t(y) * std::size_t(g.width) + std::size_t(x);
    const std::int32_t f = g.faceId[i];
    const Eigen::Vector3f bary = g.barycentric[i];
    const std::int32_t a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
    HighlightLight light;
    light.point = look.pointLight;
    light.vector = look.light;
    HighlightFootprint footprint;
    pixelDelta(g, x, y, 1, 0, footprint.dPdx, footprint.dNdx);
    pixelDelta(g, x, y, 0, 1, footprint.dPdy, footprint.dNdy);
    // The G-buffer normal was flipped towards the viewer: its neighbours' differences follow.
    if (n.dot(g.normal[i]) < 0.f) {
        footprint.dNdx = -footprint.dNdx;
        footprint.dNdy = -footprint.dNdy;
    }
    HighlightSurfacePoint point;
    point.position = g.position[i];
    // Later layers over earlier ones, as evaluateHighlights composites them, each layer with its
    // own patch, frames and normals.
    HighlightCompositor layersSoFar;
    for (const RenderHighlight& h : look.highlights) {
        if (!h.faceMask.empty() && (std::size_t(f) >= h.faceMask.size() || !h.faceMask[std::size_t(f)]))
            continue;
        const Eigen::Index last = std::max({a, b, c});
        // The layer's smoothed normal, on the viewer's side as n is; n itself where the corners'
        // normals cancel or the layer has none.
        point.normal = n;
        if (h.normals.rows() > last) {
            const Eigen::Vector3f s
                = bary.x() * h.normals.row(a) + bary.y() * h.normals.row(b) + bary.z() * h.normals.row(c);
            const float s2 = s.squaredNorm();
            if (s2 > 1e-12f) {
                const Eigen::Vector3f m = s / std::sqrt(s2);
                point.normal = m.dot(n) < 0.f ? Eigen::Vector3f(-m) : m;
            }
        }
        if (h.du.rows() > last && h.dv.rows() > last) {
            const Eigen::Vector3f du = bary.x() * h.du.row(a) + bary.y() * h.du.row(b) + bary.z() * h.du.row(c);
            const Eigen::Vector3f dv = bary.x() * h.dv.row(a) + bary.y() * h.dv.row(b) + bary.z() * h.dv.row(c);
            point.frame = makeTangentFrame(point.normal, du, dv);
        } else {
            point.frame = makeTangentFrame(point.normal, Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY());
        }
        layersSoFar.paintOver(h.layer.color, layerCoverage(point, light, eye, h.layer, &footprint));
    }
    return layersSoFar.sample();
}

bool sameCamera(const RasterCamera& a, const RasterCamera& b)
{
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.orthographic == b.orthographic
        && a.fovYDegrees == b.fovYDegrees && a.orthoHeight == b.orthoHeight && a.width == b.width
        && a.height == b.height && a.horizontalShift == b.horizontalShift;
}

template <typename Matrix> bool sameArray(const Matrix& a, const Matrix& b)
{
    return a.rows() == b.rows()
        && (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(*a.data()) * std::size_t(a.size())) == 0);
}

} // namespace

const RidgeSnakes& cachedRidgeSnakes(const Positions& shape, const TriMesh& mesh, const RasterCamera& lineCamera,
    float threshold, RidgeRenderCache& cache, bool snakes, const std::vector<float>* thresholdScale)
{
    const bool sameScale = thresholdScale ? cache.snakeScale == *thresholdScale : cache.snakeScale.empty();
    if (!sameArray(shape, cache.shape) || !sameArray(mesh.faces, cache.faces) || cache.data.featureSize <= 0.f) {
        computeRidgeShapeData(shape, mesh.faces, cache.data);
        cache.shape = shape;
        cache.faces = mesh.faces;
        cache.snakesValid = false;
    }
    if (!cache.snakesValid || !sameCamera(cache.snakeCamera, lineCamera) || cache.snakeThreshold != threshold
        || cache.snakeJoined != snakes || !sameScale) {
        extractRidgeSnakes(shape, mesh.faces, mesh.vertexFaces(), cache.data, lineCamera, threshold, cache.scratch,
            cache.snakes, thresholdScale, snakes ? SnakeOptions() : SnakeOptions::raw());
        if (thresholdScale)
            cache.snakeScale = *thresholdScale;
        else
            cache.snakeScale.clear();
        cache.snakeCamera = lineCamera;
        cache.snakeThreshold = threshold;
        cache.snakeJoined = snakes;
        cache.snakesValid = true;
    }
    return cache.snakes;
}

void renderFrame(const Positions& shape, const TriMesh& mesh, const RasterCamera& camera, const RenderLook& look,
    RenderCache& cache, RenderPasses& out, const RasterCamera* lineView, GBuffer* gbuffer)
{
    const int width = camera.width, height = camera.height;
    const auto pixelCount = std::size_t(width) * std::size_t(height);
    const Faces& faces = mesh.faces;
    RenderScratch& scratch = cache.scratch;
    const Positions* given = look.vertexNormals;
    if (!given || given->rows() != shape.rows()) {
        vertexNormals(shape, faces, scratch.normals);
        given = &scratch.normals;
    }
    const Positions& normals = *given;

    // A mesh's first frame with lines: its edge topology is built on another thread while this
    // one rasterises (issue 29: 51 ms of a one-frame render of the dragon; the core the writer
    // thread uses later is idle then). mesh.edgeTopology() below waits for it; should that thread
    // fail, it builds the topology again here and reports the failure itself.
    std::future<void> topologyBuilt;
    if (look.lines && !mesh.hasEdgeTopology()) {
        try {
            topologyBuilt = std::async(std::launch::async, [&mesh] { (void)mesh.edgeTopology(); });
        } catch (const std::system_error&) {
            // no thread to be had: built below, on this one
        }
    }

    // The pixels' points are kept where the shading reads them: for the caller of the G-buffer, a
    // point light, the comic style's hatching, the highlights and the supersampled tone (those two
    // read the neighbours' too). A directional light's toon, Gooch and Lambert shading asks only
    // whether each normal faces the eye: GBuffer::facesAway, the same test on the same bits.
    const bool comic = look.style == Style::Comic
        || std::find(look.materialStyles.begin(), look.materialStyles.end(), Style::Comic) != look.materialStyles.end();
    const bool keepPositions = gbuffer || look.pointLight || comic || !look.highlights.empty()
        || (look.toneAntialiasing == ToneAntialiasing::Supersample4 && look.toonEvaluation == ToonEvaluation::PerPixel);
    GBuffer& g = scratch.gbuffer;
    rasterise(shape, faces, normals, camera, g, keepPositions);
    // A directional light's direction does not depend on the point (lightDirection).
    auto positionAt = [&](std::size_t i) { return keepPositions ? g.position[i] : Eigen::Vector3f::Zero().eval(); };

    // Lines: topology once per mesh, features and strokes per frame, from the line view's eye
    // (the centre eye for stereo pairs, paper 3, section 4.2.2), projected with this camera.
    reserveBacked(out.lines, pixelCount);
    out.lines.assign(pixelCount, 0.f);
    if (look.lines) {
        if (topologyBuilt.valid())
            topologyBuilt.wait();
        const EdgeTopology& topology = mesh.edgeTopology(); // built once per mesh, kept with it
        const RasterCamera& lv = lineView ? *lineView : camera;
        LineView view;
        view.eye = lv.eye.cast<float>();
        view.direction = lv.forward().cast<float>();
        view.orthographic = lv.orthographic;
        FeatureEdges& features = scratch.features;
        extractFeatureEdges(shape, faces, topology, mesh.faceMaterials, view, look.lineSettings, features);
        const std::vector<Stroke> strokes = chainStrokes(topology, features);
        const ProjectionFrame projection(camera);
        auto project = [&](const Eigen::Vector3f& p) {
            return Eigen::Vector3f(projection.project(p.cast<double>()).cast<float>());
        };
        // Apparent ridges from the line view's eye, clustered in its pixels (paper 3, 4.2.1).
        const RidgeSnakes* snakes = look.lineSettings.ridges
            ? &cachedRidgeSnakes(shape, mesh, lv, look.lineSettings.ridgeThreshold, cache.ridges,
                look.lineSettings.ridgeSnakes, look.ridgeThresholdScale)
            : nullptr;
        // The viewport's LineOverlay::draw takes the same path (stroke_refine.h).
        std::vector<StyledStroke> styled
            = pictureStrokes(strokes, snakes, shape, look.lineStyle, camera.height, project);
        drawStrokes(styled, g, out.lines);
        out.strokes = std::move(styled); // for the vector writers (stroke_visibility.h)
    } else {
        out.strokes.clear();
    }

    // Per-vertex and per-face inputs of the comic paper's two coarser toon evaluations.
    std::vector<float>& vertexIntensity = scratch.vertexIntensity;
    std::array<float, 32> table{};
    if (look.toonEvaluation == ToonEvaluation::PerVertexLut) {
        table = toonLookupTable(look.toon);
        vertexIntensity.resize(std::size_t(shape.rows()));
        for (Eigen::Index v = 0; v < shape.rows(); ++v) {
            const Eigen::Vector3f p = shape.row(v);
            const Eigen::Vector3f n = normals.row(v);
            vertexIntensity[std::size_t(v)]
                = lookupIntensity(table, n.dot(lightDirection(look, p)) + offsetAt(look, std::int32_t(v)));
        }
    }

    // N.L + offset per covered pixel, on the side facing the viewer: the toon tone's input and,
    // through differences between pixels, its screen-space derivative (issue 25).
    const Eigen::Vector3f eyeF = camera.eye.cast<float>();
    auto facingNormal = [&](std::size_t i) {
        const Eigen::Vector3f& n = g.normal[i];
        // Seen from behind (the inside of an open mesh), a surface is lit from the side that
        // faces the viewer, as in every DCC viewport.
        const bool away = keepPositions ? n.dot(eyeF - g.position[i]) < 0.f : g.facesAway[i] != 0;
        return away ? Eigen::Vector3f(-n) : n;
    };
    auto pixelOffset = [&](std::size_t i) {
        const std::int32_t f = g.faceId[i];
        const Eigen::Vector3f bary = g.barycentric[i];
        return bary.x() * offsetAt(look, faces(f, 0)) + bary.y() * offsetAt(look, faces(f, 1))
            + bary.z() * offsetAt(look, faces(f, 2));
    };
    std::vector<float>& lambertAt = scratch.lambert;
    reserveBacked(lambertAt, pixelCount);
    lambertAt.assign(pixelCount, 0.f);
    for (std::size_t i = 0; i < pixelCount; ++i)
        if (g.faceId[i] >= 0)
            lambertAt[i] = facingNormal(i).dot(lightDirection(look, positionAt(i))) + pixelOffset(i);
    const bool toneAa = look.toonEvaluation == ToonEvaluation::PerPixel;
    // The per-pixel tone, anti-aliased as the look asks.
    auto pixelTone = [&](int x, int y, std::size_t i) {
        const float lambert = lambertAt[i];
        if (!toneAa || look.toneAntialiasing == ToneAntialiasing::Off)
            return toonIntensity(look.toon, lambert);
        if (look.toneAntialiasing == ToneAntialiasing::Coverage) {
            const float fwidth
                = std::abs(valueDelta(g, lambertAt, x, y, 1, 0)) + std::abs(valueDelta(g, lambertAt, x, y, 0, 1));
            return toonIntensityAntialiased(look.toon, lambert, fwidth);
        }
        // Supersample4: the tone at the four points of a 2x2 grid in the pixel, normal and position
        // moved along their differences to the neighbouring pixels.
        Eigen::Vector3f dPdx, dNdx, dPdy, dNdy;
        pixelDelta(g, x, y, 1, 0, dPdx, dNdx);
        pixelDelta(g, x, y, 0, 1, dPdy, dNdy);
        const Eigen::Vector3f n = facingNormal(i);
        const float side = n.dot(g.normal[i]) < 0.f ? -1.f : 1.f;
        const float offset = pixelOffset(i);
        float sum = 0.f;
        for (const float ox : {-0.25f, 0.25f})
            for (const float oy : {-0.25f, 0.25f}) {
                const Eigen::Vector3f p = g.position[i] + ox * dPdx + oy * dPdy;
                const Eigen::Vector3f m = (n + side * (ox * dNdx + oy * dNdy)).normalized();
                sum += toonIntensity(look.toon, m.dot(lightDirection(look, p)) + offset);
            }
        return 0.25f * sum;
    };

    const double tanHalf = std::tan(camera.fovYDegrees * kPi / 360.0);
    // Every pixel of the beauty is written below: only its size is set here.
    out.beauty.width = width;
    out.beauty.height = height;
    reserveBacked(out.beauty.pixels, pixelCount * 4);
    out.beauty.pixels.resize(pixelCount * 4);
    const bool dataPasses = look.dataPasses;
    if (dataPasses) {
        out.tone.assign(pixelCount, 0.f);
        out.highlights.assign(pixelCount, 0.f);
        out.depth = g.depth;
        out.normal.assign(pixelCount, Eigen::Vector3f::Zero());
        out.id = g.faceId;
    } else {
        out.tone.clear();
        out.highlights.clear();
        out.depth.clear();
        out.normal.clear();
        out.id.clear();
    }
    const Eigen::Vector3f lineColor = look.lineStyle.color;
    const Eigen::Vector3d eye = camera.eye;

    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            float* px = out.beauty.at(x, y);
            Color color = look.background;
            const std::int32_t f = g.faceId[i];
            if (f >= 0) {
                const int material = mesh.faceMaterials.empty() ? 0 : mesh.faceMaterials[std::size_t(f)];
                const Color base = std::size_t(material) < look.materialColors.size()
                    ? look.materialColors[std::size_t(material)]
                    : look.defaultColor;
                const Style style = std::size_t(material) < look.materialStyles.size()
                    ? look.materialStyles[std::size_t(material)]
                    : look.style;
                const Eigen::Vector3f position = positionAt(i);
                const Eigen::Vector3f n = facingNormal(i);
                const Eigen::Vector3f l = lightDirection(look, position);
                const Eigen::Vector3f bary = g.barycentric[i];
                const std::int32_t a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
                const float lambert = lambertAt[i];
                float intensity = 0.f;
                switch (style) {
                case Style::Lambert:
                    intensity = 0.15f + 0.85f * std::max(0.f, lambert);
                    color = base * intensity;
                    break;
                case Style::Toon:
                    if (look.toonEvaluation == ToonEvaluation::PerVertexLut) {
                        intensity = bary.x() * vertexIntensity[std::size_t(a)]
                            + bary.y() * vertexIntensity[std::size_t(b)] + bary.z() * vertexIntensity[std::size_t(c)];
                    } else if (look.toonEvaluation == ToonEvaluation::PerFace) {
                        const Eigen::Vector3f pa = shape.row(a), pb = shape.row(b), pc = shape.row(c);
                        Eigen::Vector3f fn = (pb - pa).cross(pc - pa).normalized();
                        if (fn.dot(eye.cast<float>() - pa) < 0.f)
                            fn = -fn;
                        const Eigen::Vector3f centre = (pa + pb + pc) / 3.f;
                        const float faceOffset = (offsetAt(look, a) + offsetAt(look, b) + offsetAt(look, c)) / 3.f;
                        intensity = toonIntensity(look.toon, fn.dot(lightDirection(look, centre)) + faceOffset);
                    } else {
                        intensity = pixelTone(x, y, i);
                    }
                    color = base * intensity;
                    break;
                case Style::Gooch:
                    color = goochShade(base, n, l,
                        std::size_t(material) < look.materialGooch.size() ? look.materialGooch[std::size_t(material)]
                                                                          : look.gooch);
                    intensity = luminance(color);
                    break;
                case Style::Comic: {
                    // Flat colour at the brightest tone, shadow tones drawn as ink strokes.
                    const int tone = toonTone(look.toon, lambert);
                    const int toneCount = int(look.toon.intensities.size());
                    const double depth = g.depth[i];
                    const float footprint
                        = float(camera.orthographic ? camera.orthoHeight / height : 2.0 * depth * tanHalf / height);
                    const float ink = hatchCoverage(position, n, tone, toneCount, look.hatch, footprint);
                    intensity = look.toon.intensities.back() * (1.f - ink);
                    color = base * look.toon.intensities.back() * (1.f - ink) + lineColor * ink;
                    break;
                }
                }
                if (!look.highlights.empty()) {
                    const HighlightSample h = highlightAt(look, g, faces, x, y, n, eye.cast<float>());
                    if (dataPasses)
                        out.highlights[i] = h.coverage;
                    color = color * (1.f - h.coverage) + h.color * h.coverage;
                }
                if (dataPasses) {
                    out.tone[i] = intensity;
                    out.normal[i] = n;
                }
            }
            const float line = out.lines[i];
            color = color * (1.f - line) + lineColor * line;
            px[0] = std::clamp(color.x(), 0.f, 1.f);
            px[1] = std::clamp(color.y(), 0.f, 1.f);
            px[2] = std::clamp(color.z(), 0.f, 1.f);
            px[3] = 1.f;
        }
    }
    if (gbuffer)
        std::swap(*gbuffer, g);
}

} // namespace celform::algo
