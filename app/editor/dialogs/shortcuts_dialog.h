// Help > Keyboard Shortcuts: every shortcut of the window (shortcuts.h) grouped by menu, the
// viewport's and the stereo review's own keys included, with a filter line that matches names,
// menus, keys and descriptions.
#pragma once

#include <QDialog>

class QLineEdit;
class QTreeWidget;

namespace celform::app {

class ShortcutList;

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    /// The shortcuts of window (the main window).
    explicit ShortcutsDialog(QWidget* window, QWidget* parent = nullptr);

    [[nodiscard]] QLineEdit* filterEdit() const;
    [[nodiscard]] QTreeWidget* tree() const;
    /// Shortcuts listed now (after the filter), not counting the group headings.
    [[nodiscard]] int visibleCount() const;
    /// The names of the shortcuts listed now with their keys ("Save As: Ctrl+Shift+S").
    [[nodiscard]] QStringList visibleEntries() const;

public slots:
    /// Lists the window's shortcuts as they are now (after a change in the preferences).
    void refresh();
    void setFilter(const QString& text);

private:
    QWidget* m_window;
    ShortcutList* m_list;
};

} // namespace celform::app
