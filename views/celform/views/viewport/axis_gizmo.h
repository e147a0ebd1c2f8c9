// The axis gizmo in the viewport's corner (Blender's navigation gizmo): the model's X, Y and Z
// axes as the camera sees them; a click on an axis end looks at the model from that side.
#pragma once

#include <QWidget>

#include <Eigen/Core>

#include <array>
#include <optional>

namespace celform::views {

class Viewport;

class AxisGizmo : public QWidget {
    Q_OBJECT
public:
    explicit AxisGizmo(Viewport* viewport);

    /// The six axis ends in widget coordinates, in the order +X, -X, +Y, -Y, +Z, -Z.
    [[nodiscard]] std::array<QPointF, 6> axisEnds() const;
    /// The axis end under a widget position (index as in axisEnds()), the nearest one in front.
    [[nodiscard]] std::optional<int> axisAt(const QPointF& position) const;

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    /// Each axis end's depth along the view direction (positive: away from the viewer).
    [[nodiscard]] std::array<double, 6> depths() const;

    Viewport* m_viewport;
    int m_hover = -1;
};

} // namespace celform::views
