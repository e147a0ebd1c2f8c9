// The light gizmo's drag: the handle follows the cursor on its sphere; Document::setLight stores it.
#include "celform/views/tools/light_tool.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_display.h"

#include <QLineF>

#include <cmath>

namespace celform::views {
namespace {

constexpr double kGrabPixels = 14.0;

} // namespace

bool LightTool::press(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !document->hasMesh() || !m_viewport->display().lightGizmoShown()
        || !(event.modifiers & Qt::ControlModifier)
        || QLineF(m_viewport->projectToWidget(m_viewport->display().lightGizmoHandle()), event.position).length()
            > kGrabPixels)
        return false;
    return openGesture();
}

void LightTool::move(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !inGesture())
        return;
    const auto [origin, direction] = m_viewport->rayThrough(event.position);
    if (!direction.allFinite())
        return;
    // The handle moves on a sphere about the model's centre: the arrow tip's for a directional
    // light, the light's own distance for a point light. It stays on the side (towards or away
    // from the viewer) it was on; off the sphere it follows the silhouette.
    model::Light light = document->data().look.lightAt(document->currentFrame()); // the track's, when keyed
    const Eigen::Vector3d centre = m_viewport->modelCentre();
    const Eigen::Vector3d handle = m_viewport->display().lightGizmoHandle();
    double radius = (handle - centre).norm();
    if (!(radius > 1e-9))
        radius = m_viewport->display().lightGizmoRadius();
    const double along = (centre - origin).dot(direction);
    const Eigen::Vector3d closest = origin + along * direction;
    const double miss2 = (closest - centre).squaredNorm();
    Eigen::Vector3d onSphere;
    if (miss2 <= radius * radius) {
        const double half = std::sqrt(radius * radius - miss2);
        const bool front = (handle - centre).dot(-direction) >= 0.0;
        onSphere = closest + (front ? -half : half) * direction;
    } else {
        onSphere = centre + radius * (closest - centre).normalized();
    }
    const Eigen::Vector3d unit = (onSphere - centre).normalized();
    if (!unit.allFinite())
        return;
    light.vector = light.type == model::LightType::Point ? Eigen::Vector3d(centre + radius * unit) : unit;
    document->look().setLight(light, gesture());
}

} // namespace celform::views
