// The viewport's camera and Maya-style navigation (turntable orbit about a pivot, pan, dolly,
// roll), over the VTK camera of the model layer. A reference drawing letterboxed in the view
// widens VTK's angle by the frame scale; camera() and setCamera() undo that, so a camera stored
// with a drawing frames the drawing exactly.
#pragma once

#include "celform/algorithms/raster.h"
#include "celform/model/data/camera.h"

#include <QPointF>

#include <Eigen/Geometry>

class vtkCamera;
class vtkRenderer;

namespace celform::views {

class ViewportCamera {
public:
    explicit ViewportCamera(vtkRenderer* renderer);

    /// Widget size in logical pixels and the device pixel ratio.
    void setWidgetSize(int width, int height, double devicePixelRatio);
    /// The model's bounds: framing, the pivot's default and the dolly limit.
    void setBounds(const Eigen::AlignedBox3d& bounds);
    [[nodiscard]] const Eigen::AlignedBox3d& bounds() const { return m_bounds; }

    [[nodiscard]] model::Camera camera() const;
    /// Shows the view of camera; an invalid camera is ignored (returns false).
    bool setCamera(const model::Camera& camera);
    void setProjection(model::Projection projection);
    [[nodiscard]] model::Projection projection() const;
    /// widget height / drawing height on screen (>= 1); changing it keeps the stored camera.
    void setFrameScale(double scale);
    [[nodiscard]] double frameScale() const { return m_frameScale; }

    /// Keeps the view direction and fits the whole model in the view.
    void frameAll();
    /// Front view (looking down -Z, Y up), framed.
    void resetView();
    /// Looks at the model's centre from the side `side` (unit, model space) with `up`, framed.
    void viewFrom(const Eigen::Vector3d& side, const Eigen::Vector3d& up);
    /// Whether the camera is as frameAll() left it (not moved since): resizes keep it framed.
    [[nodiscard]] bool isFramed() const { return m_framed; }

    /// Turntable (the default): yaw about the world's up axis, pitch clamped short of the poles.
    /// Trackball: yaw about the view's up and pitch about its right, free to roll over.
    void orbit(double yawDegrees, double pitchDegrees);
    void setTrackball(bool on) { m_trackball = on; }
    [[nodiscard]] bool isTrackball() const { return m_trackball; }
    void pan(const QPointF& deltaPixels);
    void dolly(double factor);
    void roll(double degrees);
    /// After any change: keeps VTK's up vector orthogonal and clears "framed".
    void edited();

    /// The point orbit turns around (the framed centre, moved by panning).
    [[nodiscard]] Eigen::Vector3d pivot() const { return m_pivot; }
    /// Maya's tumble pivot: orbit turns around this point from now on (the view does not move).
    void setPivot(const Eigen::Vector3d& pivot) { m_pivot = pivot; }
    /// World units per logical pixel at a point's depth.
    [[nodiscard]] double worldUnitsPerPixel(const Eigen::Vector3d& point) const;
    /// A model point in widget coordinates (logical pixels, y down).
    [[nodiscard]] QPointF projectToWidget(const Eigen::Vector3d& point) const;
    /// The ray through a widget position: origin on the near plane and unit direction.
    [[nodiscard]] std::pair<Eigen::Vector3d, Eigen::Vector3d> rayThrough(const QPointF& position) const;
    /// The projection VTK uses now, as a raster camera of the framebuffer's size (drawing
    /// letterbox included).
    [[nodiscard]] algo::RasterCamera rasterCamera(int framebufferWidth, int framebufferHeight) const;

private:
    vtkRenderer* m_renderer;
    vtkCamera* m_vtk;
    Eigen::AlignedBox3d m_bounds{Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0)};
    Eigen::Vector3d m_pivot{0.0, 0.0, 0.0};
    double m_frameScale = 1.0;
    bool m_framed = false;
    bool m_trackball = false;
    int m_width = 1;
    int m_height = 1;
    double m_dpr = 1.0;
};

} // namespace celform::views
