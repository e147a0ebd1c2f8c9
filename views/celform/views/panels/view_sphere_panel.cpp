// Viewing-sphere panel: an orthographic QPainter drawing of the key directions, their hull and the
// blend of the current view. Everything it draws is copied from the document's BlendEvaluator
// in refresh(), so painting never touches the document.
#include "celform/views/panels/view_sphere_panel.h"

#include <Eigen/Geometry>

#include <QApplication>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QRadialGradient>
#include <QToolTip>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace celform::views {
namespace {

// Paper 1, figure 4: the hit facet in green, its keys in red.
const QColor kHitFill(46, 170, 80, 64);
const QColor kHitEdge(28, 135, 58);
const QColor kActiveKey(214, 39, 40);
const QColor kKey(52, 101, 164);
const QColor kDummy(112, 112, 112);
const QColor kFalloff(232, 128, 0);

constexpr double kKeyRadius = 4.5;
constexpr double kActiveKeyRadius = 5.5;
constexpr double kDummyRadius = 3.5;
constexpr double kPickRadius = 9.0;
/// Weights below this print as 0.00: treating them as "not taking part" keeps the red points and
/// the readout telling the same story.
constexpr double kShownWeight = 0.005;
/// Drawing of things on the far side of the sphere: present for context, never competing.
constexpr double kBackOpacity = 0.35;
constexpr double kPi = 3.14159265358979323846;
constexpr double kOrbitRadiansPerPixel = 0.012;
/// The turntable stops this close to the poles, where "up" would flip.
constexpr double kPoleMarginCos = 0.9976; // cos(4 degrees)

Eigen::Vector3d defaultViewFrom()
{
    return Eigen::Vector3d(1.0, 0.6, 1.4).normalized();
}

/// Any unit vector perpendicular to v, for degenerate up vectors.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& v)
{
    const Eigen::Vector3d axis = std::abs(v.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
    return v.cross(axis).normalized();
}

/// A one-pixel pen for the sphere's wireframe. Cosmetic pens take the raster engine's line
/// rasteriser; a 1.0-wide geometric pen (dashed above all) goes through the path stroker, which
/// made the hull the dearest part of a repaint on every played frame.
QPen cosmeticPen(const QColor& color, Qt::PenStyle style)
{
    QPen pen(color, 1.0, style);
    pen.setCosmetic(true);
    return pen;
}

} // namespace

ViewSpherePanel::ViewSpherePanel(model::Document* document, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_viewFrom(defaultViewFrom())
    , m_up(Eigen::Vector3d::UnitY())
    , m_followFrom(defaultViewFrom())
    , m_followUp(Eigen::Vector3d::UnitY())
{
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    setAccessibleName(tr("Viewing sphere"));
    setToolTip(tr("The key viewpoints on the viewing sphere and their hull. The green facet holds the current "
                  "view; its red keys are the ones being blended.\nDrag to orbit, double-click a key to edit "
                  "it, double-click empty space to reset the orientation."));
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        // Key directions, enabling and the blend settings shape the sphere; offsets do not.
        if (change.reset || change.has(model::Part::Mesh) || change.has(model::Part::Blend)
            || (change.has(model::Part::Keys) && !change.offsetsOnly))
            refresh();
    });
    refresh();
}

void ViewSpherePanel::setViewDirection(const Eigen::Vector3d& direction)
{
    const Eigen::Vector3d d = direction.allFinite() ? direction : Eigen::Vector3d::Zero();
    if (d == m_viewDirection)
        return;
    m_viewDirection = d;
    refresh();
}

void ViewSpherePanel::setOrientation(const Eigen::Vector3d& viewFrom, const Eigen::Vector3d& up)
{
    if (!viewFrom.allFinite() || viewFrom.norm() == 0.0 || !up.allFinite())
        return;
    m_followFrom = viewFrom.normalized();
    const Eigen::Vector3d side = up.cross(m_followFrom);
    m_followUp
        = side.norm() > 1e-9 ? Eigen::Vector3d(m_followFrom.cross(side).normalized()) : perpendicular(m_followFrom);
    // The user's own orbit wins until they ask to follow again (double-click on empty space).
    if (m_orbited)
        return;
    m_viewFrom = m_followFrom;
    m_up = m_followUp;
    update();
}

