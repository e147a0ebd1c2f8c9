// The viewport's drawing options (viewport_display.h).
#include "celform/views/viewport/viewport_display.h"

#include "celform/algorithms/subdivision.h"
#include "celform/model/document/document.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/viewport_camera.h"

#include <algorithm>

namespace celform::views {

ViewportDisplay::ViewportDisplay(
    const model::Document* document, const ViewportCamera& camera, std::function<void(bool)> changed)
    : m_document(document)
    , m_camera(camera)
    , m_changed(std::move(changed))
{ }

bool ViewportDisplay::hasMesh() const
{
    return m_document && m_document->hasMesh();
}

void ViewportDisplay::setShadingEnabled(bool on)
{
    if (on == m_shading)
        return;
    m_shading = on;
    m_changed(true);
}

void ViewportDisplay::setLightGizmoVisible(bool on)
{
    if (on == m_lightGizmo)
        return;
    m_lightGizmo = on;
    m_changed(true);
}

bool ViewportDisplay::lightGizmoShown() const
{
    return m_lightGizmo && m_shading && hasMesh();
}

double ViewportDisplay::lightGizmoRadius() const
{
    return std::max(0.5 * m_camera.bounds().diagonal().norm(), 1e-6);
}

Eigen::Vector3d ViewportDisplay::lightGizmoHandle() const
{
    const model::Light light
        = m_document ? m_document->data().look.lightAt(m_document->currentFrame()) : model::Light{};
    if (light.type == model::LightType::Point)
        return light.vector;
    Eigen::Vector3d direction = light.vector.normalized();
    if (!direction.allFinite())
        direction = Eigen::Vector3d::UnitZ();
    return m_camera.bounds().center() + 1.3 * lightGizmoRadius() * direction;
}

void ViewportDisplay::setStereo(algo::StereoOutput output)
{
    if (output == m_stereo)
        return;
    m_stereo = output;
    m_changed(false);
}

void ViewportDisplay::setStereoLook(const std::optional<model::StereoLook>& look)
{
    m_stereoLook = look;
    m_changed(false);
}

model::StereoLook ViewportDisplay::stereoLook() const
{
    if (m_stereoLook)
        return *m_stereoLook;
    return m_document ? m_document->data().look.stereo : model::StereoLook{};
}

algo::StereoSettings ViewportDisplay::resolvedStereoSettings() const
{
    // The centroid of the base model, as the offline path (model::renderShape) uses.
    const bool mesh = hasMesh() && m_document->data().baseMesh->vertices.rows() > 0;
    const Eigen::Vector3d centroid = mesh ? m_document->data().baseMesh->centre() : m_camera.bounds().center();
    return model::resolvedStereo(stereoLook(), m_camera.camera(), centroid);
}

void ViewportDisplay::setLinesOverride(std::optional<bool> show)
{
    m_linesOverride = show;
    m_changed(false);
}

bool ViewportDisplay::linesShown() const
{
    if (!hasMesh())
        return false;
    return m_linesOverride.value_or(m_document->data().look.showLines);
}

void ViewportDisplay::setEyeOnly(Eye eye)
{
    m_eyeOnly = eye;
    m_changed(false);
}

void ViewportDisplay::setSmoothShown(bool on)
{
    if (on == m_smooth)
        return;
    m_smooth = on;
    m_changed(false);
}

void ViewportDisplay::setCageShown(bool on)
{
    if (on == m_cage)
        return;
    m_cage = on;
    m_changed(false);
}

void ViewportDisplay::setTriangleCap(std::int64_t triangles)
{
    if (triangles == m_triangleCap || triangles <= 0)
        return;
    m_triangleCap = triangles;
    m_changed(false);
}

ViewportDisplay::Subdivision ViewportDisplay::subdivision() const
{
    Subdivision s;
    if (!hasMesh())
        return s;
    const model::SubdivisionLook& look = m_document->data().look.subdivision;
    s.renderLevel = std::clamp(look.level, 0, algo::kMaxSubdivisionLevel);
    s.viewportLevel = std::clamp(look.viewport(), 0, algo::kMaxSubdivisionLevel);
    const std::int64_t faces = m_document->data().baseMesh->faceCount();
    const int wanted = m_smooth ? s.viewportLevel : 0;
    // Issue 25: a big mesh is shown a level lower, so that the viewport stays interactive; the
    // status bar says so. The control mesh is always shown whole.
    s.level = wanted;
    while (s.level > 0 && algo::subdividedFaceCount(faces, s.level) > m_triangleCap)
        --s.level;
    s.capped = s.level < wanted;
    s.triangles = algo::subdividedFaceCount(faces, s.level);
    return s;
}

} // namespace celform::views
