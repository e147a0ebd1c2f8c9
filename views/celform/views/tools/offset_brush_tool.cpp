// Mouse motion to shading-offset dabs; the document does the painting (Document::applyOffsetStroke).
#include "celform/views/tools/offset_brush_tool.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/viewport/viewport.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

struct OffsetBrush {
    Q_DECLARE_TR_FUNCTIONS(celform::views::OffsetBrushTool)
};

} // namespace

OffsetBrushTool::OffsetBrushTool(Viewport* viewport, BrushSize& size)
    : BrushHover(viewport, size)
{ }

OffsetBrushTool::~OffsetBrushTool() = default;

void OffsetBrushTool::setStrength(double strength)
{
    if (std::isfinite(strength) && strength >= 0.0)
        m_strength = strength;
}

model::ShadingTarget OffsetBrushTool::target() const
{
    const model::Document* document = m_viewport->document();
    const int frame = document ? document->currentFrame() : 0;
    if (m_targetKey != 0 && document && document->data().key(m_targetKey))
        return {m_targetKey, frame};
    return {0, frame};
}

QString OffsetBrushTool::targetText() const
{
    const model::ShadingTarget t = target();
    if (t.isBase())
        return OffsetBrush::tr("base layer (every view and frame)");
    const model::KeyViewpoint* key = m_viewport->document()->data().key(t.key);
    return OffsetBrush::tr("key “%1” at frame %2").arg(key ? key->name : QString()).arg(t.frame);
}

void OffsetBrushTool::activate()
{
    emit message(OffsetBrush::tr("Paint shading offsets into the %1: drag adds, Ctrl+drag subtracts, "
                                 "Shift+drag smooths; F resizes the brush.")
                     .arg(targetText()));
}

bool OffsetBrushTool::press(const ToolEvent& event)
{
    if (isResizing()) {
        endResize(true); // a click keeps the new size
        return false;
    }
    model::Document* document = m_viewport->document();
    if (!document || !document->hasMesh())
        return false;
    const auto hit = m_viewport->pickSurface(event.position);
    if (!hit)
        return true; // a drag that starts off the model paints nothing
    const double unitsPerPixel = m_viewport->worldUnitsPerPixel(hit->second);
    model::OffsetBrush brush;
    brush.radius = size().worldRadius(unitsPerPixel);
    brush.strength = m_strength;
    brush.mirror = m_mirror ? document->data().mirrorPlane : model::MirrorPlane::Off;
    brush.mode = m_mode;
    if (event.modifiers & Qt::ShiftModifier)
        brush.mode = model::OffsetPaintMode::Smooth;
    else if (event.modifiers & Qt::ControlModifier)
        brush.mode = model::OffsetPaintMode::Subtract;
    try {
        m_stroke = document->shading().beginOffsetStroke(target(), brush, m_viewport->displayedShape());
    } catch (const model::EditRefused& e) {
        emit message(e.message());
        return true;
    }
    showAt(event.position, brush.radius / std::max(unitsPerPixel, 1e-12));
    document->shading().applyOffsetStroke(m_stroke, hit->second);
    if (m_stroke.twinMissing)
        emit message(
            OffsetBrush::tr("The mirror finds no twin of this point across the %1 plane: only this side is painted.")
                .arg(model::mirrorPlaneName(brush.mirror).toUpper()));
    return true;
}

void OffsetBrushTool::dab(const QPointF& position)
{
    model::Document* document = m_viewport->document();
    if (!document || !m_stroke.active())
        return;
    if (const auto hit = m_viewport->pickSurface(position))
        document->shading().applyOffsetStroke(m_stroke, hit->second);
    showAt(position, circlePixels());
}

void OffsetBrushTool::move(const ToolEvent& event)
{
    dab(event.position);
}

void OffsetBrushTool::finish()
{
    if (model::Document* document = m_viewport->document())
        document->shading().endOffsetStroke(m_stroke);
    m_stroke = {};
}

void OffsetBrushTool::release(const ToolEvent& event)
{
    finish();
    hover(event.position);
    updateCircle();
}

void OffsetBrushTool::cancel()
{
    finish();
}

void OffsetBrushTool::deactivate()
{
    stopHover();
    finish();
}

} // namespace celform::views
