#include "celform/views/tools/brush_cursor.h"

#include <QPainter>
#include <QRadialGradient>

namespace celform::views {

BrushCursor::BrushCursor(QWidget* viewport)
    : QWidget(viewport)
{
    setObjectName(QStringLiteral("brushCursor"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_TranslucentBackground);
    setAttribute(Qt::WA_NoSystemBackground);
    hide();
}

void BrushCursor::showCircle(const QPointF& centre, double radiusPixels, algo::BrushFalloff falloff, bool resizing)
{
    m_centre = centre;
    m_radius = std::max(radiusPixels, 1.0);
    m_falloff = falloff;
    m_resizing = resizing;
    if (parentWidget())
        setGeometry(parentWidget()->rect());
    show();
    raise();
    update();
}

void BrushCursor::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    // The falloff as shading: the weight at each distance is the red's opacity, so the artist
    // sees how far the pull reaches before the stroke.
    QRadialGradient gradient(m_centre, m_radius);
    constexpr int kStops = 12;
    for (int i = 0; i <= kStops; ++i) {
        const double t = double(i) / kStops;
        const double w = algo::brushFalloff(t, 1.0, m_falloff);
        gradient.setColorAt(t, QColor(230, 60, 50, int(std::lround(90.0 * w))));
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(gradient);
    painter.drawEllipse(m_centre, m_radius, m_radius);
    // The rim in two tones, visible on light and dark shading.
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 3.0));
    painter.drawEllipse(m_centre, m_radius, m_radius);
    painter.setPen(QPen(QColor(255, 255, 255, 230), 1.2));
    painter.drawEllipse(m_centre, m_radius, m_radius);
    if (m_resizing) {
        painter.setPen(QPen(QColor(255, 255, 255, 200), 1.0, Qt::DashLine));
        painter.drawLine(m_centre, m_centre + QPointF(m_radius, 0.0));
    }
}

} // namespace celform::views
