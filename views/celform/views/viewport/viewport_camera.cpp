// Camera state lives in VTK's camera; this class only moves it the way Maya moves its views.
#include "celform/views/viewport/viewport_camera.h"

#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxElevationDegrees = 89.0; // turntable never passes over the pole

Eigen::Vector3d toEigen(const double v[3])
{
    return {v[0], v[1], v[2]};
}

double radians(double degrees)
{
    return degrees * kPi / 180.0;
}

} // namespace

ViewportCamera::ViewportCamera(vtkRenderer* renderer)
    : m_renderer(renderer)
    , m_vtk(renderer->GetActiveCamera())
{ }

void ViewportCamera::setWidgetSize(int width, int height, double devicePixelRatio)
{
    m_width = std::max(width, 1);
    m_height = std::max(height, 1);
    m_dpr = devicePixelRatio > 0 ? devicePixelRatio : 1.0;
}

void ViewportCamera::setBounds(const Eigen::AlignedBox3d& bounds)
{
    m_bounds = bounds;
    if (m_bounds.isEmpty() || !m_bounds.min().allFinite() || !m_bounds.max().allFinite())
        m_bounds = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0));
}

model::Camera ViewportCamera::camera() const
{
    model::Camera c;
    c.eye = toEigen(m_vtk->GetPosition());
    c.target = toEigen(m_vtk->GetFocalPoint());
    c.up = toEigen(m_vtk->GetViewUp());
    c.projection = m_vtk->GetParallelProjection() ? model::Projection::Orthographic : model::Projection::Perspective;
    // With a drawing shown, the stored camera's field of view spans the drawing's height, which
    // is letterboxed inside the viewport (m_frameScale >= 1): undo that here.
    c.fovYDegrees = 2.0 * std::atan(std::tan(radians(m_vtk->GetViewAngle() / 2.0)) / m_frameScale) * 180.0 / kPi;
    c.orthoHeight = 2.0 * m_vtk->GetParallelScale() / m_frameScale;
    return c;
}

bool ViewportCamera::setCamera(const model::Camera& camera)
{
    if (!camera.isValid())
        return false;
    m_vtk->SetPosition(camera.eye.data());
    m_vtk->SetFocalPoint(camera.target.data());
    m_vtk->SetViewUp(camera.up.data());
    m_vtk->SetParallelProjection(camera.projection == model::Projection::Orthographic);
    m_vtk->SetViewAngle(2.0 * std::atan(m_frameScale * std::tan(radians(camera.fovYDegrees / 2.0))) * 180.0 / kPi);
    m_vtk->SetParallelScale(m_frameScale * camera.orthoHeight / 2.0);
    // Orbit turns around the model: the point of the view axis nearest to its centre, so the
    // pivot stays on screen whatever target the camera was given.
    const Eigen::Vector3d forward = camera.forward();
    double along = (m_bounds.center() - camera.eye).dot(forward);
    if (!(along > 1e-6 * m_bounds.diagonal().norm()))
        along = (camera.target - camera.eye).norm(); // model behind the camera: turn about the target
    m_pivot = camera.eye + along * forward;
    edited();
    return true;
}

void ViewportCamera::setProjection(model::Projection projection)
{
    const bool ortho = projection == model::Projection::Orthographic;
    if (bool(m_vtk->GetParallelProjection()) == ortho)
        return;
    // Keep the size of the model at the pivot's depth, so switching does not jump.
    const double distance = (m_pivot - toEigen(m_vtk->GetPosition())).norm();
    const double halfAngle = radians(m_vtk->GetViewAngle() / 2.0);
    if (ortho)
        m_vtk->SetParallelScale(distance * std::tan(halfAngle));
    m_vtk->SetParallelProjection(ortho);
    edited();
}

model::Projection ViewportCamera::projection() const
{
    return m_vtk->GetParallelProjection() ? model::Projection::Orthographic : model::Projection::Perspective;
}

void ViewportCamera::setFrameScale(double scale)
{
    if (scale == m_frameScale)
        return;
    const model::Camera kept = camera();
    const Eigen::Vector3d pivot = m_pivot;
    const bool framed = m_framed;
    m_frameScale = scale;
    setCamera(kept);
    m_pivot = pivot;
    m_framed = framed;
}

