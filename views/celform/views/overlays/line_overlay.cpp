// Viewport lines: the offline renderer's stroke pipeline (algo::extractFeatureEdges, chainStrokes,
// pictureStrokes, drawStrokes) run against depth read back from GL instead of a CPU G-buffer.
#include "celform/views/overlays/line_overlay.h"

#include "celform/views/overlays/srgb_bytes.h"

#include "celform/algorithms/stroke_refine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

namespace celform::views {

namespace {

const std::array<float, 256>& decodeTable()
{
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int k = 0; k < 256; ++k)
            t[std::size_t(k)] = algo::srgbToLinear(float(k) / 255.f);
        return t;
    }();
    return table;
}

} // namespace

void viewDepthFromWindowDepth(const std::vector<float>& windowDepth, int width, int height, double nearDistance,
    double farDistance, bool orthographic, std::vector<float>& out)
{
    const std::size_t pixels = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    out.assign(pixels, std::numeric_limits<float>::infinity());
    if (windowDepth.size() < pixels)
        return;
    const double n = nearDistance, f = farDistance;
    for (int y = 0; y < height; ++y) {
        const float* row = windowDepth.data() + std::size_t(height - 1 - y) * std::size_t(width);
        float* target = out.data() + std::size_t(y) * std::size_t(width);
        for (int x = 0; x < width; ++x) {
            const double d = row[x];
            if (d >= 1.0)
                continue; // cleared: nothing drawn here
            if (orthographic) {
                target[x] = float(n + d * (f - n));
            } else {
                // Inverse of the perspective depth mapping with glDepthRange(0, 1).
                const double ndc = 2.0 * d - 1.0;
                target[x] = float(2.0 * n * f / (f + n - ndc * (f - n)));
            }
        }
    }
}

void LineOverlay::clear()
{
    m_mesh = nullptr;
    m_generation = 0;
    m_valid = false;
    m_strokes.clear();
    m_ridgeGeneration = 0;
    m_snakes.clear();
}

void LineOverlay::update(const algo::Shape& shape, const algo::TriMesh& mesh, const algo::LineView& view,
    const algo::LineSettings& settings, const algo::RasterCamera& lineCamera)
{
    const bool sameView
        = view.eye == m_view.eye && view.direction == m_view.direction && view.orthographic == m_view.orthographic;
    // Snakes are clustered in the line camera's pixels: its size and lens matter too.
    const bool sameRidgeCamera = !settings.ridges
        || (lineCamera.width == m_ridgeCamera.width && lineCamera.height == m_ridgeCamera.height
            && lineCamera.fovYDegrees == m_ridgeCamera.fovYDegrees
            && lineCamera.orthoHeight == m_ridgeCamera.orthoHeight && lineCamera.eye == m_ridgeCamera.eye
            && lineCamera.target == m_ridgeCamera.target && lineCamera.up == m_ridgeCamera.up
            && lineCamera.orthographic == m_ridgeCamera.orthographic);
    // A generation is never reused, and a new mesh comes with a new shape: it alone says whether
    // the positions (and so the strokes) can have changed.
    if (m_valid && sameView && sameRidgeCamera && shape.generation != 0 && shape.generation == m_generation
        && settings == m_settings)
        return;
    const algo::EdgeTopology& topology = mesh.edgeTopology();
    algo::FeatureEdges features;
    algo::extractFeatureEdges(shape.positions, mesh.faces, topology, mesh.faceMaterials, view, settings, features);
    m_strokes = algo::chainStrokes(topology, features);
    m_snakes.clear();
    if (settings.ridges) {
        // Curvature once per shape (generation), the view-dependent part per view.
        if (shape.generation == 0 || shape.generation != m_ridgeGeneration || m_mesh != &mesh) {
            algo::computeRidgeShapeData(shape.positions, mesh.faces, m_ridgeData);
            m_ridgeGeneration = shape.generation;
        }
        algo::extractRidgeSnakes(shape.positions, mesh.faces, mesh.vertexFaces(), m_ridgeData, lineCamera,
            settings.ridgeThreshold, m_ridgeScratch, m_snakes, nullptr,
            settings.ridgeSnakes ? algo::SnakeOptions() : algo::SnakeOptions::raw());
    }
    m_ridgeCamera = lineCamera;
    m_mesh = &mesh;
    m_generation = shape.generation;
    m_view = view;
    m_settings = settings;
    m_valid = true;
}

