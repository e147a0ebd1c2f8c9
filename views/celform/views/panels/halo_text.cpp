// Cached halo labels (halo_text.h).
#include "celform/views/panels/halo_text.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QRectF>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

/// Room around the text for the halo's stroke (3 px wide: 1.5 px each side, rounded up).
constexpr int kPad = 2;

} // namespace

QFont scaledFont(const QFont& base, double factor)
{
    QFont font = base;
    if (font.pointSizeF() > 0)
        font.setPointSizeF(std::max(6.5, font.pointSizeF() * factor));
    else
        font.setPixelSize(std::max(9, int(std::lround(font.pixelSize() * factor))));
    return font;
}

QRectF clampInto(QRectF r, const QRectF& bounds)
{
    if (r.right() > bounds.right())
        r.moveRight(bounds.right());
    if (r.left() < bounds.left())
        r.moveLeft(bounds.left());
    if (r.bottom() > bounds.bottom())
        r.moveBottom(bounds.bottom());
    if (r.top() < bounds.top())
        r.moveTop(bounds.top());
    return r;
}

void HaloTextCache::draw(
    QPainter& painter, const QRectF& rect, const QString& text, const QColor& color, const QColor& halo)
{
    if (text.isEmpty() || rect.isEmpty())
        return;
    const QFont& font = painter.font();
    const qreal ratio = painter.device() ? painter.device()->devicePixelRatioF() : 1.0;
    // The label's look depends on the text, the font, both colours and the box's size. It is placed
    // at the nearest whole pixel, so a label that moves (the sphere turning while the timeline
    // plays) is drawn once, not once per sub-pixel phase.
    const QPointF corner(std::round(rect.left()), std::round(rect.top()));
    const QString key = text + QChar(0) + font.key() + QChar(0) + QString::number(color.rgba()) + QLatin1Char('/')
        + QString::number(halo.rgba()) + QLatin1Char('/') + QString::number(rect.width(), 'f', 1) + QLatin1Char('x')
        + QString::number(rect.height(), 'f', 1) + QLatin1Char('*') + QString::number(ratio);
    auto it = m_images.constFind(key);
    if (it == m_images.constEnd()) {
        if (m_images.size() >= kMaxImages)
            m_images.clear();
        const QSizeF logical(std::ceil(rect.width()) + 2 * kPad, std::ceil(rect.height()) + 2 * kPad);
        QImage image((logical * ratio).toSize(), QImage::Format_ARGB32_Premultiplied);
        image.setDevicePixelRatio(ratio);
        image.fill(Qt::transparent);
        QPainter p(&image);
        p.setRenderHints(painter.renderHints());
        p.setFont(font);
        const QRectF box(QPointF(kPad, kPad), rect.size());
        QPainterPath path;
        path.addText(QPointF(box.left(), box.top() + QFontMetricsF(font).ascent()), font, text);
        p.setPen(QPen(halo, 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.setPen(color);
        p.drawText(box, Qt::AlignLeft | Qt::AlignTop | Qt::TextSingleLine, text);
        p.end();
        it = m_images.insert(key, image);
    }
    painter.drawImage(corner - QPointF(kPad, kPad), *it);
}

} // namespace celform::views