QSize ViewSpherePanel::sizeHint() const
{
    return {260, 260};
}

QSize ViewSpherePanel::minimumSizeHint() const
{
    return {160, 160};
}

QPointF ViewSpherePanel::screenPosition(model::ObjectId key) const
{
    if (key == 0 || m_empty != EmptyState::None)
        return {};
    const Frame f = frame();
    for (const SpherePoint& point : m_points)
        if (point.key == key)
            return project(f, point.direction);
    return {};
}

// --- state ----------------------------------------------------------------------------------

void ViewSpherePanel::refresh()
{
    m_points.clear();
    m_facets.clear();
    m_hitFacet = -1;
    m_barycentric.setZero();
    m_falloff = 1.0;
    m_baseShare = 1.0;
    m_hoverPoint = -1;

    const model::ProjectData& data = m_document->data();
    const bool anyEnabled = std::any_of(data.keys.begin(), data.keys.end(), [](const auto& k) { return k.enabled; });
    if (!m_document->hasMesh())
        m_empty = EmptyState::NoModel;
    else if (data.keys.empty())
        m_empty = EmptyState::NoKeys;
    else if (!anyEnabled)
        m_empty = EmptyState::AllKeysDisabled;
    else {
        model::BlendEvaluator& blender = m_document->blender();
        const algo::ViewSphere* sphere = blender.sphere();
        if (!sphere) {
            m_empty = EmptyState::NoHull;
        } else {
            m_empty = EmptyState::None;
            const auto& ids = blender.sphereKeys();
            const auto& points = sphere->points();
            m_points.reserve(points.size());
            for (std::size_t i = 0; i < points.size(); ++i) {
                SpherePoint point;
                point.direction = points[i].normalized();
                if (int(i) < sphere->keyCount() && i < ids.size()) {
                    point.key = ids[i];
                    const model::KeyViewpoint* key = data.key(point.key);
                    point.name = key ? key->name : QString();
                }
                m_points.push_back(std::move(point));
            }
            m_facets = sphere->facets();
            if (m_viewDirection.norm() > 0.0) {
                const model::BlendResult blend = blender.weights(data, m_viewDirection);
                // raw weights index the directions given to the sphere, i.e. its first points.
                for (const algo::KeyWeight& kw : blend.raw.weights)
                    if (kw.key >= 0 && std::size_t(kw.key) < m_points.size())
                        m_points[std::size_t(kw.key)].weight = kw.weight;
                if (blend.raw.facet >= 0 && std::size_t(blend.raw.facet) < m_facets.size())
                    m_hitFacet = blend.raw.facet;
                m_barycentric = blend.raw.barycentric;
                m_falloff = blend.raw.falloff;
                m_baseShare = blend.baseShare;
            }
        }
    }
    rebuildReadout();
    update();
}

void ViewSpherePanel::rebuildReadout()
{
    m_readout.clear();
    if (m_empty != EmptyState::None)
        return;
    std::vector<const SpherePoint*> shown;
    for (const SpherePoint& point : m_points)
        if (isActive(point))
            shown.push_back(&point);
    std::stable_sort(
        shown.begin(), shown.end(), [](const SpherePoint* a, const SpherePoint* b) { return a->weight > b->weight; });
    QStringList parts;
    const QLocale loc = locale();
    for (const SpherePoint* point : shown)
        parts << tr("%1 %2", "key name and its weight").arg(point->name, loc.toString(point->weight, 'f', 2));
    // Clamped so that rounding never shows "-0.00".
    const double base = std::clamp(m_baseShare, 0.0, 1.0);
    parts << tr("base %1", "the base model's share of the blend").arg(loc.toString(base, 'f', 2));
    m_readout = parts.join(tr(" · ", "separator between key weights"));
    setAccessibleDescription(m_readout);
}

bool ViewSpherePanel::isActive(const SpherePoint& point) const
{
    return point.key != 0 && point.weight >= kShownWeight;
}

