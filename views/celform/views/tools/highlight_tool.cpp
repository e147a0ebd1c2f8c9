// Screen motion to highlight parameters: the tangent frame the renderer uses at the picked vertex,
// seen on screen, maps the drag to translation amounts along du and dv.
#include "celform/views/tools/highlight_tool.h"

#include "celform/algorithms/highlights.h"
#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/model/render_output.h"
#include "celform/views/viewport.h"

#include <cmath>

namespace celform::views {

bool HighlightTool::press(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    const model::ObjectId target = m_viewport->highlightTarget();
    if (!document || !document->data().highlight(target))
        return false;
    // Fallback without a picked point: screen axes, a fixed rate.
    m_du = QPointF(1.0, 0.0);
    m_dv = QPointF(0.0, -1.0);
    m_unitsPerPixel = 0.005;
    openGesture();
    const auto& mesh = document->data().baseMesh;
    const std::int64_t vertex = m_viewport->pickVertex(event.position);
    const algo::Positions& shape = m_viewport->displayedShape();
    if (!mesh || vertex < 0 || vertex >= shape.rows() || shape.rows() != mesh->vertices.rows())
        return true;
    const model::HighlightTrack& track = *document->data().highlight(target);
    const Eigen::Vector3f p = shape.row(vertex).transpose();
    // The frame the renderer uses at that vertex (UVs where the model has them, else the guide
    // smoothed over the patch); a hidden layer or a vertex off its patch falls back to the guide.
    algo::HighlightFrame frame;
    bool found = false;
    for (const auto& h :
        model::renderHighlightsFor(document->data(), document->data().look, shape, document->currentFrame()))
        if (QString::fromStdString(h.layer.name) == track.name && h.du.rows() == shape.rows()
            && h.du.row(vertex).squaredNorm() > 0.5f) {
            frame.du = h.du.row(vertex).transpose();
            frame.dv = h.dv.row(vertex).transpose();
            found = true;
            break;
        }
    if (!found) {
        const algo::Positions normals = algo::vertexNormals(shape, mesh->faces);
        frame = algo::guideTangentFrame(normals.row(vertex).transpose(), track.guide);
    }
    const double perPixel = m_viewport->worldUnitsPerPixel(p.cast<double>());
    const QPointF origin = m_viewport->projectToWidget(p.cast<double>());
    auto screenDirection = [&](const Eigen::Vector3f& d) {
        const QPointF s = m_viewport->projectToWidget((p + d * float(perPixel * 10.0)).cast<double>()) - origin;
        const double length = std::hypot(s.x(), s.y());
        return length > 1e-6 ? s / length : QPointF();
    };
    m_du = screenDirection(frame.du);
    m_dv = screenDirection(frame.dv);
    // H + alpha du tilts H by atan(alpha): on a surface of curvature radius r the highlight moves
    // about r * alpha; the distance to the model's centre stands in for r.
    const double radius = std::max(double((p.cast<double>() - m_viewport->modelCentre()).norm()), 1e-9);
    m_unitsPerPixel = perPixel / radius;
    return true;
}

void HighlightTool::move(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    const model::ObjectId target = m_viewport->highlightTarget();
    if (!document || !inGesture() || !document->data().highlight(target))
        return;
    using T = algo::HighlightOperationType;
    const QPointF d = event.delta;
    const bool rotate = event.modifiers & Qt::ShiftModifier, scale = event.modifiers & Qt::ControlModifier;
    try {
        if (rotate) {
            document->nudgeHighlight(target, document->currentFrame(), T::Rotation, d.x() * 0.5);
        } else if (scale) {
            document->nudgeHighlight(target, document->currentFrame(), T::DirectionalScaling, d.x() * 0.005);
        } else {
            const double a = d.x() * m_du.x() + d.y() * m_du.y();
            const double b = d.x() * m_dv.x() + d.y() * m_dv.y();
            document->nudgeHighlight(
                target, document->currentFrame(), T::Translation, a * m_unitsPerPixel, b * m_unitsPerPixel);
        }
    } catch (const model::EditRefused& e) {
        emit m_viewport->message(e.message());
    }
}

} // namespace celform::views
