// Where the Viewing Sphere's labels go (view_sphere_panel.h): a key's name radially outside its
// point, the view marker's below its dot unless a key's label is there.
#include "celform/views/panels/view_sphere_panel.h"

#include <QFontMetricsF>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace celform::views {

QRectF ViewSpherePanel::labelBounds() const
{
    return QRectF(rect()).adjusted(2.0, 2.0, -2.0, 0.0).intersected(QRectF(0.0, 0.0, width(), readoutRect().top()));
}

std::vector<QRectF> ViewSpherePanel::keyLabelRects(const Frame& f) const
{
    // Keys that fall close on screen (two keys a right angle apart seen along their bisector) would
    // print their names over each other: each key's label steps down, or up, off the labels of the
    // keys before it (in the points' order, so painting and hit tests agree). One pass for all.
    const QRectF bounds = labelBounds();
    std::vector<QRectF> rects(m_points.size());
    std::vector<QRectF> placed;
    auto free = [&](const QRectF& r) {
        return std::none_of(placed.begin(), placed.end(), [&](const QRectF& e) { return e.intersects(r); });
    };
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        if (m_points[i].key == 0)
            continue;
        const QRectF preferred = keyLabelPlace(f, m_points[i], nullptr);
        QRectF result = preferred;
        for (int step = 1; step <= 4 && !free(result); ++step)
            for (const double sign : {1.0, -1.0}) {
                const QRectF moved
                    = clampInto(preferred.translated(0.0, sign * step * (preferred.height() + 1.0)), bounds);
                if (free(moved)) {
                    result = moved;
                    break;
                }
            }
        if (!free(result))
            result = preferred;
        rects[i] = result;
        placed.push_back(result);
    }
    return rects;
}

QRectF ViewSpherePanel::keyLabelPlace(const Frame& f, const SpherePoint& point, QString* text) const
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
    QRectF farBelow = box, farAbove = above;
    farBelow.moveTop(s.y() + 8.0 + box.height());
    farAbove.moveBottom(s.y() - 8.0 - box.height());
    // The candidates in order of preference; the first free of every key's label and dot wins (a
    // dot over "view" read as "ew"), else the one covering the least of them, labels counting most.
    std::vector<QRectF> labels = keyLabelRects(f), dots;
    for (const SpherePoint& point : m_points) {
        if (point.key == 0)
            continue;
        const double r = pointRadius(point) + 1.5;
        const QPointF p = project(f, point.direction);
        dots.emplace_back(p.x() - r, p.y() - r, 2.0 * r, 2.0 * r);
    }
    auto area = [](const QRectF& a, const QRectF& b) {
        const QRectF common = a.intersected(b);
        return common.isEmpty() ? 0.0 : common.width() * common.height();
    };
    QRectF best;
    double bestCost = std::numeric_limits<double>::infinity();
    for (const QRectF& candidate : {box, above, right, left, farBelow, farAbove}) {
        const QRectF placed = clampInto(candidate, bounds);
        double cost = 0.0;
        for (const QRectF& l : labels)
            cost += 10.0 * area(l, placed);
        for (const QRectF& d : dots)
            cost += area(d, placed);
        if (cost == 0.0)
            return placed;
        if (cost < bestCost) {
            bestCost = cost;
            best = placed;
        }
    }
    return best;
}

std::vector<QRectF> ViewSpherePanel::labelRects() const
{
    std::vector<QRectF> rects;
    if (m_empty != EmptyState::None)
        return rects;
    const Frame f = frame();
    const std::vector<QRectF> keys = keyLabelRects(f);
    for (std::size_t i = 0; i < m_points.size(); ++i)
        if (m_points[i].key != 0)
            rects.push_back(keys[i]);
    if (m_viewDirection.norm() > 0.0)
        rects.push_back(viewLabelRect(f, nullptr));
    return rects;
}

} // namespace celform::views
