// Mouse motion to brush steps; the document does the deformation (Document::applyBrushStroke).
#include "celform/views/tools/brush_tool.h"

#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/views/viewport.h"

#include <QCoreApplication>

#include <cmath>

namespace celform::views {
namespace {

struct Brush {
    Q_DECLARE_TR_FUNCTIONS(celform::views::BrushTool)
};

constexpr double kRadiansPerPixel = 0.5 * 3.14159265358979323846 / 180.0; // half a degree
constexpr double kScalePerPixel = 0.005; // exp(kScalePerPixel * pixels)
constexpr double kSmoothStrength = 0.25;

} // namespace

bool BrushTool::press(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    const model::ObjectId key = m_viewport->displayedKey();
    if (!document || !document->data().key(key)) {
        emit m_viewport->message(Brush::tr("Choose a key to deform first (Scene panel, then Edit Key)."));
        return true;
    }
    const std::int64_t picked = m_viewport->pickVertex(event.position);
    if (picked < 0) {
        m_viewport->showBrushSelection(nullptr, nullptr);
        return true;
    }
    try {
        m_stroke = document->beginBrushStroke(key, document->currentFrame(), std::uint32_t(picked),
            m_viewport->brushRadius(), m_viewport->camera(), m_viewport->brushMirrorX());
    } catch (const model::EditRefused& e) {
        emit m_viewport->message(e.message());
        return true;
    }
    m_unitsPerPixel = m_viewport->worldUnitsPerPixel(m_stroke.shape.row(picked).cast<double>().transpose());
    m_viewport->showBrushSelection(&m_stroke.selection, &m_stroke.mirrorSelection);
    return true;
}

void BrushTool::move(const ToolEvent& event)
{
    model::Document* document = m_viewport->document();
    if (!document || !m_stroke.active())
        return;
    const QPointF d = event.delta;
    model::BrushStep step;
    const bool ctrl = event.modifiers & Qt::ControlModifier, shift = event.modifiers & Qt::ShiftModifier;
    if (m_viewport->brushMode() == Viewport::BrushMode::Smooth)
        step = {model::BrushMotion::Smooth, kSmoothStrength, 0.0};
    else if (ctrl && shift)
        step = {model::BrushMotion::Scale, std::exp(kScalePerPixel * d.x()), 0.0};
    else if (shift)
        step = {model::BrushMotion::Rotate, -kRadiansPerPixel * d.x(), 0.0};
    else if (ctrl)
        step = {model::BrushMotion::Push, -d.y() * m_unitsPerPixel, 0.0};
    else
        step = {model::BrushMotion::Drag, d.x() * m_unitsPerPixel, -d.y() * m_unitsPerPixel};
    document->applyBrushStroke(m_stroke, step);
}

void BrushTool::finish()
{
    if (model::Document* document = m_viewport->document())
        document->endBrushStroke(m_stroke);
}

void BrushTool::release(const ToolEvent&)
{
    finish();
    // The selection is shown during the stroke only: afterwards (and after an undo) the model
    // shows its look again.
    m_viewport->showBrushSelection(nullptr, nullptr);
}

void BrushTool::cancel()
{
    finish();
    m_viewport->showBrushSelection(nullptr, nullptr);
}

void BrushTool::deactivate()
{
    finish();
    m_stroke = {};
    m_viewport->showBrushSelection(nullptr, nullptr);
}

} // namespace celform::views
