// The editor's keyboard shortcuts (shortcuts.h).
#include "editor/settings/shortcuts.h"

#include "editor/review_window.h"

#include "celform/views/viewport/viewport_keys.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenu>
#include <QRegularExpression>
#include <QVariant>
#include <QWidget>

#include <algorithm>
#include <iterator>

namespace celform::app {
namespace {

const char* const kDefaultKeysProperty = "celformDefaultShortcuts";

struct ShortcutText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::Shortcuts)
};

/// A menu's or an action's text as shown: & marks removed (&& is a literal &), and with them
/// the "(&N)" mnemonics of Japanese menus; no ellipsis.
QString plainText(QString text)
{
    static const QRegularExpression mnemonic(QStringLiteral("\\(&[^&]\\)"));
    text.remove(mnemonic);
    QString out;
    for (int i = 0; i < text.size(); ++i) {
        if (text[i] != QLatin1Char('&')) {
            out += text[i];
        } else if (i + 1 < text.size() && text[i + 1] == QLatin1Char('&')) {
            out += QLatin1Char('&');
            ++i;
        }
    }
    if (out.endsWith(QChar(0x2026)))
        out.chop(1);
    else if (out.endsWith(QLatin1String("...")))
        out.chop(3);
    return out.trimmed();
}

/// The keys of each action as they would be: keysByAction's, else the action's own.
QList<QKeySequence> keysOf(const QAction* action, const QMap<const QAction*, QList<QKeySequence>>& keysByAction)
{
    const auto it = keysByAction.constFind(action);
    QList<QKeySequence> keys = it != keysByAction.constEnd() ? *it : action->shortcuts();
    keys.removeAll(QKeySequence());
    return keys;
}

QString keyText(const QKeySequence& key)
{
    return key.toString(QKeySequence::NativeText);
}

} // namespace

QAction* addWindowAction(
    QWidget* window, const QString& objectName, const QString& text, const QKeySequence& key, const QString& tip)
{
    auto* action = new QAction(text, window);
    action->setObjectName(objectName);
    action->setShortcut(key);
    action->setToolTip(tip);
    action->setStatusTip(tip);
    window->addAction(action);
    return action;
}

QMenu* menuOf(const QAction* action)
{
    // Menus without a title are not the window's: the menu bar's overflow menu holds the menus
    // that did not fit at some point.
    for (QObject* object : action->associatedObjects())
        if (auto* menu = qobject_cast<QMenu*>(object); menu && !menu->title().isEmpty())
            return menu;
    return nullptr;
}

std::vector<QAction*> shortcutActions(const QWidget* window)
{
    std::vector<QAction*> actions;
    for (QAction* action : window->findChildren<QAction*>())
        if (action->objectName().startsWith(QLatin1String("action")))
            actions.push_back(action);
    return actions;
}

QString actionGroup(const QAction* action)
{
    QStringList path;
    for (const QMenu* menu = menuOf(action); menu;) {
        path.prepend(plainText(menu->title()));
        menu = menuOf(menu->menuAction());
    }
    return path.isEmpty() ? ShortcutText::tr("Other") : path.join(QStringLiteral(" ▸ "));
}

QString actionName(const QAction* action)
{
    const QString fixed = action->property("shortcutName").toString();
    return fixed.isEmpty() ? plainText(action->text()) : fixed;
}

std::vector<ShortcutEntry> collectShortcuts(const QWidget* window, bool withoutKeys)
{
    std::vector<ShortcutEntry> entries;
    QList<QKeySequence> taken;
    for (QAction* action : shortcutActions(window)) {
        QList<QKeySequence> keys = action->shortcuts();
        keys.removeAll(QKeySequence());
        taken += keys;
        if (keys.isEmpty() && !withoutKeys)
            continue;
        entries.push_back({actionGroup(action), actionName(action), action->toolTip(), keys, action});
    }
    // The viewport's own keys reach it only when no action of the window takes them first; a
    // tool's keys go to it before the window's shortcuts while the tool is on.
    const QString viewport = ShortcutText::tr("Viewport");
    const QString brush = ShortcutText::tr("Viewport ▸ Brush tool");
    for (const views::ViewportKeyBinding& binding : views::viewportKeyBindings()) {
        const bool tool = binding.scope != views::ViewportKeyBinding::Scope::Viewport;
        if (tool || !taken.contains(binding.sequence()))
            entries.push_back(
                {tool ? brush : viewport, binding.description(), QString(), {binding.sequence()}, nullptr});
    }
    const QString review = ShortcutText::tr("Stereo Review");
    for (const ReviewWindow::KeyBinding& binding : ReviewWindow::keyBindings()) {
        const QString text = binding.description();
        entries.push_back(
            {review, text.left(1).toUpper() + text.mid(1), QString(), {QKeySequence(binding.key)}, nullptr});
    }
    return entries;
}