double ViewSpherePanel::pointRadius(const SpherePoint& point) const
{
    return isActive(point) ? kActiveKeyRadius : kKeyRadius;
}

// --- geometry -------------------------------------------------------------------------------

QRectF ViewSpherePanel::readoutRect() const
{
    const QFontMetricsF fm(scaledFont(font(), 0.9));
    const double h = std::ceil(fm.height()) + 8.0;
    return QRectF(0.0, height() - h, width(), h);
}

ViewSpherePanel::Frame ViewSpherePanel::frame() const
{
    Frame f;
    // Right-handed: screen x = right, screen y = up, depth towards the viewer = viewFrom.
    f.toViewer = m_viewFrom;
    Eigen::Vector3d right = m_up.cross(m_viewFrom);
    f.right = right.norm() > 1e-9 ? Eigen::Vector3d(right.normalized()) : perpendicular(m_viewFrom);
    f.up = f.toViewer.cross(f.right);

    const QRectF area(0.0, 0.0, width(), readoutRect().top());
    // Room outside the circle for the labels of keys on the silhouette.
    const double margin = std::ceil(QFontMetricsF(scaledFont(font(), 0.85)).height()) + 6.0;
    f.centre = area.center();
    f.radius = std::max(8.0, std::min(area.width(), area.height()) / 2.0 - margin);
    return f;
}

QPointF ViewSpherePanel::project(const Frame& f, const Eigen::Vector3d& p) const
{
    return {f.centre.x() + f.radius * p.dot(f.right), f.centre.y() - f.radius * p.dot(f.up)};
}

double ViewSpherePanel::depth(const Frame& f, const Eigen::Vector3d& p) const
{
    return p.dot(f.toViewer);
}

int ViewSpherePanel::pointAt(const QPointF& pos, bool keysOnly) const
{
    if (m_empty != EmptyState::None)
        return -1;
    const Frame f = frame();
    int best = -1;
    double bestDepth = -2.0;
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        const SpherePoint& point = m_points[i];
        if (keysOnly && point.key == 0)
            continue;
        const QPointF d = project(f, point.direction) - pos;
        if (std::hypot(d.x(), d.y()) > kPickRadius)
            continue;
        // Points that overlap on screen: the one in front is the one the user sees.
        const double z = depth(f, point.direction);
        if (z > bestDepth) {
            bestDepth = z;
            best = int(i);
        }
    }
    return best;
}

// --- painting -------------------------------------------------------------------------------

void ViewSpherePanel::paintEvent(QPaintEvent*)
{
    const Frame f = frame();
    paintBackground(f);
    QPainter painter(this);
    painter.drawPixmap(0, 0, m_background);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    paintGuides(painter, f);

    if (m_empty != EmptyState::None) {
        paintEmptyHint(painter, f);
        paintAxes(painter, f);
        paintReadout(painter);
        return;
    }
    paintHull(painter, f, false);
    paintPoints(painter, f, false);
    paintHitFacet(painter, f);
    paintHull(painter, f, true);
    paintView(painter, f);
    paintPoints(painter, f, true);
    paintViewLabel(painter, f);
    paintAxes(painter, f);
    paintReadout(painter);
}

void ViewSpherePanel::paintBackground(const Frame& f) const
{
    // Kept between paints: an antialiased disc with a radial gradient is the dearest thing the
    // panel draws, and it changes only with the size, the font (the margin) and the palette.
    const qreal ratio = devicePixelRatioF();
    const QString key = QStringLiteral("%1x%2 %3 %4 %5")
                            .arg(width())
                            .arg(height())
                            .arg(ratio)
                            .arg(palette().cacheKey())
                            .arg(f.radius);
    if (key == m_backgroundKey && !m_background.isNull())
        return;
    m_backgroundKey = key;
    m_background = QPixmap(size() * ratio);
    m_background.setDevicePixelRatio(ratio);
    m_background.fill(palette().color(QPalette::Window));
    QPainter painter(&m_background);
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor base = palette().color(QPalette::Base);
    // A soft radial shade reads as a sphere without competing with the wireframe.
    QRadialGradient shade(f.centre - QPointF(0.35 * f.radius, 0.35 * f.radius), 1.45 * f.radius);
    shade.setColorAt(0.0, base);
    shade.setColorAt(1.0, base.darker(112));
    painter.setPen(QPen(palette().color(QPalette::Mid), 1.2));
    painter.setBrush(shade);
    painter.drawEllipse(f.centre, f.radius, f.radius);
}

