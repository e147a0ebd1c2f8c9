#include "celform/views/viewport/axis_gizmo.h"

#include "celform/views/viewport/viewport.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <numeric>

namespace celform::views {
namespace {

constexpr int kSize = 84; // logical pixels
constexpr double kReach = 0.36; // axis length as a share of the size
constexpr double kDotRadius = 8.5;

const std::array<Eigen::Vector3d, 6> kAxes = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
    Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};

// Blender's axis colours.
const std::array<QColor, 3> kColours = {QColor(230, 72, 84), QColor(120, 190, 40), QColor(60, 130, 230)};

Viewport::ViewPreset presetOf(int axis)
{
    // Clicking an axis end looks at the model from that side.
    constexpr std::array<Viewport::ViewPreset, 6> presets
        = {Viewport::ViewPreset::Right, Viewport::ViewPreset::Left, Viewport::ViewPreset::Top,
            Viewport::ViewPreset::Bottom, Viewport::ViewPreset::Front, Viewport::ViewPreset::Back};
    return presets[std::size_t(axis)];
}

} // namespace

AxisGizmo::AxisGizmo(Viewport* viewport)
    : QWidget(viewport)
    , m_viewport(viewport)
{
    setObjectName(QStringLiteral("axisGizmo"));
    setFixedSize(kSize, kSize);
    setMouseTracking(true);
    setAttribute(Qt::WA_TranslucentBackground);
    setCursor(Qt::PointingHandCursor);
    setToolTip(tr("Click an axis to look at the model from that side (numeric keypad 1, 3, 7; Ctrl for the "
                  "opposite side)"));
    connect(viewport, &Viewport::cameraChanged, this, qOverload<>(&QWidget::update));
}

std::array<QPointF, 6> AxisGizmo::axisEnds() const
{
    const model::Camera camera = m_viewport->camera();
    const Eigen::Vector3d right = camera.right(), up = camera.trueUp();
    const QPointF centre(width() / 2.0, height() / 2.0);
    const double reach = kReach * kSize;
    std::array<QPointF, 6> ends;
    for (std::size_t i = 0; i < kAxes.size(); ++i)
        ends[i] = centre + QPointF(kAxes[i].dot(right), -kAxes[i].dot(up)) * reach;
    return ends;
}

std::array<double, 6> AxisGizmo::depths() const
{
    const Eigen::Vector3d forward = m_viewport->camera().forward();
    std::array<double, 6> depth;
    for (std::size_t i = 0; i < kAxes.size(); ++i)
        depth[i] = kAxes[i].dot(forward);
    return depth;
}

std::optional<int> AxisGizmo::axisAt(const QPointF& position) const
{
    const std::array<QPointF, 6> ends = axisEnds();
    const std::array<double, 6> depth = depths();
    std::optional<int> best;
    for (int i = 0; i < 6; ++i) {
        const QPointF d = ends[std::size_t(i)] - position;
        if (QPointF::dotProduct(d, d) > kDotRadius * kDotRadius)
            continue;
        if (!best || depth[std::size_t(i)] < depth[std::size_t(*best)])
            best = i;
    }
    return best;
}

void AxisGizmo::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPointF centre(width() / 2.0, height() / 2.0);
    if (m_hover >= 0) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(255, 255, 255, 40));
        painter.drawEllipse(centre, kSize / 2.0 - 1.0, kSize / 2.0 - 1.0);
    }
    const std::array<QPointF, 6> ends = axisEnds();
    const std::array<double, 6> depth = depths();
    // Far ends first, so the near ones are drawn over them.
    std::array<int, 6> order;
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return depth[std::size_t(a)] > depth[std::size_t(b)]; });
    QFont font = painter.font();
    font.setBold(true);
    font.setPixelSize(11);
    painter.setFont(font);
    for (int i : order) {
        const QColor colour = kColours[std::size_t(i / 2)];
        const bool positive = i % 2 == 0;
        const QPointF end = ends[std::size_t(i)];
        if (positive) {
            painter.setPen(QPen(colour, 2.0));
            painter.drawLine(centre, end);
        }
        QColor fill = positive ? colour : colour.darker(170);
        if (i == m_hover)
            fill = fill.lighter(140);
        painter.setPen(positive ? Qt::NoPen : QPen(colour, 1.5));
        painter.setBrush(fill);
        painter.drawEllipse(end, kDotRadius, kDotRadius);
        if (positive || i == m_hover) {
            painter.setPen(QColor(20, 20, 20));
            const QString letter = QString(QChar(u"XYZ"[i / 2]));
            painter.drawText(QRectF(end.x() - kDotRadius, end.y() - kDotRadius, 2 * kDotRadius, 2 * kDotRadius),
                Qt::AlignCenter, positive ? letter : QStringLiteral("-") + letter);
        }
    }
}

void AxisGizmo::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    if (const std::optional<int> axis = axisAt(event->position()))
        m_viewport->setViewPreset(presetOf(*axis));
    event->accept();
}

void AxisGizmo::mouseMoveEvent(QMouseEvent* event)
{
    const int hover = axisAt(event->position()).value_or(-1);
    if (hover != m_hover) {
        m_hover = hover;
        update();
    }
}

void AxisGizmo::leaveEvent(QEvent*)
{
    m_hover = -1;
    update();
}

} // namespace celform::views
