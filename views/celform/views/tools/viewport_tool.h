// The interface of the viewport's editing tools (brush, patch painting, alignment, light,
// highlight drag): the viewport handles navigation and hands the rest of a left-button drag to
// the active tool as press, move, release, or cancel when the drag ends another way. Tools turn
// pointer motion into document operations; they hold no document data of their own, but they own
// their settings (the panels reach them through Viewport::tool<T>()). A tool reports through its
// own signals (message, and the tool's own), which the viewport relays or listens to: it never
// emits the viewport's.
#pragma once

#include "celform/model/document/gesture.h"

#include <QCursor>
#include <QObject>
#include <QPointF>
#include <QString>

namespace celform::model {
class Document;
}

namespace celform::views {

class Viewport;

/// One pointer event in widget coordinates (logical pixels, y down).
struct ToolEvent {
    QPointF position;
    QPointF delta; ///< since the previous event of the drag (zero on press)
    Qt::KeyboardModifiers modifiers;
};

class ViewportTool : public QObject {
    Q_OBJECT
public:
    explicit ViewportTool(Viewport* viewport)
        : m_viewport(viewport)
    { }
    ~ViewportTool() override = default;

    /// The tool became active or inactive (setTool).
    virtual void activate() { }
    virtual void deactivate() { }
    /// Left-button press; true when the tool takes the drag (move and release follow).
    virtual bool press(const ToolEvent& event) = 0;
    virtual void move(const ToolEvent& /*event*/) { }
    /// The drag ended: by default endDrag() (its edits form one undo step).
    virtual void release(const ToolEvent& /*event*/) { endDrag(); }
    /// The drag ended without a release (tool change, a popup took the mouse): by default
    /// endDrag(), keeping what was done.
    virtual void cancel() { endDrag(); }
    /// The viewport's camera moved (navigation, programmatic).
    virtual void cameraChanged() { }
    /// A navigation gesture (an orbit, pan, dolly or roll drag, a burst of wheel ticks) starts or
    /// ends while the tool is on.
    virtual void navigationStarted() { }
    virtual void navigationEnded() { }
    [[nodiscard]] virtual Qt::CursorShape cursor() const { return Qt::CrossCursor; }
    /// The pointer moves over the viewport with no button held (hover feedback), or leaves it.
    virtual void hover(const QPointF& /*position*/) { }
    virtual void leave() { }
    /// A key the tool takes before the window's shortcuts (F resizes the brush, as in Blender);
    /// keyPress then handles it and returns whether it did.
    [[nodiscard]] virtual bool wantsKey(int /*key*/, Qt::KeyboardModifiers /*modifiers*/) const { return false; }
    virtual bool keyPress(int /*key*/, Qt::KeyboardModifiers /*modifiers*/) { return false; }
    /// Whether the tool works in the view of a document camera (a drawing's while aligning, a
    /// key's while brushing it): Frame All would take the view off it, so it is refused.
    [[nodiscard]] virtual bool holdsCamera() const { return false; }

signals:
    /// A message for the status bar (an edit refused, a hint); the viewport relays it.
    void message(const QString& text);

protected:
    /// Opens a document gesture for the drag: until closeGesture(), the tool's edits of one
    /// property merge into one undo step. Returns false without a document.
    bool openGesture();
    /// Ends the tool's gesture.
    void closeGesture();
    /// Ends what the drag opened: by default the tool's gesture; a tool whose drag is a
    /// document stroke ends the stroke.
    virtual void endDrag() { closeGesture(); }
    [[nodiscard]] bool inGesture() const { return m_gesture.isOpen(); }
    /// The drag's gesture, for the edits that merge (none outside a drag).
    [[nodiscard]] model::GestureId gesture() const { return m_gesture.id(); }

    Viewport* m_viewport;

private:
    model::Gesture m_gesture;
};

} // namespace celform::views
