// The 3D viewport: VTK 9.1 hosted in a Qt 6 QOpenGLWidget (STACK.md pitfall 5), showing the
// document's base model, with Maya-style navigation handled here rather than by a VTK interactor.
#pragma once

#include "celform/model/camera.h"

#include <QColor>
#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>
#include <QSurfaceFormat>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>

namespace celform::model {
class Document;
}

namespace celform::views {

class Viewport : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit Viewport(model::Document* document, QWidget* parent = nullptr);
    ~Viewport() override;

    /// The surface format VTK needs (OpenGL 3.2 core, depth, stencil). Must be installed with
    /// QSurfaceFormat::setDefaultFormat() before the QApplication is created.
    static QSurfaceFormat defaultFormat();

    [[nodiscard]] model::Camera camera() const;
    /// Shows the view of camera. An invalid camera (see model::Camera::isValid) is ignored.
    void setCamera(const model::Camera& camera);
    void setProjection(model::Projection projection);
    [[nodiscard]] model::Projection projection() const;

    /// What the widget shows now, in device pixels (size() * devicePixelRatio()).
    QImage renderedImage();
    /// Number of frames drawn so far; tests wait on it.
    [[nodiscard]] int renderCount() const { return m_renderCount; }

    void setBackgroundColors(const QColor& top, const QColor& bottom);

    /// Centre of the frame-all bounds, moved by panning: the point orbit turns around.
    [[nodiscard]] Eigen::Vector3d pivot() const { return m_pivot; }

public slots:
    /// Keeps the view direction and fits the whole model in the view.
    void frameAll();
    /// Front view (looking down -Z, Y up), framed.
    void resetView();

signals:
    /// Emitted after every navigation step and every programmatic camera change.
    void cameraChanged();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;

    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Dolly };

    void releaseGraphics();
    void rebuildMesh();
    void rebuildGrid();
    void updateTriadViewport();
    void syncTriadCamera();

    void orbit(double yawDegrees, double pitchDegrees);
    void pan(const QPointF& deltaPixels);
    void dolly(double factor);
    void cameraEdited();

    struct Vtk; // VTK objects, kept out of this header so that users do not pull VTK in
    model::Document* m_document;
    std::unique_ptr<Vtk> m_vtk;

    Eigen::AlignedBox3d m_bounds; ///< of the base model, or a unit box when there is none
    Eigen::Vector3d m_pivot{0.0, 0.0, 0.0};
    Drag m_drag = Drag::None;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    QPointF m_lastPos;
    int m_renderCount = 0;
    bool m_framed = false; ///< the camera is as frameAll() left it, not moved since
    bool m_initialized = false;
};

} // namespace celform::views
