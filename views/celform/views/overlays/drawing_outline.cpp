// The lines of a reference drawing (drawing_outline.h).
#include "celform/views/overlays/drawing_outline.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace celform::views {

QImage drawingEdges(const QImage& drawing, const QColor& colour)
{
    if (drawing.isNull())
        return {};
    const QImage source = drawing.convertToFormat(QImage::Format_ARGB32);
    const int w = source.width(), h = source.height();
    // Luminance and alpha on one scale (transparent pixels count as white paper), 0..255.
    std::vector<std::uint8_t> lum(std::size_t(w) * std::size_t(h)), alpha(lum.size());
    for (int y = 0; y < h; ++y) {
        const auto* row = reinterpret_cast<const QRgb*>(source.constScanLine(y));
        for (int x = 0; x < w; ++x) {
            const QRgb p = row[x];
            const int a = qAlpha(p);
            const int l = (qRed(p) * 54 + qGreen(p) * 183 + qBlue(p) * 19) >> 8;
            lum[std::size_t(y) * std::size_t(w) + std::size_t(x)] = std::uint8_t((l * a + 255 * (255 - a)) / 255);
            alpha[std::size_t(y) * std::size_t(w) + std::size_t(x)] = std::uint8_t(a);
        }
    }
    constexpr int kThreshold = 64;
    std::vector<std::uint8_t> edge(lum.size(), 0);
    auto differs = [&](std::size_t a, std::size_t b) {
        return std::abs(int(lum[a]) - int(lum[b])) > kThreshold || std::abs(int(alpha[a]) - int(alpha[b])) > kThreshold;
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            // Dark ink is an outline already; so is any jump to the right or below.
            const bool ink = alpha[i] > 128 && lum[i] < 96;
            const bool jump = (x + 1 < w && differs(i, i + 1)) || (y + 1 < h && differs(i, i + std::size_t(w)));
            if (ink || jump)
                edge[i] = 1;
        }
    }
    QImage out(w, h, QImage::Format_ARGB32_Premultiplied);
    out.fill(Qt::transparent);
    const QRgb ink = colour.rgba();
    for (int y = 0; y < h; ++y) {
        auto* row = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < w; ++x) {
            // One pixel wider, so thin lines stay visible when the drawing is scaled down.
            bool on = false;
            for (int dy = -1; dy <= 1 && !on; ++dy)
                for (int dx = -1; dx <= 1 && !on; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    on = xx >= 0 && yy >= 0 && xx < w && yy < h
                        && edge[std::size_t(yy) * std::size_t(w) + std::size_t(xx)];
                }
            if (on)
                row[x] = ink;
        }
    }
    return out;
}

} // namespace celform::views
