// Drawing thumbnails for the Scene tree and the Properties panel: the image over a neutral checker,
// so that white-on-transparent line art (a scanned drawing with its paper keyed out) still shows.
#pragma once

#include <QImage>
#include <QPainter>
#include <QPixmap>

#include <algorithm>
#include <cstdlib>

namespace celform::views {

/// The image scaled to fit size (aspect kept) over a grey checker of 4-pixel squares, with a thin
/// frame. Each thumbnail pixel keeps the most contrasting pixel of the block it covers (over mid
/// grey), not their average: thin ink lines on white paper and white lines on transparency both
/// survive a 40-fold reduction, where smooth scaling fades them to the paper's colour.
inline QPixmap drawingThumbnail(const QImage& image, const QSize& size)
{
    const QSize target = image.size().scaled(size, Qt::KeepAspectRatio).expandedTo(QSize(1, 1));
    const QImage source = image.convertToFormat(QImage::Format_ARGB32);
    QImage out(target, QImage::Format_ARGB32);
    const int square = 4;
    for (int ty = 0; ty < target.height(); ++ty) {
        const int y0 = ty * source.height() / target.height();
        const int y1 = std::max(y0 + 1, (ty + 1) * source.height() / target.height());
        auto* row = reinterpret_cast<QRgb*>(out.scanLine(ty));
        for (int tx = 0; tx < target.width(); ++tx) {
            const int x0 = tx * source.width() / target.width();
            const int x1 = std::max(x0 + 1, (tx + 1) * source.width() / target.width());
            int best = -1;
            QRgb chosen = 0;
            for (int y = y0; y < y1; ++y) {
                const auto* in = reinterpret_cast<const QRgb*>(source.constScanLine(y));
                for (int x = x0; x < x1; ++x) {
                    const QRgb p = in[x];
                    const int a = qAlpha(p);
                    const int lum = (qRed(p) * 54 + qGreen(p) * 183 + qBlue(p) * 19) >> 8;
                    const int contrast = std::abs(lum - 128) * a / 255;
                    if (contrast > best) {
                        best = contrast;
                        chosen = p;
                    }
                }
            }
            const QColor under = ((tx + ty) / square) % 2 ? QColor(150, 150, 150) : QColor(110, 110, 110);
            const int a = qAlpha(chosen);
            auto mix = [a](int top, int bottom) { return (top * a + bottom * (255 - a)) / 255; };
            row[tx] = qRgb(
                mix(qRed(chosen), under.red()), mix(qGreen(chosen), under.green()), mix(qBlue(chosen), under.blue()));
        }
    }
    QPainter frame(&out);
    frame.setPen(QColor(90, 90, 90));
    frame.drawRect(out.rect().adjusted(0, 0, -1, -1));
    frame.end();
    return QPixmap::fromImage(out);
}

} // namespace celform::views
