// The brush circle under the cursor (as Blender's and Krita's): the radius on the surface at the
// point under the cursor, with the falloff curve drawn as shading inside it. A child widget over
// the viewport that lets every mouse event through.
#pragma once

#include "celform/algorithms/brush.h"

#include <QWidget>

namespace celform::views {

class BrushCursor : public QWidget {
    Q_OBJECT
public:
    explicit BrushCursor(QWidget* viewport);

    /// Shows the circle at centre (widget pixels) with a radius in pixels; resizing draws the
    /// radius line of F-resize.
    void showCircle(const QPointF& centre, double radiusPixels, algo::BrushFalloff falloff, bool resizing = false);
    [[nodiscard]] QPointF centre() const { return m_centre; }
    [[nodiscard]] double radiusPixels() const { return m_radius; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QPointF m_centre;
    double m_radius = 0.0;
    algo::BrushFalloff m_falloff = algo::BrushFalloff::Paper;
    bool m_resizing = false;
};

} // namespace celform::views
