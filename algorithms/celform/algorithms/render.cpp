// The offline renderer: rasterise, shade every covered pixel with the look's style, draw the
// feature lines over it, and fill the passes. No threads and no globals: the same inputs give the
// same pixels on every machine (DESIGN.md, "Rendering").
#include "celform/algorithms/render.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

} // namespace

void renderFrame(const Positions& shape, const TriMesh& mesh, const RasterCamera& camera, const RenderLook& look,
    RenderCache& cache, RenderPasses& out, const RasterCamera* lineView)
{
    const int width = camera.width, height = camera.height;
    const auto pixelCount = std::size_t(width) * std::size_t(height);
    const Faces& faces = mesh.faces;
    const Positions normals = vertexNormals(shape, faces);

    GBuffer g;
    rasterize(shape, faces, normals, camera, g);

    // Lines: topology once per mesh, features and strokes per frame, from the line view's eye
    // (the centre eye for stereo pairs, paper 3, section 4.2.2), projected with this camera.
    out.lines.assign(pixelCount, 0.f);
    if (look.lines) {
        if (cache.faces != &faces || cache.topology.edges.rows() == 0) {
            cache.topology = buildEdgeTopology(faces, std::int32_t(shape.rows()));
            cache.faces = &faces;
        }
        const RasterCamera& lv = lineView ? *lineView : camera;
        LineView view;
        view.eye = lv.eye.cast<float>();
        view.direction = lv.forward().cast<float>();
        view.orthographic = lv.orthographic;
        FeatureEdges features;
        extractFeatureEdges(shape, faces, cache.topology, mesh.faceMaterials, view, look.lineSettings, features);
        const std::vector<Stroke> strokes = chainStrokes(cache.topology, features);
        const std::vector<StyledStroke> styled = styleStrokes(strokes, shape, look.lineStyle,
            [&](const Eigen::Vector3f& p) { return Eigen::Vector3f(camera.project(p.cast<double>()).cast<float>()); });
        drawStrokes(styled, g, out.lines);
    }

    // Per-vertex and per-face inputs of the comic paper's two coarser toon evaluations.
    std::vector<float> vertexIntensity;
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

    const double tanHalf = std::tan(camera.fovYDegrees * kPi / 360.0);
    out.beauty = ImageRGBA(width, height);
    out.tone.assign(pixelCount, 0.f);
    out.highlights.assign(pixelCount, 0.f);
    out.depth = g.depth;
    out.normal.assign(pixelCount, Eigen::Vector3f::Zero());
    out.id = g.faceId;
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
                const Eigen::Vector3f position = g.position[i];
                Eigen::Vector3f n = g.normal[i];
                // Seen from behind (the inside of an open mesh), a surface is lit from the side
                // that faces the viewer, as in every DCC viewport.
                if (n.dot((eye.cast<float>() - position)) < 0.f)
                    n = -n;
                const Eigen::Vector3f l = lightDirection(look, position);
                const Eigen::Vector3f bary = g.barycentric[i];
                const std::int32_t a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
                const float offset
                    = bary.x() * offsetAt(look, a) + bary.y() * offsetAt(look, b) + bary.z() * offsetAt(look, c);
                const float lambert = n.dot(l) + offset;
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
                        intensity = toonIntensity(look.toon, lambert);
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
                out.tone[i] = intensity;
                out.normal[i] = n;
            }
            const float line = out.lines[i];
            color = color * (1.f - line) + lineColor * line;
            px[0] = std::clamp(color.x(), 0.f, 1.f);
            px[1] = std::clamp(color.y(), 0.f, 1.f);
            px[2] = std::clamp(color.z(), 0.f, 1.f);
            px[3] = 1.f;
        }
    }
}

} // namespace celform::algo
