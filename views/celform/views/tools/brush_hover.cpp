// The brush circle and F-resize shared by the viewport's brushes (brush_hover.h).
#include "celform/views/tools/brush_hover.h"

#include "celform/views/tools/brush_cursor.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_keys.h"

#include <QCoreApplication>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

// The texts were the geometry brush's first: their translations live in its context.
struct Brush {
    Q_DECLARE_TR_FUNCTIONS(celform::views::BrushTool)
};

} // namespace

BrushHover::BrushHover(Viewport* viewport, BrushSize& size)
    : ViewportTool(viewport)
    , m_size(size)
    , m_circle(new BrushCursor(viewport))
    , m_timer(new QTimer(viewport))
{
    m_timer->setSingleShot(true);
    m_timer->setInterval(16);
    QObject::connect(m_timer, &QTimer::timeout, this, [this] { updateCircle(); });
}

BrushHover::~BrushHover() = default;

void BrushHover::updateCircle()
{
    if (m_resizing)
        return;
    const auto hit = m_viewport->pickSurface(m_position);
    if (!hit) {
        m_unitsPerPixel = 0.0;
        m_circle->hide();
        return;
    }
    m_unitsPerPixel = m_viewport->worldUnitsPerPixel(hit->second);
    m_circle->showCircle(m_position, m_size.pixelsAt(m_unitsPerPixel), falloff());
}

void BrushHover::hover(const QPointF& position)
{
    m_position = position;
    if (m_resizing) {
        // The radius is the cursor's distance from the circle's centre.
        const QPointF d = position - m_resizeCentre;
        const double pixels = std::max(std::sqrt(QPointF::dotProduct(d, d)), 2.0);
        if (m_size.unit() == BrushSize::Unit::Pixels)
            m_size.setPixelRadius(pixels);
        else if (m_unitsPerPixel > 0.0)
            m_size.setRadius(pixels * m_unitsPerPixel);
        m_circle->showCircle(m_resizeCentre, pixels, falloff(), true);
        return;
    }
    if (!m_timer->isActive())
        m_timer->start();
}

void BrushHover::leave()
{
    m_timer->stop();
    if (!m_resizing && !strokeActive())
        m_circle->hide();
}

void BrushHover::cameraChanged()
{
    // The surface under the cursor moved: its scale (world units per pixel) changed.
    if (m_circle->isVisible() && !m_resizing && !strokeActive())
        hover(m_position);
}

void BrushHover::showAt(const QPointF& position, double radiusPixels)
{
    m_timer->stop();
    m_circle->showCircle(position, radiusPixels, falloff());
}

double BrushHover::circlePixels() const
{
    return m_circle->radiusPixels();
}

bool BrushHover::wantsKey(int key, Qt::KeyboardModifiers modifiers) const
{
    if (modifiers & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize)) // F, listed in Help > Keyboard Shortcuts
        return !strokeActive();
    return m_resizing && (key == Qt::Key_Escape || key == Qt::Key_Return || key == Qt::Key_Enter);
}

bool BrushHover::keyPress(int key, Qt::KeyboardModifiers modifiers)
{
    if (!wantsKey(key, modifiers))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize) && !m_resizing) {
        if (m_unitsPerPixel <= 0.0 && m_size.unit() == BrushSize::Unit::World) {
            emit message(Brush::tr("Hold the cursor over the model to resize the brush there."));
            return true;
        }
        m_resizing = true;
        m_radiusBeforeResize = m_size.current();
        // The circle stays where it is; moving the cursor away from its centre sizes it.
        const double pixels = m_size.pixelsAt(m_unitsPerPixel);
        m_resizeCentre = m_position - QPointF(pixels, 0.0);
        m_circle->showCircle(m_resizeCentre, pixels, falloff(), true);
        emit message(Brush::tr("Move the mouse to resize the brush; click or Enter to keep, Esc to cancel."));
        return true;
    }
    endResize(key != Qt::Key_Escape);
    return true;
}

void BrushHover::endResize(bool keep)
{
    if (!m_resizing)
        return;
    m_resizing = false;
    if (!keep)
        m_size.setCurrent(m_radiusBeforeResize);
    updateCircle();
}

void BrushHover::stopHover()
{
    m_resizing = false;
    m_timer->stop();
    m_circle->hide();
}

} // namespace celform::views
