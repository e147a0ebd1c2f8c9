// Mouse motion to shading-offset dabs; the document does the painting (Document::applyOffsetStroke).
#include "celform/views/tools/offset_brush_tool.h"

#include "celform/model/document.h"
#include "celform/model/io_error.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/viewport.h"
#include "celform/views/viewport_keys.h"

#include <QCoreApplication>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

struct OffsetBrush {
    Q_DECLARE_TR_FUNCTIONS(celform::views::OffsetBrushTool)
};

} // namespace

OffsetBrushTool::OffsetBrushTool(Viewport* viewport)
    : ViewportTool(viewport)
    , m_circle(new BrushCursor(viewport))
    , m_hoverTimer(new QTimer(viewport))
{
    m_circle->hide();
    m_hoverTimer->setSingleShot(true);
    m_hoverTimer->setInterval(16);
    QObject::connect(m_hoverTimer, &QTimer::timeout, viewport, [this] { updateCircle(); });
}

OffsetBrushTool::~OffsetBrushTool() = default; // the circle and the timer belong to the viewport

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
    emit m_viewport->message(OffsetBrush::tr("Paint shading offsets into the %1: drag adds, Ctrl+drag subtracts, "
                                             "Shift+drag smooths; F resizes the brush.")
                                 .arg(targetText()));
}

double OffsetBrushTool::radiusPixels(double unitsPerPixel) const
{
    if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
        return m_viewport->brushPixelRadius();
    return unitsPerPixel > 0.0 ? m_viewport->brushRadius() / unitsPerPixel : 0.0;
}

void OffsetBrushTool::updateCircle()
{
    if (m_resizing)
        return;
    const auto hit = m_viewport->pickSurface(m_hoverPos);
    if (!hit) {
        m_hoverUnitsPerPixel = 0.0;
        m_circle->hide();
        return;
    }
    m_hoverUnitsPerPixel = m_viewport->worldUnitsPerPixel(hit->second);
    m_circle->showCircle(m_hoverPos, radiusPixels(m_hoverUnitsPerPixel), algo::BrushFalloff::Paper);
}

void OffsetBrushTool::hover(const QPointF& position)
{
    m_hoverPos = position;
    if (m_resizing) {
        const QPointF d = position - m_resizeCentre;
        const double pixels = std::max(std::sqrt(QPointF::dotProduct(d, d)), 2.0);
        if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
            m_viewport->setBrushPixelRadius(pixels);
        else if (m_hoverUnitsPerPixel > 0.0)
            m_viewport->setBrushRadius(pixels * m_hoverUnitsPerPixel);
        m_circle->showCircle(m_resizeCentre, pixels, algo::BrushFalloff::Paper, true);
        return;
    }
    if (!m_hoverTimer->isActive())
        m_hoverTimer->start();
}

void OffsetBrushTool::leave()
{
    m_hoverTimer->stop();
    if (!m_resizing && !m_stroke.active())
        m_circle->hide();
}

void OffsetBrushTool::cameraChanged()
{
    if (m_circle->isVisible() && !m_resizing && !m_stroke.active())
        hover(m_hoverPos);
}

bool OffsetBrushTool::wantsKey(int key, Qt::KeyboardModifiers modifiers) const
{
    if (modifiers & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize))
        return !m_stroke.active();
    return m_resizing && (key == Qt::Key_Escape || key == Qt::Key_Return || key == Qt::Key_Enter);
}

bool OffsetBrushTool::keyPress(int key, Qt::KeyboardModifiers modifiers)
{
    if (!wantsKey(key, modifiers))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize) && !m_resizing) {
        if (m_hoverUnitsPerPixel <= 0.0 && m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::World) {
            emit m_viewport->message(OffsetBrush::tr("Hold the cursor over the model to resize the brush there."));
            return true;
        }
        m_resizing = true;
        m_radiusBeforeResize = m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels
            ? m_viewport->brushPixelRadius()
            : m_viewport->brushRadius();
        const double pixels = radiusPixels(m_hoverUnitsPerPixel);
        m_resizeCentre = m_hoverPos - QPointF(pixels, 0.0);
        m_circle->showCircle(m_resizeCentre, pixels, algo::BrushFalloff::Paper, true);
        emit m_viewport->message(
            OffsetBrush::tr("Move the mouse to resize the brush; click or Enter to keep, Esc to cancel."));
        return true;
    }
    m_resizing = false;
    if (key == Qt::Key_Escape) {
        if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
            m_viewport->setBrushPixelRadius(m_radiusBeforeResize);
        else
            m_viewport->setBrushRadius(m_radiusBeforeResize);
    }
    updateCircle();
    return true;
}

bool OffsetBrushTool::press(const ToolEvent& event)
{
    if (m_resizing) {
        m_resizing = false; // a click keeps the new size
        updateCircle();
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
    brush.radius = m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels
        ? m_viewport->brushPixelRadius() * unitsPerPixel
        : m_viewport->brushRadius();
    brush.strength = m_strength;
    brush.mirrorX = m_mirrorX;
    brush.mode = m_mode;
    if (event.modifiers & Qt::ShiftModifier)
        brush.mode = model::OffsetPaintMode::Smooth;
    else if (event.modifiers & Qt::ControlModifier)
        brush.mode = model::OffsetPaintMode::Subtract;
    try {
        m_stroke = document->beginOffsetStroke(target(), brush, m_viewport->displayedShape());
    } catch (const model::EditRefused& e) {
        emit m_viewport->message(e.message());
        return true;
    }
    m_hoverTimer->stop();
    m_circle->showCircle(event.position, brush.radius / std::max(unitsPerPixel, 1e-12), algo::BrushFalloff::Paper);
    document->applyOffsetStroke(m_stroke, hit->second);
    return true;
}

void OffsetBrushTool::dab(const QPointF& position)
{
    model::Document* document = m_viewport->document();
    if (!document || !m_stroke.active())
        return;
    if (const auto hit = m_viewport->pickSurface(position))
        document->applyOffsetStroke(m_stroke, hit->second);
    m_circle->showCircle(position, m_circle->radiusPixels(), algo::BrushFalloff::Paper);
}

void OffsetBrushTool::move(const ToolEvent& event)
{
    dab(event.position);
}

void OffsetBrushTool::finish()
{
    if (model::Document* document = m_viewport->document())
        document->endOffsetStroke(m_stroke);
    m_stroke = {};
}

void OffsetBrushTool::release(const ToolEvent& event)
{
    finish();
    m_hoverPos = event.position;
    updateCircle();
}

void OffsetBrushTool::cancel()
{
    finish();
}

void OffsetBrushTool::deactivate()
{
    m_resizing = false;
    m_hoverTimer->stop();
    m_circle->hide();
    finish();
}

} // namespace celform::views
