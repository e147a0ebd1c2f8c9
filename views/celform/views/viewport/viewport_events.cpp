// The viewport's pointer and key events: Maya-style navigation (Alt+left orbit, Alt+middle pan,
// Alt+right dolly) or Blender's (middle orbit, Shift+middle pan, Ctrl+middle dolly), the wheel, the light gizmo's
// Ctrl+drag, and every other left-button drag handed to the active tool.
#include "celform/views/viewport/viewport.h"

#include "celform/views/tools/brush_size.h"
#include "celform/views/viewport/viewport_camera.h"
#include "celform/views/viewport/viewport_keys.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <cmath>

namespace celform::views {
namespace {

constexpr double kOrbitDegreesPerPixel = 0.4;
constexpr double kRollSnapDegrees = 15.0;
constexpr double kDollyPerPixel = 0.005; // exp(-kDollyPerPixel * pixels)
constexpr double kDollyPerWheelNotch = 0.85; // factor per 120 units of wheel angle

} // namespace

void Viewport::mousePressEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None) {
        event->accept();
        return;
    }
    const Qt::KeyboardModifiers mods = event->modifiers();
    const Qt::MouseButton button = event->button();
    const ToolEvent toolEvent{event->position(), {}, mods};
    Drag drag = Drag::None;
    ViewportTool* tool = nullptr;
    if (button == Qt::LeftButton && !(mods & Qt::AltModifier) && m_lightTool->press(toolEvent)) {
        // Ctrl+left on the light gizmo's handle grabs the light (elsewhere Ctrl+left is the tool's).
        drag = Drag::Tool;
        tool = m_lightTool.get();
    } else if ((mods & Qt::AltModifier) && (mods & Qt::ShiftModifier) && button == Qt::LeftButton) {
        drag = Drag::Roll; // for matching a drawing's tilt (paper 1, section 3.1.1)
    } else if ((mods & Qt::AltModifier) && m_navigation.style == NavigationStyle::Maya) {
        // Maya: Alt + left orbit, middle pan, right dolly.
        if (button == Qt::LeftButton)
            drag = Drag::Orbit;
        else if (button == Qt::MiddleButton)
            drag = Drag::Pan;
        else if (button == Qt::RightButton)
            drag = Drag::Dolly;
    } else if (button == Qt::MiddleButton) {
        // Middle button alone for tablets and laptops where Alt is taken by the window manager.
        if (mods & Qt::ShiftModifier)
            drag = Drag::Pan;
        else if (mods & Qt::ControlModifier)
            drag = Drag::Dolly;
        else
            drag = Drag::Orbit;
    } else if (button == Qt::LeftButton && activeTool() && activeTool()->press(toolEvent)) {
        drag = Drag::Tool;
        tool = activeTool();
    }
    if (drag == Drag::None) {
        QOpenGLWidget::mousePressEvent(event);
        event->accept();
        return;
    }
    m_drag = drag;
    m_dragTool = tool;
    m_dragButton = button;
    m_lastPos = event->position();
    m_rollDragged = m_rollApplied = 0.0;
    if (drag == Drag::Orbit && m_navigation.orbitAroundCursor) {
        if (const auto hit = pickSurface(event->position()))
            m_camera->setPivot(hit->second);
    }
    if (drag != Drag::Tool && activeTool())
        activeTool()->navigationStarted();
    switch (drag) {
    case Drag::Orbit:
        setCursor(Qt::ClosedHandCursor);
        break;
    case Drag::Pan:
        setCursor(Qt::SizeAllCursor);
        break;
    case Drag::Dolly:
        setCursor(Qt::SizeVerCursor);
        break;
    case Drag::Roll:
        setCursor(Qt::SizeHorCursor);
        break;
    case Drag::Tool:
        setCursor(tool->cursor());
        break;
    case Drag::None:
        break;
    }
    event->accept();
}