QRect LineOverlay::draw(const algo::Positions& shape, const algo::LineStyle& style, const algo::RasterCamera& camera,
    const std::vector<float>& depth, std::vector<float>& coverage) const
{
    const int w = camera.width, h = camera.height;
    coverage.assign(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)), 0.f);
    if (!m_valid || (m_strokes.empty() && m_snakes.strokes.empty()) || w <= 0 || h <= 0
        || depth.size() != coverage.size() || !m_mesh || shape.rows() != m_mesh->vertexCount())
        return {};
    auto project = [&camera](const Eigen::Vector3f& p) {
        return Eigen::Vector3f(camera.project(p.cast<double>()).cast<float>());
    };
    // The CPU renderer's path (render.cpp), so both draw the same strokes.
    const std::vector<algo::StyledStroke> styled
        = algo::pictureStrokes(m_strokes, m_snakes.strokes.empty() ? nullptr : &m_snakes, shape, style, h, project);
    // drawStrokes reads only depth and face id: a face id of 0 marks "on the model".
    algo::GBuffer g;
    g.width = w;
    g.height = h;
    g.depth = depth;
    g.faceId.resize(depth.size());
    // GL's depth at the model's outline is that of the rim's nearer side a pixel in, where the
    // outline stroke itself would fail the depth test: within kOutlineBand pixels of the
    // background a stroke is not depth tested, as off the model.
    constexpr int kOutlineBand = 2;
    auto background = [&](int x, int y) {
        return x < 0 || y < 0 || x >= w || y >= h
            || !std::isfinite(depth[std::size_t(y) * std::size_t(w) + std::size_t(x)]);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            bool outline = background(x, y);
            for (int d = 1; d <= kOutlineBand && !outline; ++d)
                outline = background(x - d, y) || background(x + d, y) || background(x, y - d) || background(x, y + d);
            g.faceId[std::size_t(y) * std::size_t(w) + std::size_t(x)] = outline ? -1 : 0;
        }
    algo::drawStrokes(styled, g, coverage);

    float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const algo::StyledStroke& s : styled)
        for (std::size_t k = 0; k < s.points.size(); ++k) {
            const float r = 0.5f * s.widths[k] + 1.f;
            x0 = std::min(x0, s.points[k].x() - r);
            y0 = std::min(y0, s.points[k].y() - r);
            x1 = std::max(x1, s.points[k].x() + r);
            y1 = std::max(y1, s.points[k].y() + r);
        }
    if (!(x0 <= x1) || !(y0 <= y1))
        return {};
    const QRect box(QPoint(int(std::floor(std::max(x0, 0.f))), int(std::floor(std::max(y0, 0.f)))),
        QPoint(int(std::ceil(std::min(x1, float(w - 1)))), int(std::ceil(std::min(y1, float(h - 1))))));
    return box.intersected(QRect(0, 0, w, h));
}

void blendLines(QImage& image, const QPoint& origin, const std::vector<float>& coverage, int coverageWidth,
    const Eigen::Vector3f& lineColor)
{
    if (image.format() != QImage::Format_RGBA8888)
        image = image.convertToFormat(QImage::Format_RGBA8888);
    if (coverageWidth <= 0)
        return;
    const int coverageHeight = int(coverage.size() / std::size_t(coverageWidth));
    const QRect area = image.rect().translated(origin).intersected(QRect(0, 0, coverageWidth, coverageHeight));
    const auto& decode = decodeTable();
    for (int y = area.top(); y <= area.bottom(); ++y) {
        uchar* row = image.scanLine(y - origin.y());
        const float* a = coverage.data() + std::size_t(y) * std::size_t(coverageWidth);
        for (int x = area.left(); x <= area.right(); ++x) {
            const float alpha = a[x];
            if (alpha <= 0.f)
                continue;
            uchar* p = row + 4 * (x - origin.x());
            for (int c = 0; c < 3; ++c)
                p[c] = srgbByte(decode[p[c]] * (1.f - alpha) + lineColor[c] * alpha);
        }
    }
}

algo::ImageRGBA toLinear(const QImage& source)
{
    const QImage image
        = source.format() == QImage::Format_RGBA8888 ? source : source.convertToFormat(QImage::Format_RGBA8888);
    algo::ImageRGBA out(image.width(), image.height());
    const auto& decode = decodeTable();
    for (int y = 0; y < image.height(); ++y) {
        const uchar* row = image.constScanLine(y);
        float* target = out.at(0, y);
        for (int x = 0; x < image.width(); ++x) {
            for (int c = 0; c < 3; ++c)
                target[4 * x + c] = decode[row[4 * x + c]];
            target[4 * x + 3] = float(row[4 * x + 3]) / 255.f;
        }
    }
    return out;
}

QImage toSrgb(const algo::ImageRGBA& image)
{
    QImage out(image.width, image.height, QImage::Format_RGBA8888);
    for (int y = 0; y < image.height; ++y) {
        uchar* row = out.scanLine(y);
        const float* source = image.at(0, y);
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c)
                row[4 * x + c] = srgbByte(source[4 * x + c]);
            row[4 * x + 3] = 255; // the viewport is opaque
        }
    }
    return out;
}

algo::ImageRGBA composeStereo(algo::StereoOutput output, const algo::ImageRGBA& left, const algo::ImageRGBA& right,
    const algo::DuboisMatrices& dubois)
{
    switch (output) {
    case algo::StereoOutput::Anaglyph:
        return algo::composeAnaglyph(left, right);
    case algo::StereoOutput::Dubois:
        return algo::composeDubois(left, right, dubois);
    case algo::StereoOutput::HalfColor:
        return algo::composeHalfColor(left, right);
    case algo::StereoOutput::SideBySide:
        return algo::composeSideBySide(left, right);
    case algo::StereoOutput::TopBottom:
        return algo::composeTopBottom(left, right);
    case algo::StereoOutput::Off:
        break;
    }
    return left;
}

} // namespace celform::views
