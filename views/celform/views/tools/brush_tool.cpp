// Mouse motion to brush steps; the document does the deformation (Document::applyBrushStroke).
#include "celform/views/tools/brush_tool.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_keys.h"

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

BrushTool::BrushTool(Viewport* viewport)
    : ViewportTool(viewport)
    , m_hover(viewport, [viewport] { return viewport->brushProfile().falloff; })
{ }

BrushTool::~BrushTool() = default; // the circle and the timer belong to the viewport

void BrushTool::hover(const QPointF& position)
{
    m_hover.hover(position);
}

void BrushTool::leave()
{
    m_hover.leave(m_stroke.active());
}

void BrushTool::cameraChanged()
{
    m_hover.cameraChanged(m_stroke.active());
}

bool BrushTool::wantsKey(int key, Qt::KeyboardModifiers modifiers) const
{
    return m_hover.wantsKey(key, modifiers, m_stroke.active());
}

bool BrushTool::keyPress(int key, Qt::KeyboardModifiers modifiers)
{
    return m_hover.keyPress(key, modifiers, m_stroke.active(),
        Brush::tr("Hold the cursor over the model to resize the brush there."),
        Brush::tr("Move the mouse to resize the brush; click or Enter to keep, Esc to cancel."));
}

bool BrushTool::press(const ToolEvent& event)
{
    if (m_hover.isResizing()) {
        m_hover.endResize(true); // Blender: a click keeps the new size
        return false;
    }
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
    const Eigen::Vector3d pickedPoint = m_viewport->displayedShape().row(picked).cast<double>().transpose();
    const double unitsPerPixel = m_viewport->worldUnitsPerPixel(pickedPoint);
    // A radius in pixels is the world radius that many pixels span at the picked point.
    const double radius = m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels
        ? m_viewport->brushPixelRadius() * unitsPerPixel
        : m_viewport->brushRadius();
    try {
        m_stroke = document->keys().beginBrushStroke(key, document->currentFrame(), std::uint32_t(picked), radius,
            m_viewport->camera(), m_viewport->brushMirrorX(), m_viewport->brushProfile());
    } catch (const model::EditRefused& e) {
        emit m_viewport->message(e.message());
        return true;
    }
    m_unitsPerPixel = unitsPerPixel;
    m_viewport->showBrushSelection(&m_stroke.selection, &m_stroke.mirrorSelection);
    m_hover.showAt(event.position, radius / std::max(unitsPerPixel, 1e-12));
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
    else if (m_viewport->brushMode() == Viewport::BrushMode::Relax)
        step = {model::BrushMotion::Relax, kSmoothStrength, 0.0};
    else if (ctrl && shift)
        step = {model::BrushMotion::Scale, std::exp(kScalePerPixel * d.x()), 0.0};
    else if (shift)
        step = {model::BrushMotion::Rotate, -kRadiansPerPixel * d.x(), 0.0};
    else if (ctrl)
        step = {model::BrushMotion::Push, -d.y() * m_unitsPerPixel, 0.0};
    else
        step = {model::BrushMotion::Drag, d.x() * m_unitsPerPixel, -d.y() * m_unitsPerPixel};
    document->keys().applyBrushStroke(m_stroke, step);
    // The circle follows the cursor with the stroke's radius.
    m_hover.showAt(event.position, m_hover.circle()->radiusPixels());
}

void BrushTool::finish()
{
    if (model::Document* document = m_viewport->document())
        document->keys().endBrushStroke(m_stroke);
}

void BrushTool::release(const ToolEvent& event)
{
    finish();
    // The selection is shown during the stroke only: afterwards (and after an undo) the model
    // shows its look again.
    m_viewport->showBrushSelection(nullptr, nullptr);
    m_hover.hover(event.position);
    m_hover.updateCircle();
}

void BrushTool::cancel()
{
    finish();
    m_viewport->showBrushSelection(nullptr, nullptr);
}

void BrushTool::deactivate()
{
    m_hover.stop();
    finish();
    m_stroke = {};
    m_viewport->showBrushSelection(nullptr, nullptr);
}

} // namespace celform::views
