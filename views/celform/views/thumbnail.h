// Drawing thumbnails for the Scene tree and the Properties panel: the image over a neutral checker,
// so that white-on-transparent line art (a scanned drawing with its paper keyed out) still shows.
#pragma once

#include <QImage>
#include <QPainter>
#include <QPixmap>

namespace celform::views {

/// The image scaled to fit size (aspect kept) over a light grey checker of 4-pixel squares.
inline QPixmap drawingThumbnail(const QImage& image, const QSize& size)
{
    const QImage scaled = image.scaled(size, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QPixmap out(scaled.size().isEmpty() ? size : scaled.size());
    QPainter p(&out);
    const int square = 4;
    for (int y = 0; y < out.height(); y += square)
        for (int x = 0; x < out.width(); x += square)
            p.fillRect(x, y, square, square, ((x + y) / square) % 2 ? QColor(150, 150, 150) : QColor(110, 110, 110));
    p.drawImage(0, 0, scaled);
    return out;
}

} // namespace celform::views
