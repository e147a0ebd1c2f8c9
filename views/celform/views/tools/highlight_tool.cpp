// Cursor to highlight parameters. A plain drag keeps the grabbed point of the highlight under the
// cursor: the translation that puts the highlight's centre (where N · H~ is 1) on the surface point
// under the cursor has a closed form in the renderer's tangent frame there, and the drag keeps the
// offset the press had from it. Shift (rotation) and Ctrl (scaling) map pixels to amounts.
#include "celform/views/tools/highlight_tool.h"

#include "celform/algorithms/highlights.h"
#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/viewport.h"

#include <cmath>
#include <optional>

namespace celform::views {

std::optional<Eigen::Vector2d> HighlightTool::centringTranslation(const QPointF& position)
{
    model::Document* document = m_viewport->document();
    const auto hit = m_viewport->pickSurface(position);
    if (!document || !hit || !document->hasMesh() || m_layer.du.rows() == 0)
        return std::nullopt;
    const algo::TriMesh& mesh = *document->data().baseMesh;
    const algo::Positions& shape = m_viewport->displayedShape();
    const auto face = hit->first;
    if (!m_layer.faceMask.empty() && !m_layer.faceMask[std::size_t(face)])
        return std::nullopt; // off the layer's patch: the highlight cannot sit there
    const Eigen::Vector3f p = hit->second.cast<float>();
    const Eigen::Index a = mesh.faces(face, 0), b = mesh.faces(face, 1), c = mesh.faces(face, 2);
    // Barycentric coordinates of the picked point, as the renderer interpolates its attributes.
    const Eigen::Vector3f pa = shape.row(a), pb = shape.row(b), pc = shape.row(c);
    const Eigen::Vector3f n0 = (pb - pa).cross(pc - pa);
    const float area = n0.squaredNorm();
    if (!(area > 0.f))
        return std::nullopt;
    const float u = (pb - p).cross(pc - p).dot(n0) / area, v = (pc - p).cross(pa - p).dot(n0) / area;
    const Eigen::Vector3f w(u, v, 1.f - u - v);
    auto at = [&](const algo::Positions& rows) {
        return Eigen::Vector3f(w.x() * rows.row(a) + w.y() * rows.row(b) + w.z() * rows.row(c));
    };
    // The layer's normal (smoothed where it asks for it) on the viewer's side, and its frame.
    const model::Camera camera = m_viewport->camera();
    Eigen::Vector3f normal = n0.normalized();
    if (m_layer.normals.rows() == shape.rows() && at(m_layer.normals).squaredNorm() > 1e-12f)
        normal = at(m_layer.normals).normalized();
    const Eigen::Vector3f towardsEye = camera.projection == model::Projection::Orthographic
        ? Eigen::Vector3f(-camera.forward().cast<float>())
        : Eigen::Vector3f(camera.eye.cast<float>() - p);
    if (normal.dot(towardsEye) < 0.f)
        normal = -normal;
    const algo::HighlightFrame frame = algo::makeTangentFrame(normal, at(m_layer.du), at(m_layer.dv));
    // Paper 2, "translation": H~ = (H + alpha du + beta dv) / |...|. With H = h_n N + h_u du + h_v dv
    // in this orthonormal frame, H~ is parallel to N (the highlight's centre) for alpha = -h_u and
    // beta = -h_v.
    const model::Light light = document->data().look.lightAt(document->currentFrame());
    algo::HighlightLight highlightLight;
    highlightLight.point = light.type == model::LightType::Point;
    highlightLight.vector = light.vector.cast<float>();
    // V towards the camera's eye, as the renderer takes it for either projection.
    const Eigen::Vector3f h = algo::halfwayVector(p, highlightLight, camera.eye.cast<float>());
    if (!(h.dot(normal) > 0.f))
        return std::nullopt; // the light is behind this point: no highlight can centre here
    return Eigen::Vector2d(-double(h.dot(frame.du)), -double(h.dot(frame.dv)));
}

bool HighlightTool::press(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    const model::ObjectId target = m_target;
    if (!document || !document->data().highlight(target))
        return false;
    const int frame = document->currentFrame();
    try {
        m_drag = document->highlights().beginHighlightDrag(target, frame);
    } catch (const model::EditRefused& e) {
        emit message(e.message());
        return true;
    }
    const model::HighlightTrack& track = *document->data().highlight(target);
    // The layer's geometry as the renderer resolves it (UV frames, or the guide over the patch;
    // smoothed normals): fixed for the drag, the shape does not change under it.
    m_layer = {};
    const algo::Positions& shape = m_viewport->displayedShape();
    for (auto& h : model::renderHighlightsFor(document->data(), document->data().look, shape, frame))
        if (QString::fromStdString(h.layer.name) == track.name) {
            m_layer = std::move(h);
            break;
        }
    // The grabbed point: later centring translations minus this one move the highlight.
    m_pressCentring = centringTranslation(event.position);
    // Rotation and scaling: a fixed rate per pixel.
    return true;
}

void HighlightTool::move(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !m_drag.active())
        return;
    using M = model::HighlightMotion;
    const QPointF d = event.delta;
    const bool rotate = event.modifiers & Qt::ShiftModifier, scale = event.modifiers & Qt::ControlModifier;
    try {
        if (rotate) {
            document->highlights().applyHighlightDrag(m_drag, {M::Rotate, d.x() * 0.5, 0.0});
        } else if (scale) {
            document->highlights().applyHighlightDrag(m_drag, {M::Scale, d.x() * 0.005, 0.0});
        } else if (m_pressCentring) {
            // The grabbed point follows the cursor; off the model (or the patch) it stays put.
            if (const auto centring = centringTranslation(event.position)) {
                const Eigen::Vector2d offset = *centring - *m_pressCentring;
                document->highlights().applyHighlightDrag(m_drag, {M::Move, offset.x(), offset.y()});
            }
        }
    } catch (const model::EditRefused& e) {
        emit message(e.message());
    }
}

void HighlightTool::endDrag()
{
    if (model::Document* document = m_viewport->document())
        document->highlights().endHighlightDrag(m_drag);
    m_drag = {};
}

} // namespace celform::views