void rememberDefaultShortcuts(const QWidget* window)
{
    for (QAction* action : shortcutActions(window))
        if (!action->property(kDefaultKeysProperty).isValid())
            action->setProperty(kDefaultKeysProperty, QVariant::fromValue(action->shortcuts()));
}

QList<QKeySequence> defaultShortcuts(const QAction* action)
{
    const QVariant keys = action->property(kDefaultKeysProperty);
    return keys.isValid() ? keys.value<QList<QKeySequence>>() : action->shortcuts();
}

QList<QKeySequence> keysWith(const QAction* action, const QKeySequence& primary)
{
    QList<QKeySequence> keys = defaultShortcuts(action);
    if (!keys.isEmpty())
        keys.removeFirst();
    keys.removeAll(primary);
    if (!primary.isEmpty())
        keys.prepend(primary);
    return keys;
}

void applyShortcuts(const QWidget* window, const ShortcutOverrides& overrides)
{
    for (QAction* action : shortcutActions(window)) {
        const auto it = overrides.constFind(action->objectName());
        action->setShortcuts(it == overrides.constEnd() ? defaultShortcuts(action) : keysWith(action, *it));
    }
}

QString ShortcutConflict::text() const
{
    QStringList others;
    for (std::size_t i = 1; i < actions.size(); ++i)
        others << QStringLiteral("“%1”").arg(actionName(actions[i]));
    return ShortcutText::tr("%1 is given to “%2” and to %3.")
        .arg(keyText(key), actionName(actions.front()), others.join(ShortcutText::tr(" and ", "between action names")));
}

std::vector<ShortcutConflict> shortcutConflicts(
    const QWidget* window, const QMap<const QAction*, QList<QKeySequence>>& keysByAction)
{
    // Keys in the order their first action comes, each with the actions that have it.
    std::vector<ShortcutConflict> byKey;
    for (const QAction* action : shortcutActions(window))
        for (const QKeySequence& key : keysOf(action, keysByAction)) {
            auto it
                = std::find_if(byKey.begin(), byKey.end(), [&key](const ShortcutConflict& c) { return c.key == key; });
            if (it == byKey.end())
                byKey.push_back({key, {action}});
            else if (std::find(it->actions.begin(), it->actions.end(), action) == it->actions.end())
                it->actions.push_back(action);
        }
    std::vector<ShortcutConflict> conflicts;
    std::copy_if(byKey.begin(), byKey.end(), std::back_inserter(conflicts),
        [](const ShortcutConflict& c) { return c.actions.size() > 1; });
    return conflicts;
}

QStringList shadowedViewportKeys(const QWidget* window, const QMap<const QAction*, QList<QKeySequence>>& keysByAction)
{
    QStringList notes;
    for (const QAction* action : shortcutActions(window)) {
        const QList<QKeySequence> defaults = defaultShortcuts(action);
        for (const QKeySequence& key : keysOf(action, keysByAction)) {
            if (defaults.contains(key))
                continue;
            for (const views::ViewportKeyBinding& binding : views::viewportKeyBindings())
                if (binding.scope == views::ViewportKeyBinding::Scope::Viewport && binding.sequence() == key)
                    notes << ShortcutText::tr("%1 is the viewport's key for “%2”: “%3” takes it first.")
                                 .arg(keyText(key), binding.description(), actionName(action));
        }
    }
    return notes;
}

} // namespace celform::app
