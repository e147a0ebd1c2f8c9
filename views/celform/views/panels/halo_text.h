// Labels with a halo in the background colour, so they stay readable over lines (the Viewing
// Sphere's key names). Stroking a glyph outline is the dear part of such a label: QPainterPath
// loads each glyph's outline from FreeType on every call. A panel that repaints on every played
// frame keeps its labels here, drawn once per text, font, colours and pixel ratio, and blits them.
#pragma once

#include <QColor>
#include <QFont>
#include <QHash>
#include <QImage>
#include <QString>

#include <QRectF>

class QPainter;

namespace celform::views {

/// base scaled by factor (a label's font smaller than the panel's), never below a legible size.
[[nodiscard]] QFont scaledFont(const QFont& base, double factor);
/// Moves r inside bounds (as far as it fits).
[[nodiscard]] QRectF clampInto(QRectF r, const QRectF& bounds);

class HaloTextCache {
public:
    /// Draws text left-aligned at the top of rect (clipped to it, as QPainter::drawText does) in
    /// color over a 3-pixel halo in halo, with the painter's font and opacity.
    void draw(QPainter& painter, const QRectF& rect, const QString& text, const QColor& color, const QColor& halo);
    void clear() { m_images.clear(); }

private:
    /// Past this many labels the cache starts again (a label with a changing number in it).
    static constexpr qsizetype kMaxImages = 64;
    QHash<QString, QImage> m_images;
};

} // namespace celform::views