void ViewSpherePanel::paintGuides(QPainter& painter, const Frame& f) const
{
    // The equator (normal +Y) and the meridian through front and top (normal +X) orient the
    // artist: front keys sit on the meridian, side keys on the equator.
    QColor line = palette().color(QPalette::Text);
    line.setAlphaF(0.16);
    QColor backLine = line;
    backLine.setAlphaF(0.09);
    constexpr int kSegments = 144;
    for (const Eigen::Vector3d& normal : {Eigen::Vector3d::UnitY().eval(), Eigen::Vector3d::UnitX().eval()}) {
        const Eigen::Vector3d a = perpendicular(normal);
        const Eigen::Vector3d b = normal.cross(a);
        QPolygonF run;
        bool runFront = true;
        auto flush = [&] {
            if (run.size() > 1) {
                painter.setPen(cosmeticPen(runFront ? line : backLine, runFront ? Qt::SolidLine : Qt::DotLine));
                painter.drawPolyline(run);
            }
            run.clear();
        };
        for (int i = 0; i <= kSegments; ++i) {
            const double t = 2.0 * kPi * i / kSegments;
            const Eigen::Vector3d p = std::cos(t) * a + std::sin(t) * b;
            const bool front = depth(f, p) >= 0.0;
            if (!run.isEmpty() && front != runFront) {
                const QPointF last = run.back();
                flush();
                run << last;
            }
            runFront = front;
            run << project(f, p);
        }
        flush();
    }
}

