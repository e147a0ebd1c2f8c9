// The editor's keyboard shortcuts in one place: the window's actions (grouped by the menu that
// holds them), the keys the viewport and the stereo review handle themselves (their own tables),
// the actions' default keys, the user's keys from the preferences, and conflicts between them.
// Help > Keyboard Shortcuts and Edit > Preferences both read this.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QMap>
#include <QString>

#include <vector>

class QAction;
class QMenu;
class QWidget;

namespace celform::app {

struct ShortcutEntry {
    QString group; ///< the menu path ("View ▸ View From"), "Viewport" or "Stereo Review"
    QString name; ///< what it is called in its menu, without & and …
    QString description; ///< the action's tooltip, or what a fixed key does
    QList<QKeySequence> keys;
    QAction* action = nullptr; ///< null for the viewport's and the review's own keys
};

/// The window's actions that can have a shortcut: those with an object name ("action…"), in
/// creation order.
[[nodiscard]] std::vector<QAction*> shortcutActions(const QWidget* window);

/// A new action of the window (an "action…" object name, so it is listed with the shortcuts):
/// its text, default key (may be empty) and the tip shown as tooltip and in the status bar.
QAction* addWindowAction(
    QWidget* window, const QString& objectName, const QString& text, const QKeySequence& key, const QString& tip);

/// The window's menu holding an action (the first, if several), or null.
[[nodiscard]] QMenu* menuOf(const QAction* action);
/// The menu path of an action ("File", "View ▸ View From"), or "Other" outside the menus.
[[nodiscard]] QString actionGroup(const QAction* action);
/// The action's name as its menu shows it, without & and the trailing ellipsis.
[[nodiscard]] QString actionName(const QAction* action);

/// Every shortcut of the window: its actions with keys, then the viewport's own keys that no
/// action takes first, then the stereo review's keys. withoutKeys also lists actions with none.
[[nodiscard]] std::vector<ShortcutEntry> collectShortcuts(const QWidget* window, bool withoutKeys = false);

/// Notes each action's keys as its defaults (once, before any user keys are applied).
void rememberDefaultShortcuts(const QWidget* window);
/// The keys an action had before the user's preferences.
[[nodiscard]] QList<QKeySequence> defaultShortcuts(const QAction* action);

/// The user's key for an action (its first shortcut; empty: none) by object name.
using ShortcutOverrides = QMap<QString, QKeySequence>;
/// Gives each named action its user key (keeping its other default keys), the others their
/// defaults.
void applyShortcuts(const QWidget* window, const ShortcutOverrides& overrides);
/// The keys an action has with the given user key: that key first, then the defaults' other keys.
[[nodiscard]] QList<QKeySequence> keysWith(const QAction* action, const QKeySequence& primary);

/// A key given to several actions: Qt runs none of them (an ambiguous shortcut).
struct ShortcutConflict {
    QKeySequence key;
    std::vector<const QAction*> actions; ///< two or more, in the window's order
    /// "Ctrl+S is given to “Save” and to “Render Image”."
    [[nodiscard]] QString text() const;
};
/// The keys given to several actions, for the actions' keys as they would be (keysByAction;
/// actions not in it keep theirs); empty when there are none.
[[nodiscard]] std::vector<ShortcutConflict> shortcutConflicts(
    const QWidget* window, const QMap<const QAction*, QList<QKeySequence>>& keysByAction);
/// Sentences naming each key the viewport handles itself (brush size, ...) that an action would
/// take from it, other than the action's default keys (F and Home do the same either way).
[[nodiscard]] QStringList shadowedViewportKeys(
    const QWidget* window, const QMap<const QAction*, QList<QKeySequence>>& keysByAction);

} // namespace celform::app
