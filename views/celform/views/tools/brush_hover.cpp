// The brush circle and F-resize shared by the viewport's brushes (brush_hover.h).
#include "celform/views/tools/brush_hover.h"

#include "celform/views/tools/brush_cursor.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/viewport/viewport_keys.h"

#include <QTimer>

#include <algorithm>
#include <cmath>

namespace celform::views {

BrushHover::BrushHover(Viewport* viewport, std::function<algo::BrushFalloff()> falloff)
    : m_viewport(viewport)
    , m_falloff(std::move(falloff))
    , m_circle(new BrushCursor(viewport))
    , m_timer(new QTimer(viewport))
{
    m_timer->setSingleShot(true);
    m_timer->setInterval(16);
    QObject::connect(m_timer, &QTimer::timeout, viewport, [this] { updateCircle(); });
}

double BrushHover::radiusPixels(double unitsPerPixel) const
{
    if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
        return m_viewport->brushPixelRadius();
    return unitsPerPixel > 0.0 ? m_viewport->brushRadius() / unitsPerPixel : 0.0;
}

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
    m_circle->showCircle(m_position, radiusPixels(m_unitsPerPixel), m_falloff());
}

void BrushHover::hover(const QPointF& position)
{
    m_position = position;
    if (m_resizing) {
        // The radius is the cursor's distance from the circle's centre.
        const QPointF d = position - m_resizeCentre;
        const double pixels = std::max(std::sqrt(QPointF::dotProduct(d, d)), 2.0);
        if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
            m_viewport->setBrushPixelRadius(pixels);
        else if (m_unitsPerPixel > 0.0)
            m_viewport->setBrushRadius(pixels * m_unitsPerPixel);
        m_circle->showCircle(m_resizeCentre, pixels, m_falloff(), true);
        return;
    }
    if (!m_timer->isActive())
        m_timer->start();
}

void BrushHover::leave(bool strokeActive)
{
    m_timer->stop();
    if (!m_resizing && !strokeActive)
        m_circle->hide();
}

void BrushHover::cameraChanged(bool strokeActive)
{
    // The surface under the cursor moved: its scale (world units per pixel) changed.
    if (m_circle->isVisible() && !m_resizing && !strokeActive)
        hover(m_position);
}

void BrushHover::showAt(const QPointF& position, double radiusPixels)
{
    m_timer->stop();
    m_circle->showCircle(position, radiusPixels, m_falloff());
}

bool BrushHover::wantsKey(int key, Qt::KeyboardModifiers modifiers, bool strokeActive) const
{
    if (modifiers & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize)) // F, listed in Help > Keyboard Shortcuts
        return !strokeActive;
    return m_resizing && (key == Qt::Key_Escape || key == Qt::Key_Return || key == Qt::Key_Enter);
}

bool BrushHover::keyPress(
    int key, Qt::KeyboardModifiers modifiers, bool strokeActive, const QString& hint, const QString& prompt)
{
    if (!wantsKey(key, modifiers, strokeActive))
        return false;
    if (key == viewportKey(ViewportKeyCommand::BrushResize) && !m_resizing) {
        if (m_unitsPerPixel <= 0.0 && m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::World) {
            emit m_viewport->message(hint);
            return true;
        }
        m_resizing = true;
        m_radiusBeforeResize = m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels
            ? m_viewport->brushPixelRadius()
            : m_viewport->brushRadius();
        // The circle stays where it is; moving the cursor away from its centre sizes it.
        const double pixels = radiusPixels(m_unitsPerPixel);
        m_resizeCentre = m_position - QPointF(pixels, 0.0);
        m_circle->showCircle(m_resizeCentre, pixels, m_falloff(), true);
        emit m_viewport->message(prompt);
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
    if (!keep) {
        if (m_viewport->brushRadiusUnit() == Viewport::BrushRadiusUnit::Pixels)
            m_viewport->setBrushPixelRadius(m_radiusBeforeResize);
        else
            m_viewport->setBrushRadius(m_radiusBeforeResize);
    }
    updateCircle();
}

void BrushHover::stop()
{
    m_resizing = false;
    m_timer->stop();
    m_circle->hide();
}

} // namespace celform::views