void ViewSpherePanel::paintHull(QPainter& painter, const Frame& f, bool front) const
{
    // An edge is seen from the front when either of its facets faces the viewer; hull facets of
    // sphere points face outward, so the facet's centroid orients its normal.
    std::map<std::pair<int, int>, bool> edges;
    for (const auto& facet : m_facets) {
        const Eigen::Vector3d& a = m_points[std::size_t(facet[0])].direction;
        const Eigen::Vector3d& b = m_points[std::size_t(facet[1])].direction;
        const Eigen::Vector3d& c = m_points[std::size_t(facet[2])].direction;
        Eigen::Vector3d n = (b - a).cross(c - a);
        const Eigen::Vector3d mid = (a + b + c) / 3.0;
        bool facing;
        if (std::abs(n.dot(mid)) > 1e-9) {
            if (n.dot(mid) < 0.0)
                n = -n;
            facing = depth(f, n) >= 0.0;
        } else {
            facing = depth(f, mid) >= 0.0; // a facet through the centre: no outward side
        }
        for (int i = 0; i < 3; ++i) {
            const auto edge = std::minmax(facet[std::size_t(i)], facet[std::size_t((i + 1) % 3)]);
            edges[edge] = edges[edge] || facing;
        }
    }
    QColor color = palette().color(QPalette::Text);
    color.setAlphaF(front ? 0.62 : 0.28);
    painter.setPen(cosmeticPen(color, front ? Qt::SolidLine : Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    for (const auto& [edge, facing] : edges) {
        if (facing != front)
            continue;
        painter.drawLine(project(f, m_points[std::size_t(edge.first)].direction),
            project(f, m_points[std::size_t(edge.second)].direction));
    }
}

void ViewSpherePanel::paintHitFacet(QPainter& painter, const Frame& f) const
{
    if (m_hitFacet < 0)
        return;
    const auto& facet = m_facets[std::size_t(m_hitFacet)];
    QPolygonF triangle;
    for (int index : facet)
        triangle << project(f, m_points[std::size_t(index)].direction);
    painter.setPen(QPen(kHitEdge, 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.setBrush(kHitFill);
    painter.drawPolygon(triangle);
}

void ViewSpherePanel::paintPoints(QPainter& painter, const Frame& f, bool front) const
{
    std::vector<int> order(m_points.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return depth(f, m_points[std::size_t(a)].direction) < depth(f, m_points[std::size_t(b)].direction);
    });
    const QColor base = palette().color(QPalette::Base);
    const QColor text = palette().color(QPalette::Text);
    const QFont labelFont = scaledFont(font(), 0.85);
    const std::vector<QRectF> labels = keyLabelRects(f); // once: each key's is placed off the others'
    QFont activeFont = labelFont;
    activeFont.setBold(true);

    for (int i : order) {
        const SpherePoint& point = m_points[std::size_t(i)];
        const double z = depth(f, point.direction);
        if ((z >= 0.0) != front)
            continue;
        const QPointF s = project(f, point.direction);
        painter.save();
        painter.setOpacity(front ? 1.0 : kBackOpacity);
        if (point.key == 0) {
            // A dummy is the base model seen from there: hollow, it carries no shape of its own.
            painter.setPen(QPen(kDummy, 1.4));
            painter.setBrush(base);
            painter.drawEllipse(s, kDummyRadius, kDummyRadius);
            painter.restore();
            continue;
        }
        const bool active = isActive(point);
        const double r = pointRadius(point);
        if (i == m_hoverPoint) {
            painter.setPen(QPen(palette().color(QPalette::Highlight), 2.0));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(s, r + 3.0, r + 3.0);
        }
        painter.setPen(QPen(base, 1.5));
        painter.setBrush(active ? kActiveKey : kKey);
        painter.drawEllipse(s, r, r);

        painter.setFont(active ? activeFont : labelFont);
        QString name;
        (void)keyLabelPlace(f, point, &name);
        const QRectF label = labels[std::size_t(i)];
        m_labels.draw(painter, label, name, active ? kActiveKey.darker(135) : text, base);
        painter.restore();
    }
}

void ViewSpherePanel::paintView(QPainter& painter, const Frame& f) const
{
    if (m_viewDirection.norm() == 0.0)
        return;
    const Eigen::Vector3d v = m_viewDirection.normalized();
    const QPointF s = project(f, v);
    const bool front = depth(f, v) >= 0.0;
    const bool outside = m_hitFacet < 0;
    const QColor text = palette().color(QPalette::Text);
    const QColor base = palette().color(QPalette::Base);

    // The ray from the centre to the eye (paper 1, section 3.2.1), and where it meets the facet.
    QColor ray = text;
    ray.setAlphaF(front ? 0.55 : 0.3);
    painter.setPen(cosmeticPen(ray, front ? Qt::SolidLine : Qt::DashLine));
    painter.drawLine(f.centre, s);
    if (!outside) {
        const auto& facet = m_facets[std::size_t(m_hitFacet)];
        Eigen::Vector3d hit = Eigen::Vector3d::Zero();
        for (int i = 0; i < 3; ++i)
            hit += m_barycentric[i] * m_points[std::size_t(facet[std::size_t(i)])].direction;
        painter.setPen(Qt::NoPen);
        painter.setBrush(kHitEdge);
        painter.drawEllipse(project(f, hit), 2.2, 2.2);
    }

    // The marker stays opaque even on the far side: it is what the panel is about; the dashed
    // ray says it is behind.
    painter.setPen(QPen(outside ? kFalloff.darker(130) : base, 1.5));
    painter.setBrush(outside ? kFalloff : text);
    painter.drawEllipse(s, 4.5, 4.5);
}

void ViewSpherePanel::paintViewLabel(QPainter& painter, const Frame& f) const
{
    if (m_viewDirection.norm() == 0.0)
        return;
    const bool outside = m_hitFacet < 0;
    painter.setFont(scaledFont(font(), 0.85));
    QString label;
    const QRectF box = viewLabelRect(f, &label);
    m_labels.draw(painter, box, label, outside ? kFalloff.darker(150) : palette().color(QPalette::Text),
        palette().color(QPalette::Base));
}

void ViewSpherePanel::paintAxes(QPainter& painter, const Frame& f) const
{
    // A small triad in the corner: the model's axes as the sphere is drawn now.
    constexpr double kLength = 14.0;
    const QPointF origin(22.0, readoutRect().top() - 18.0);
    struct Axis {
        Eigen::Vector3d v;
        const char* name;
    };
    std::array<Axis, 3> axes
        = {{{Eigen::Vector3d::UnitX(), "X"}, {Eigen::Vector3d::UnitY(), "Y"}, {Eigen::Vector3d::UnitZ(), "Z"}}};
    std::sort(axes.begin(), axes.end(), [&](const Axis& a, const Axis& b) { return depth(f, a.v) < depth(f, b.v); });
    painter.setFont(scaledFont(font(), 0.75));
    const QFontMetricsF fm(painter.font());
    for (const Axis& axis : axes) {
        QColor color = palette().color(QPalette::Text);
        color.setAlphaF(depth(f, axis.v) >= 0.0 ? 0.7 : 0.35);
        const QPointF tip = origin + kLength * QPointF(axis.v.dot(f.right), -axis.v.dot(f.up));
        painter.setPen(QPen(color, 1.2, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(origin, tip);
        QPointF dir = tip - origin;
        const double len = std::hypot(dir.x(), dir.y());
        dir = len > 1e-6 ? dir / len : QPointF(0.0, 0.0);
        const QString name = QString::fromLatin1(axis.name);
        QRectF box(QPointF(), QSizeF(fm.horizontalAdvance(name), fm.height()));
        box.moveCenter(tip + dir * 5.0);
        painter.drawText(box, Qt::AlignCenter, name);
    }
}

void ViewSpherePanel::paintReadout(QPainter& painter) const
{
    const QRectF r = readoutRect();
    QColor separator = palette().color(QPalette::Mid);
    separator.setAlphaF(0.6);
    painter.setPen(QPen(separator, 1.0));
    painter.drawLine(QPointF(r.left() + 4.0, r.top() + 0.5), QPointF(r.right() - 4.0, r.top() + 0.5));
    if (m_readout.isEmpty())
        return;
    painter.setFont(scaledFont(font(), 0.9));
    painter.setPen(palette().color(QPalette::WindowText));
    const QRectF text = r.adjusted(6.0, 1.0, -6.0, 0.0);
    const QString elided = painter.fontMetrics().elidedText(m_readout, Qt::ElideRight, int(text.width()));
    painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine, elided);
}

void ViewSpherePanel::paintEmptyHint(QPainter& painter, const Frame& f) const
{
    QString hint;
    switch (m_empty) {
    case EmptyState::NoModel:
        hint = tr("No base model yet: import a model to build its viewing sphere");
        break;
    case EmptyState::NoKeys:
        hint = tr("No keys yet: create a key from an aligned drawing");
        break;
    case EmptyState::AllKeysDisabled:
        hint = tr("All keys are disabled: enable a key to blend it");
        break;
    case EmptyState::NoHull:
        hint = tr("The key directions cannot be hulled: the model shows its base shape");
        break;
    case EmptyState::None:
        return;
    }
    painter.setFont(scaledFont(font(), 0.95));
    painter.setPen(palette().color(QPalette::PlaceholderText));
    // The square inscribed in the circle keeps the wrapped text inside the outline.
    const double side = f.radius * std::sqrt(2.0) - 8.0;
    QRectF box(QPointF(), QSizeF(side, side));
    box.moveCenter(f.centre);
    painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, hint);
}

// --- interaction ----------------------------------------------------------------------------

void ViewSpherePanel::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    m_pressed = true;
    m_dragging = false;
    m_pressPos = event->position().toPoint();
    m_lastDragPos = m_pressPos;
    event->accept();
}

void ViewSpherePanel::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint pos = event->position().toPoint();
    if (m_pressed && (event->buttons() & Qt::LeftButton)) {
        if (!m_dragging && (pos - m_pressPos).manhattanLength() >= QApplication::startDragDistance()) {
            m_dragging = true;
            m_orbited = true;
            setCursor(Qt::ClosedHandCursor);
            QToolTip::hideText();
        }
        if (m_dragging) {
            // Turntable about the orientation's up axis: yaw with x, pitch with y, the grabbed
            // surface following the mouse.
            const QPoint delta = pos - m_lastDragPos;
            m_lastDragPos = pos;
            const Eigen::Vector3d axis = m_up.normalized();
            m_viewFrom = Eigen::AngleAxisd(-delta.x() * kOrbitRadiansPerPixel, axis) * m_viewFrom;
            const Eigen::Vector3d right = axis.cross(m_viewFrom).normalized();
            const Eigen::Vector3d pitched = Eigen::AngleAxisd(-delta.y() * kOrbitRadiansPerPixel, right) * m_viewFrom;
            if (std::abs(pitched.dot(axis)) < kPoleMarginCos)
                m_viewFrom = pitched;
            m_viewFrom.normalize();
            update();
        }
        event->accept();
        return;
    }
    const int hover = pointAt(event->position(), true);
    if (hover != m_hoverPoint) {
        m_hoverPoint = hover;
        if (hover >= 0)
            setCursor(Qt::PointingHandCursor);
        else
            unsetCursor();
        update();
    }
    QWidget::mouseMoveEvent(event);
}

void ViewSpherePanel::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton) {
        if (m_dragging)
            unsetCursor();
        m_pressed = false;
        m_dragging = false;
        event->accept();
        return;
    }
    QWidget::mouseReleaseEvent(event);
}