void Viewport::endDrag(bool cancelled)
{
    if (m_drag == Drag::Tool && m_dragTool) {
        ViewportTool* tool = m_dragTool;
        m_dragTool = nullptr;
        if (cancelled)
            tool->cancel();
        else
            tool->release({m_lastPos, {}, Qt::NoModifier});
    } else if (m_drag != Drag::None && activeTool()) {
        activeTool()->navigationEnded();
    }
    m_drag = Drag::None;
    m_dragButton = Qt::NoButton;
    setCursor(activeTool() ? activeTool()->cursor() : Qt::ArrowCursor);
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (m_drag == Drag::None) {
        if (ViewportTool* tool = activeTool(); tool && event->buttons() == Qt::NoButton)
            tool->hover(event->position());
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    if (!(event->buttons() & m_dragButton)) {
        // The release went elsewhere (a popup, a window manager grab): end the drag here.
        endDrag(true);
        return;
    }
    const QPointF delta = event->position() - m_lastPos;
    m_lastPos = event->position();
    if (delta.isNull())
        return;
    switch (m_drag) {
    case Drag::Orbit:
        m_camera->orbit(delta.x() * kOrbitDegreesPerPixel * m_navigation.orbitSpeed,
            delta.y() * kOrbitDegreesPerPixel * m_navigation.orbitSpeed);
        cameraEdited();
        break;
    case Drag::Pan:
        m_camera->pan(delta);
        cameraEdited();
        break;
    // Dragging right or up brings the camera closer.
    case Drag::Dolly:
        m_camera->dolly(std::exp(-kDollyPerPixel * (delta.x() - delta.y())));
        cameraEdited();
        break;
    case Drag::Roll: {
        // Ctrl snaps the drag's roll to 15 degree steps (Blender's and Maya's snapping key).
        m_rollDragged += delta.x() * kOrbitDegreesPerPixel;
        const double wanted = (event->modifiers() & Qt::ControlModifier)
            ? kRollSnapDegrees * std::round(m_rollDragged / kRollSnapDegrees)
            : m_rollDragged;
        if (wanted != m_rollApplied) {
            m_camera->roll(wanted - m_rollApplied);
            m_rollApplied = wanted;
            cameraEdited();
        }
        break;
    }
    case Drag::Tool:
        if (m_dragTool)
            m_dragTool->move({event->position(), delta, event->modifiers()});
        break;
    case Drag::None:
        break;
    }
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None && event->button() == m_dragButton) {
        m_lastPos = event->position();
        endDrag(false);
        event->accept();
        return;
    }
    QOpenGLWidget::mouseReleaseEvent(event);
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    // A burst of wheel ticks is one navigation gesture for the tool (one undo step while aligning).
    if (!m_wheelBurst.isActive() && activeTool())
        activeTool()->navigationStarted();
    m_wheelBurst.start();
    m_camera->dolly(std::pow(kDollyPerWheelNotch, notches));
    cameraEdited();
    event->accept();
}

void Viewport::leaveEvent(QEvent* event)
{
    if (ViewportTool* tool = activeTool())
        tool->leave();
    QOpenGLWidget::leaveEvent(event);
}

bool Viewport::event(QEvent* event)
{
    // Keys the tool wants come here before the window's shortcuts (the brush's F, Esc while resizing).
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (ViewportTool* tool = activeTool();
            tool && m_drag == Drag::None && tool->wantsKey(key->key(), key->modifiers())) {
            event->accept();
            return true;
        }
    }
    return QOpenGLWidget::event(event);
}

bool Viewport::toolTakesKey(const QKeyEvent& event) const
{
    ViewportTool* tool = activeTool();
    if (!tool || m_drag != Drag::None)
        return false;
    if (tool->wantsKey(event.key(), event.modifiers()))
        return true;
    // The brush-size keys are the viewport's, but they belong to the brushes' work.
    const auto command = viewportKeyCommand(event);
    return (m_tool == Tool::Brush || m_tool == Tool::OffsetBrush)
        && (command == ViewportKeyCommand::BrushSmaller || command == ViewportKeyCommand::BrushLarger);
}

void Viewport::keyPressEvent(QKeyEvent* event)
{
    if (ViewportTool* tool = activeTool();
        tool && m_drag == Drag::None && tool->keyPress(event->key(), event->modifiers())) {
        event->accept();
        return;
    }
    // The keys and what they do are listed in one table (viewport_keys.h) for the help too.
    const auto command = viewportKeyCommand(*event);
    if (!command) {
        QOpenGLWidget::keyPressEvent(event);
        return;
    }
    switch (*command) {
    case ViewportKeyCommand::FrameAll:
        frameAll();
        break;
    case ViewportKeyCommand::FrontView:
        if (m_tool == Tool::Align || !refusedWhileHeld(tr("The front view")))
            resetView();
        break;
    case ViewportKeyCommand::BrushResize: // the brush tool's own (viewportKeyCommand never gives it)
        break;
    case ViewportKeyCommand::BrushSmaller:
    case ViewportKeyCommand::BrushLarger: {
        // Krita's and Photoshop's brush-size keys.
        const double factor = *command == ViewportKeyCommand::BrushLarger ? 1.25 : 0.8;
        emit message(m_brushSize->scale(factor));
        if (ViewportTool* tool = activeTool())
            tool->hover(mapFromGlobal(QCursor::pos()));
        break;
    }
    }
    event->accept();
}

} // namespace celform::views
