// The outline-only view of a reference drawing while aligning: only the pixels where the drawing
// changes (its ink lines and the edge of its silhouette) are kept, in one vivid colour, so the
// model shows through everywhere else and the artist sees the contours meet.
#pragma once

#include <QColor>
#include <QImage>

namespace celform::views {

/// Pixels whose luminance or alpha differs from a 4-neighbour's by more than a quarter of the
/// range, widened by one pixel, in colour; everything else transparent. ARGB32 premultiplied.
QImage drawingOutline(const QImage& drawing, const QColor& colour = QColor(255, 0, 170));

} // namespace celform::views
