// The viewport's editing tools (brush, offset brush, patch painting, alignment, highlight drag)
// as the viewport holds them: which is active, the brush sizes they share, picking the surface
// under the pointer, and the alignment tool's state the panels read.
#include "celform/views/viewport/viewport.h"

#include "celform/model/document/document.h"
#include "celform/views/tools/align_tool.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/tools/offset_brush_tool.h"
#include "celform/views/viewport/viewport_scene.h"
#include "celform/views/viewport/displayed_shape.h"

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

AlignTool* Viewport::alignTool() const
{
    return static_cast<AlignTool*>(m_tools.at(Tool::Align).get());
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

void Viewport::setBrushRadius(double radius)
{
    if (!(radius > 0.0) || !std::isfinite(radius) || radius == m_brushRadius)
        return;
    m_brushRadius = radius;
    emit brushRadiusChanged(radius);
}

void Viewport::setBrushPixelRadius(double pixels)
{
    if (!(pixels > 0.0) || !std::isfinite(pixels) || pixels == m_brushPixelRadius)
        return;
    m_brushPixelRadius = std::clamp(pixels, 1.0, 4096.0);
    emit brushPixelRadiusChanged(m_brushPixelRadius);
}

OffsetBrushTool* Viewport::offsetBrushTool() const
{
    return static_cast<OffsetBrushTool*>(m_tools.at(Tool::OffsetBrush).get());
}

BrushTool* Viewport::brushTool() const
{
    return static_cast<BrushTool*>(m_tools.at(Tool::Brush).get());
}

void Viewport::setPatchTarget(const QString& name)
{
    if (name == m_patchTarget)
        return;
    m_patchTarget = name;
    m_patchStale = true;
    update();
}

void Viewport::showBrushSelection(const algo::BrushSelection* selection, const algo::BrushSelection* mirror)
{
    const Eigen::Index rows = m_document && m_document->hasMesh() ? m_document->data().baseMesh->vertexCount() : 0;
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
    if (!hit || hit->face >= m_document->data().baseMesh->faceCount())
        return std::nullopt;
    return std::make_pair(hit->face, hit->position);
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

// --- alignment (the AlignTool's state, reachable from the panels) ----------------------------------

void Viewport::setPointMatching(bool on)
{
    alignTool()->setMatching(on);
}

bool Viewport::isPointMatching() const
{
    return alignTool()->isMatching();
}

const std::vector<Eigen::Vector3d>& Viewport::matchedModelPoints() const
{
    return alignTool()->modelPoints();
}

const std::vector<Eigen::Vector2d>& Viewport::matchedDrawingPoints() const
{
    return alignTool()->drawingPoints();
}

void Viewport::clearMatchedPoints()
{
    alignTool()->clearPoints();
}

void Viewport::removeLastMatchedPoint()
{
    alignTool()->removeLastPoint();
}

std::optional<double> Viewport::solveFromMatchedPoints(QString* error)
{
    return alignTool()->solve(error);
}

} // namespace celform::views
