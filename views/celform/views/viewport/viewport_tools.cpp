// The viewport's editing tools (brush, offset brush, patch painting, alignment, highlight drag)
// as the viewport holds them: which is active, finding one by type, the brush selection a stroke
// shows, and picking the surface under the pointer.
#include "celform/views/viewport/viewport.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/viewport_scene.h"
#include "celform/views/viewport/displayed_shape.h"
#include "celform/views/viewport/subdivided_display.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace celform::views {

// --- tools ------------------------------------------------------------------------------------

ViewportTool* Viewport::activeTool() const
{
    const auto it = m_tools.find(m_tool);
    return it == m_tools.end() ? nullptr : it->second.get();
}

std::vector<ViewportTool*> Viewport::allTools() const
{
    std::vector<ViewportTool*> tools;
    tools.reserve(m_tools.size() + 1);
    for (const auto& [kind, tool] : m_tools)
        tools.push_back(tool.get());
    tools.push_back(m_lightTool.get());
    return tools;
}

void Viewport::setTool(Tool tool)
{
    if (tool == m_tool)
        return;
    if (m_drag == Drag::Tool)
        endDrag(true);
    if (m_wheelBurst.isActive()) {
        m_wheelBurst.stop();
        if (ViewportTool* old = activeTool())
            old->navigationEnded();
    }
    if (ViewportTool* old = activeTool())
        old->deactivate();
    m_tool = tool;
    m_patchStale = true;
    if (ViewportTool* now = activeTool())
        now->activate();
    setCursor(activeTool() ? activeTool()->cursor() : Qt::ArrowCursor);
    update();
    emit toolChanged(tool);
}

void Viewport::showBrushSelection(const algo::BrushSelection* selection, const algo::BrushSelection* mirror)
{
    Eigen::Index rows = 0;
    if (m_document && m_document->hasMesh() && m_scene->hasMesh()) {
        // The selection is of control vertices; the colours go on the displayed ones.
        syncSubdivision();
        const model::ProjectData& data = m_document->data();
        rows = m_surface->view(data, *m_shape).mesh->vertexCount();
        if (m_surface->level() > 0 && (selection || mirror)) {
            selection = m_surface->selection(selection, mirror, data.baseMesh->vertexCount());
            mirror = nullptr;
        }
    }
    const bool wasShown = m_scene->selectionShown();
    m_scene->setSelectionColors(selection, mirror, rows);
    if (wasShown != m_scene->selectionShown())
        applyShadingState(); // the clay look shows the selection colours
    update();
}

std::optional<std::pair<std::int64_t, Eigen::Vector3d>> Viewport::pickSurface(const QPointF& position)
{
    if (!m_initialized || !m_document || !m_document->hasMesh())
        return std::nullopt;
    syncScene(); // VTK picks against the arrays: they must hold the shape on screen
    const qreal dpr = devicePixelRatioF();
    makeCurrent();
    const auto hit = m_scene->pick(position.x() * dpr, (height() - position.y()) * dpr);
    doneCurrent();
    const model::ProjectData& data = m_document->data();
    if (!hit || hit->face >= m_surface->view(data, *m_shape).mesh->faceCount())
        return std::nullopt;
    // Issue 25: the tools pick on the control mesh (its face, and the point with the same
    // barycentric coordinates there), whatever surface is displayed.
    return m_surface->toControl(hit->face, hit->position, data.baseMesh->faces, m_shape->positions());
}

std::int64_t Viewport::pickVertex(const QPointF& position)
{
    const auto hit = pickSurface(position);
    if (!hit)
        return -1;
    const auto& faces = m_document->data().baseMesh->faces;
    const algo::Positions& shape = m_shape->positions();
    std::int64_t best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (int k = 0; k < 3; ++k) {
        const auto vertex = faces(hit->first, k);
        const double d = (shape.row(vertex).cast<double>().transpose() - hit->second).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = vertex;
        }
    }
    return best;
}

} // namespace celform::views
