// Where the Viewing Sphere's labels go (view_sphere_panel.h): a key's name radially outside its
// point, the view marker's below its dot unless a key's label is there.
#include "celform/views/panels/view_sphere_panel.h"

#include <QFontMetricsF>
#include <QLocale>

#include <algorithm>
#include <cmath>

namespace celform::views {

QRectF ViewSpherePanel::labelBounds() const
{
    return QRectF(rect()).adjusted(2.0, 2.0, -2.0, 0.0).intersected(QRectF(0.0, 0.0, width(), readoutRect().top()));
}

QRectF ViewSpherePanel::keyLabelRect(const Frame& f, const SpherePoint& point, QString* text) const
{
    QFont labelFont = scaledFont(font(), 0.85);
    labelFont.setBold(isActive(point));
    const double r = pointRadius(point);
    const QPointF s = project(f, point.direction);
    const QRectF bounds = labelBounds();
    // The label sits radially outside the point, where the hull's edges are fewest.
    const QFontMetricsF fm(labelFont);
    const QSizeF size(fm.horizontalAdvance(point.name) + 1.0, fm.height());
    QPointF dir = s - f.centre;
    const double len = std::hypot(dir.x(), dir.y());
    dir = len > 0.15 * f.radius ? dir / len : QPointF(0.7071, -0.7071);
    const QPointF anchor = s + dir * (r + 3.0);
    // On the outer side when it fits there, else on the roomier side, shortened with "…" when
    // even that is too narrow: a label is never cut by the panel's edge.
    const double roomRight = bounds.right() - anchor.x(), roomLeft = anchor.x() - bounds.left();
    bool right = dir.x() >= -0.2;
    if (size.width() > (right ? roomRight : roomLeft))
        right = roomRight >= roomLeft;
    const double room = std::max(0.0, right ? roomRight : roomLeft);
    if (text)
        *text = size.width() <= room ? point.name : fm.elidedText(point.name, Qt::ElideRight, room - 1.0);
    QRectF label(QPointF(), QSizeF(std::min(size.width(), room), size.height()));
    label.moveTop(anchor.y() - size.height() / 2.0 + dir.y() * size.height() / 2.0);
    if (right)
        label.moveLeft(anchor.x() + (std::abs(dir.x()) < 0.2 ? 2.0 : 0.0));
    else
        label.moveRight(anchor.x());
    return clampInto(label, bounds);
}

QRectF ViewSpherePanel::viewLabelRect(const Frame& f, QString* text) const
{
    const Eigen::Vector3d v = m_viewDirection.normalized();
    const QPointF s = project(f, v);
    const bool outside = m_hitFacet < 0;
    const QFontMetricsF fm(scaledFont(font(), 0.85));
    // Paper 1, section 3.3: outside the keys' coverage the blend fades to the base model by c.
    const QString label = outside ? tr("view · falloff c = %1", "marker of the current view outside the keys")
                                        .arg(locale().toString(m_falloff, 'f', 2))
                                  : tr("view", "marker of the current view direction");
    if (text)
        *text = label;
    // Below the dot, running towards the centre: key labels sit radially outside their points,
    // so this side is usually the free one; when a key's label is there (the view near a key),
    // above, then beside the dot.
    QRectF box(QPointF(), QSizeF(fm.horizontalAdvance(label) + 1.0, fm.height()));
    const double dx = s.x() - f.centre.x();
    box.moveTop(s.y() + 6.0);
    if (std::abs(dx) < 0.25 * f.radius)
        box.moveLeft(s.x() - box.width() / 2.0);
    else if (dx > 0.0)
        box.moveRight(s.x() + 6.0);
    else
        box.moveLeft(s.x() - 6.0);
    const QRectF bounds(2.0, 2.0, width() - 4.0, readoutRect().top() - 2.0);
    QRectF above = box, right = box, left = box;
    above.moveBottom(s.y() - 6.0);
    right.moveLeft(s.x() + 8.0);
    right.moveTop(s.y() - box.height() / 2.0);
    left.moveRight(s.x() - 8.0);
    left.moveTop(right.top());
    const QRectF first = clampInto(box, bounds);
    for (const QRectF& candidate :
        {first, clampInto(above, bounds), clampInto(right, bounds), clampInto(left, bounds)}) {
        const bool free = std::none_of(m_points.begin(), m_points.end(), [&](const SpherePoint& point) {
            return point.key != 0 && keyLabelRect(f, point, nullptr).intersects(candidate);
        });
        if (free)
            return candidate;
    }
    return first;
}

std::vector<QRectF> ViewSpherePanel::labelRects() const
{
    std::vector<QRectF> rects;
    if (m_empty != EmptyState::None)
        return rects;
    const Frame f = frame();
    for (const SpherePoint& point : m_points)
        if (point.key != 0)
            rects.push_back(keyLabelRect(f, point, nullptr));
    if (m_viewDirection.norm() > 0.0)
        rects.push_back(viewLabelRect(f, nullptr));
    return rects;
}

} // namespace celform::views