void ViewportCamera::frameAll()
{
    const Eigen::Vector3d center = m_bounds.center();
    const double radius = std::max(0.5 * m_bounds.diagonal().norm(), 1e-6);
    Eigen::Vector3d forward = (toEigen(m_vtk->GetFocalPoint()) - toEigen(m_vtk->GetPosition())).normalized();
    if (!forward.allFinite())
        forward = -Eigen::Vector3d::UnitZ();

    // The bounding sphere must fit the narrower of the two fields of view.
    const double aspect = double(m_width) / double(m_height);
    const double halfY = radians(m_vtk->GetViewAngle() / 2.0);
    const double halfX = std::atan(std::tan(halfY) * aspect);
    const double halfMin = std::min(halfX, halfY);
    const double margin = 1.05;
    const double distance = margin * radius / std::sin(halfMin);

    const Eigen::Vector3d eye = center - distance * forward;
    m_vtk->SetFocalPoint(center.data());
    m_vtk->SetPosition(eye.data());
    m_vtk->SetParallelScale(margin * radius * std::max(1.0, 1.0 / aspect));
    m_pivot = center;
    edited();
    m_framed = true;
}

void ViewportCamera::resetView()
{
    viewFrom(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
}

void ViewportCamera::viewFrom(const Eigen::Vector3d& side, const Eigen::Vector3d& up)
{
    const Eigen::Vector3d center = m_bounds.center();
    m_vtk->SetFocalPoint(center.data());
    const Eigen::Vector3d eye = center + side;
    m_vtk->SetPosition(eye.data());
    m_vtk->SetViewUp(up.data());
    frameAll();
}

void ViewportCamera::edited()
{
    m_framed = false;
    m_vtk->OrthogonalizeViewUp();
}

void ViewportCamera::roll(double degrees)
{
    m_vtk->Roll(degrees);
    edited();
}

void ViewportCamera::orbit(double yawDegrees, double pitchDegrees)
{
    const Eigen::Vector3d eye = toEigen(m_vtk->GetPosition());
    const Eigen::Vector3d target = toEigen(m_vtk->GetFocalPoint());
    const Eigen::Vector3d up = toEigen(m_vtk->GetViewUp());
    const Eigen::Vector3d forward = (target - eye).normalized();
    const Eigen::Vector3d worldUp = Eigen::Vector3d::UnitY();

    if (m_trackball) {
        const Eigen::Vector3d right = forward.cross(up).normalized();
        const Eigen::Vector3d trueUp = right.cross(forward);
        const Eigen::Matrix3d rotation
            = (Eigen::AngleAxisd(radians(-pitchDegrees), right) * Eigen::AngleAxisd(radians(-yawDegrees), trueUp))
                  .toRotationMatrix();
        const Eigen::Vector3d newEye = m_pivot + rotation * (eye - m_pivot);
        const Eigen::Vector3d newTarget = m_pivot + rotation * (target - m_pivot);
        const Eigen::Vector3d newUp = rotation * trueUp;
        m_vtk->SetPosition(newEye.data());
        m_vtk->SetFocalPoint(newTarget.data());
        m_vtk->SetViewUp(newUp.data());
        edited();
        return;
    }

    // Turntable: yaw about the world up axis, then pitch about the camera's horizontal axis,
    // clamped by elevation so the view never rolls over the pole.
    const double elevation = std::asin(std::clamp(-forward.dot(worldUp), -1.0, 1.0)) * 180.0 / kPi;
    const double newElevation = std::clamp(elevation + pitchDegrees, -kMaxElevationDegrees, kMaxElevationDegrees);
    const double pitch = newElevation - elevation;

    const Eigen::AngleAxisd yaw(radians(-yawDegrees), worldUp);
    Eigen::Vector3d right = yaw * forward.cross(worldUp);
    if (right.norm() < 1e-9)
        right = yaw * forward.cross(up);
    const Eigen::AngleAxisd tilt(radians(-pitch), right.normalized());
    const Eigen::Matrix3d rotation = (tilt * yaw).toRotationMatrix();

    const Eigen::Vector3d newEye = m_pivot + rotation * (eye - m_pivot);
    const Eigen::Vector3d newTarget = m_pivot + rotation * (target - m_pivot);
    const Eigen::Vector3d newUp = rotation * up;
    m_vtk->SetPosition(newEye.data());
    m_vtk->SetFocalPoint(newTarget.data());
    m_vtk->SetViewUp(newUp.data());
    edited();
}

void ViewportCamera::pan(const QPointF& deltaPixels)
{
    const model::Camera c = camera();
    // World units per logical pixel at the pivot's depth, so the model follows the cursor.
    const double perPixel = worldUnitsPerPixel(m_pivot);
    const Eigen::Vector3d shift = perPixel * (-deltaPixels.x() * c.right() + deltaPixels.y() * c.trueUp());
    const Eigen::Vector3d eye = c.eye + shift;
    const Eigen::Vector3d target = c.target + shift;
    m_vtk->SetPosition(eye.data());
    m_vtk->SetFocalPoint(target.data());
    // Maya's centre of interest moves with a track: orbit then turns about what is on screen.
    m_pivot += shift;
    edited();
}

void ViewportCamera::dolly(double factor)
{
    if (!(factor > 0.0) || !std::isfinite(factor))
        return;
    if (m_vtk->GetParallelProjection()) {
        m_vtk->SetParallelScale(std::max(m_vtk->GetParallelScale() * factor, 1e-6));
        edited();
        return;
    }
    const Eigen::Vector3d eye = toEigen(m_vtk->GetPosition());
    const Eigen::Vector3d target = toEigen(m_vtk->GetFocalPoint());
    const double distance = (m_pivot - eye).norm();
    // Never reach the pivot: a zero distance would lose the view direction.
    const double minDistance = 1e-4 * std::max(m_bounds.diagonal().norm(), 1e-6);
    const double newDistance = std::max(distance * factor, minDistance);
    const Eigen::Vector3d shift = (distance - newDistance) * (m_pivot - eye).normalized();
    const Eigen::Vector3d newEye = eye + shift;
    const Eigen::Vector3d newTarget = target + shift;
    m_vtk->SetPosition(newEye.data());
    m_vtk->SetFocalPoint(newTarget.data());
    edited();
}

double ViewportCamera::worldUnitsPerPixel(const Eigen::Vector3d& point) const
{
    // From VTK's own camera: its angle spans the whole widget height, drawing or not.
    double viewHeight = 2.0 * m_vtk->GetParallelScale();
    if (!m_vtk->GetParallelProjection()) {
        const Eigen::Vector3d eye = toEigen(m_vtk->GetPosition());
        const Eigen::Vector3d forward = (toEigen(m_vtk->GetFocalPoint()) - eye).normalized();
        const double depth = (point - eye).dot(forward);
        viewHeight = 2.0 * std::max(depth, 1e-9) * std::tan(radians(m_vtk->GetViewAngle() / 2.0));
    }
    return viewHeight / double(m_height);
}

QPointF ViewportCamera::projectToWidget(const Eigen::Vector3d& point) const
{
    vtkNew<vtkCoordinate> coordinate;
    coordinate->SetCoordinateSystemToWorld();
    coordinate->SetValue(point.x(), point.y(), point.z());
    const double* display = coordinate->GetComputedDoubleDisplayValue(m_renderer);
    return {display[0] / m_dpr, m_height - display[1] / m_dpr};
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> ViewportCamera::rayThrough(const QPointF& position) const
{
    const double x = position.x() * m_dpr, y = (m_height - position.y()) * m_dpr;
    auto unproject = [&](double depth) {
        m_renderer->SetDisplayPoint(x, y, depth);
        m_renderer->DisplayToWorld();
        const double* w = m_renderer->GetWorldPoint();
        return Eigen::Vector3d(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
    };
    const Eigen::Vector3d origin = unproject(0.0);
    return {origin, (unproject(1.0) - origin).normalized()};
}

algo::RasterCamera ViewportCamera::rasterCamera(int framebufferWidth, int framebufferHeight) const
{
    algo::RasterCamera r;
    r.eye = toEigen(m_vtk->GetPosition());
    r.target = toEigen(m_vtk->GetFocalPoint());
    r.up = toEigen(m_vtk->GetViewUp());
    r.orthographic = m_vtk->GetParallelProjection() != 0;
    // VTK's own angle and scale span the whole framebuffer height (a drawing's letterbox included).
    r.fovYDegrees = m_vtk->GetViewAngle();
    r.orthoHeight = 2.0 * m_vtk->GetParallelScale();
    r.width = framebufferWidth;
    r.height = framebufferHeight;
    // vtkCamera's window centre puts the view axis at NDC -x; RasterCamera's shift is in widths.
    r.horizontalShift = -0.5 * m_vtk->GetWindowCenter()[0];
    return r;
}

} // namespace celform::views
