// Routing a tool's keys from anywhere in the window (tool_keys.h).
#include "editor/actions/tool_keys.h"

#include "celform/views/viewport/viewport.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPointer>
#include <QTextEdit>

namespace celform::app {
namespace {

/// Whether a widget types the keys into text (a name, a number): those keep them.
bool takesText(const QWidget* widget)
{
    for (const QWidget* w = widget; w; w = w->parentWidget())
        if (qobject_cast<const QLineEdit*>(w) || qobject_cast<const QAbstractSpinBox*>(w)
            || qobject_cast<const QTextEdit*>(w) || qobject_cast<const QPlainTextEdit*>(w))
            return true;
    return false;
}

class ToolKeyRouter : public QObject {
public:
    ToolKeyRouter(QWidget* window, views::Viewport* viewport)
        : QObject(window)
        , m_window(window)
        , m_viewport(viewport)
    { }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
            return false;
        auto* widget = qobject_cast<QWidget*>(watched);
        if (!widget || !m_viewport || widget == m_viewport || widget->window() != m_window
            || m_viewport->isAncestorOf(widget) || !m_viewport->isVisible() || takesText(widget))
            return false;
        auto* key = static_cast<QKeyEvent*>(event);
        if (!m_viewport->toolTakesKey(*key))
            return false;
        if (event->type() == QEvent::ShortcutOverride) {
            event->accept(); // no window shortcut: the press comes next, and goes to the viewport
            return true;
        }
        QKeyEvent press(
            QEvent::KeyPress, key->key(), key->modifiers(), key->text(), key->isAutoRepeat(), ushort(key->count()));
        QApplication::sendEvent(m_viewport, &press);
        return true;
    }

private:
    QWidget* m_window;
    QPointer<views::Viewport> m_viewport;
};

} // namespace

void routeToolKeys(QWidget* window, views::Viewport* viewport)
{
    qApp->installEventFilter(new ToolKeyRouter(window, viewport));
}

} // namespace celform::app