void ViewSpherePanel::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseDoubleClickEvent(event);
        return;
    }
    event->accept();
    const int index = pointAt(event->position(), true);
    if (index >= 0) {
        emit keyActivated(m_points[std::size_t(index)].key);
        return;
    }
    if (pointAt(event->position(), false) >= 0)
        return; // a dummy: nothing to jump to, and not "empty space" either
    if (m_orbited) {
        m_orbited = false;
        m_viewFrom = m_followFrom;
        m_up = m_followUp;
        update();
    }
}

void ViewSpherePanel::leaveEvent(QEvent* event)
{
    if (m_hoverPoint >= 0) {
        m_hoverPoint = -1;
        unsetCursor();
        update();
    }
    QWidget::leaveEvent(event);
}

bool ViewSpherePanel::event(QEvent* event)
{
    if (event->type() != QEvent::ToolTip || m_dragging)
        return QWidget::event(event);
    auto* help = static_cast<QHelpEvent*>(event);
    const QLocale loc = locale();
    auto vectorText = [&](const Eigen::Vector3d& v) {
        return tr("(%1, %2, %3)", "a direction vector")
            .arg(loc.toString(v.x(), 'f', 2), loc.toString(v.y(), 'f', 2), loc.toString(v.z(), 'f', 2));
    };
    const int index = pointAt(help->pos(), false);
    if (index >= 0) {
        const SpherePoint& point = m_points[std::size_t(index)];
        const QString text = point.key != 0
            ? tr("<b>%1</b><br>Direction %2<br>Weight in this view: %3<br><i>Double-click to edit this key</i>")
                  .arg(point.name.toHtmlEscaped(), vectorText(point.direction), loc.toString(point.weight, 'f', 2))
            : tr("<b>Dummy key</b> %1<br>The base model, filling a view no key covers (paper 1, section 3.3)")
                  .arg(vectorText(point.direction));
        QToolTip::showText(help->globalPos(), text, this);
        return true;
    }
    if (m_empty == EmptyState::None && m_viewDirection.norm() > 0.0) {
        const QPointF s = project(frame(), m_viewDirection.normalized());
        const QPointF d = s - QPointF(help->pos());
        if (std::hypot(d.x(), d.y()) <= kPickRadius) {
            QToolTip::showText(help->globalPos(),
                tr("<b>Current view</b><br>Direction %1").arg(vectorText(m_viewDirection.normalized())), this);
            return true;
        }
    }
    return QWidget::event(event);
}

} // namespace celform::views
