// The lines of a reference drawing: only the pixels where the drawing changes (its ink lines and
// the edge of its silhouette) are kept, in one vivid colour, so the model shows through everywhere
// else. The outline mode shows these when no outline can be extracted from the drawing (the
// extracted outline, what Fit to Drawing aims at, otherwise).
#pragma once

#include <QColor>
#include <QImage>

namespace celform::views {

/// Pixels whose luminance or alpha differs from a 4-neighbour's by more than a quarter of the
/// range, widened by one pixel, in colour; everything else transparent. ARGB32 premultiplied.
QImage drawingEdges(const QImage& drawing, const QColor& colour = QColor(255, 0, 170));

} // namespace celform::views
