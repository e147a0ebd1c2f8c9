// The viewing-sphere panel (paper 1, section 3.2.1 and figure 4): the enabled keys' directions as
// points on the unit sphere, their convex hull in wireframe, and the facet and keys that the
// current view blends, so an artist can see why the model looks the way it does from here.
#pragma once

#include "celform/model/document/document.h"
#include "celform/views/panels/halo_text.h"

#include <Eigen/Core>

#include <QPixmap>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QWidget>

#include <array>
#include <vector>

namespace celform::views {

class ViewSpherePanel : public QWidget {
    Q_OBJECT
public:
    explicit ViewSpherePanel(model::Document* document, QWidget* parent = nullptr);

    /// The current view direction (unit, from the model centroid towards the eye), e.g. from the
    /// viewport camera. Zero hides the view marker.
    void setViewDirection(const Eigen::Vector3d& direction);
    [[nodiscard]] Eigen::Vector3d viewDirection() const { return m_viewDirection; }

    /// The camera orientation used to draw the sphere: the sphere is drawn as seen from
    /// `viewFrom` (unit) with `up`. Ignored while the user has orbited the sphere by dragging,
    /// until a double-click on empty space returns to this orientation.
    void setOrientation(const Eigen::Vector3d& viewFrom, const Eigen::Vector3d& up);
    /// The orientation the sphere is drawn with now (after any orbiting by the user).
    [[nodiscard]] Eigen::Vector3d drawnViewFrom() const { return m_viewFrom; }
    [[nodiscard]] bool isOrbitedByUser() const { return m_orbited; }

    /// The weights line shown at the bottom, unelided ("front 0.62 · side 0.38 · base 0.00");
    /// empty when there is nothing to blend.
    [[nodiscard]] QString readout() const { return m_readout; }
    /// Where a key's point is drawn, in widget coordinates; a null point when the key is not on
    /// the sphere (unknown or disabled). Used for tooltips, picking and tests.
    [[nodiscard]] QPointF screenPosition(model::ObjectId key) const;
    /// Where the labels are painted, in widget coordinates: every key's on the sphere, then the
    /// view marker's (when there is a view). Used for tests.
    [[nodiscard]] std::vector<QRectF> labelRects() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    /// The user double-clicked a key's point: the editor can jump to that key.
    void keyActivated(celform::model::ObjectId key);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;

private:
    /// What the panel shows instead of a sphere with keys.
    enum class EmptyState { None, NoModel, NoKeys, AllKeysDisabled, NoHull };

    /// One point of the hull as drawn: a key (id != 0) or a dummy.
    struct SpherePoint {
        Eigen::Vector3d direction;
        model::ObjectId key = 0;
        QString name;
        double weight = 0.0;
    };

    /// Screen placement of the sphere, recomputed from the widget size.
    struct Frame {
        Eigen::Vector3d right, up, toViewer;
        QPointF centre;
        double radius = 1.0;
    };

    /// Copies what the painter needs from the document's evaluator: the evaluator may rebuild
    /// its sphere behind our back when someone else asks for it.
    void refresh();
    void rebuildReadout();
    [[nodiscard]] Frame frame() const;
    [[nodiscard]] QRectF readoutRect() const;
    [[nodiscard]] QPointF project(const Frame& f, const Eigen::Vector3d& p) const;
    [[nodiscard]] double depth(const Frame& f, const Eigen::Vector3d& p) const;
    /// Index into m_points of the point under pos, preferring the one nearest the viewer; -1.
    [[nodiscard]] int pointAt(const QPointF& pos, bool keysOnly) const;
    [[nodiscard]] bool isActive(const SpherePoint& point) const;
    /// The radius a key's point is drawn with (larger when it takes part in the blend).
    [[nodiscard]] double pointRadius(const SpherePoint& point) const;

    /// Renders m_background (window colour and the shaded disc) when the size or palette changed.
    void paintBackground(const Frame& f) const;
    void paintGuides(QPainter& painter, const Frame& f) const;
    void paintHull(QPainter& painter, const Frame& f, bool front) const;
    void paintHitFacet(QPainter& painter, const Frame& f) const;
    void paintPoints(QPainter& painter, const Frame& f, bool front) const;
    void paintView(QPainter& painter, const Frame& f) const;
    /// The view marker's label, painted last so no key's dot or label covers it.
    void paintViewLabel(QPainter& painter, const Frame& f) const;
    void paintAxes(QPainter& painter, const Frame& f) const;
    void paintReadout(QPainter& painter) const;
    void paintEmptyHint(QPainter& painter, const Frame& f) const;
    /// Where labels may go: the panel less a margin, above the readout.
    [[nodiscard]] QRectF labelBounds() const;
    /// A key's label box (its text, elided to fit, in text when given).
    /// Every key's label rectangle, by point index (empty for dummies), kept off each other.
    [[nodiscard]] std::vector<QRectF> keyLabelRects(const Frame& f) const;
    /// Where a key's label goes on its own, and its text (elided to fit); keyLabelRects then keeps
    /// it off the earlier keys'.
    [[nodiscard]] QRectF keyLabelPlace(const Frame& f, const SpherePoint& point, QString* text) const;
    /// The view marker's label box, clear of the keys' labels where there is room.
    [[nodiscard]] QRectF viewLabelRect(const Frame& f, QString* text) const;

    model::Document* m_document;

    Eigen::Vector3d m_viewDirection{0.0, 0.0, 1.0};
    Eigen::Vector3d m_viewFrom;
    Eigen::Vector3d m_up;
    Eigen::Vector3d m_followFrom;
    Eigen::Vector3d m_followUp;
    bool m_orbited = false;

    EmptyState m_empty = EmptyState::NoModel;
    std::vector<SpherePoint> m_points;
    std::vector<std::array<int, 3>> m_facets;
    int m_hitFacet = -1;
    Eigen::Vector3d m_barycentric = Eigen::Vector3d::Zero();
    double m_falloff = 1.0;
    double m_baseShare = 1.0;
    QString m_readout;

    /// Key and view labels, drawn once and blitted (the panel repaints on every played frame).
    mutable HaloTextCache m_labels;
    /// The window colour and the shaded disc of the sphere, which only the size and palette change.
    mutable QPixmap m_background;
    mutable QString m_backgroundKey;

    int m_hoverPoint = -1;
    QPoint m_pressPos;
    QPoint m_lastDragPos;
    bool m_pressed = false;
    bool m_dragging = false;
};

} // namespace celform::views
