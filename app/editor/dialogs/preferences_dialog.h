// Edit > Preferences: viewport navigation (Maya or Blender style, turntable or trackball orbit,
// orbit speed, orbit around the point under the cursor), autosave, undo steps, language, the
// shading style of new projects, and a key for each menu command with conflicts reported. OK and
// Apply store the preferences and apply them to the window at once (preferences.h).
#pragma once

#include "editor/settings/preferences.h"

#include <QDialog>
#include <QMap>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QKeySequenceEdit;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTabWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace celform::app {

class ShortcutList;

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    /// The preferences applier's (current) values for window; OK and Apply go through applier.
    PreferencesDialog(PreferencesApplier* applier, MainWindow* window, QWidget* parent = nullptr);

    /// The preferences as edited (not yet stored).
    [[nodiscard]] Preferences preferences() const;
    /// The key conflicts of the edited shortcuts, one sentence each; OK is disabled while any.
    [[nodiscard]] QStringList conflicts() const;
    /// The editor of an action's key (by object name), or null.
    [[nodiscard]] QKeySequenceEdit* shortcutEdit(const QString& actionName) const;
    [[nodiscard]] QTabWidget* tabs() const { return m_tabs; }

public slots:
    /// Stores and applies the preferences, then closes (refused while keys conflict).
    void accept() override;
    /// Stores and applies the preferences, the dialog stays open.
    bool apply();
    /// Puts every field to its default (stored on OK or Apply).
    void restoreDefaults();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* buildNavigationPage();
    QWidget* buildGeneralPage();
    QWidget* buildShortcutsPage();
    void showValues(const Preferences& prefs);
    void updateState();
    [[nodiscard]] QMap<const QAction*, QList<QKeySequence>> editedKeys() const;

    PreferencesApplier* m_applier;
    MainWindow* m_window;
    QTabWidget* m_tabs = nullptr;
    QComboBox* m_navigationStyle = nullptr;
    QLabel* m_navigationHelp = nullptr;
    QComboBox* m_orbitMode = nullptr;
    QDoubleSpinBox* m_orbitSpeed = nullptr;
    QCheckBox* m_orbitAroundCursor = nullptr;
    QSpinBox* m_autosave = nullptr;
    QSpinBox* m_undoLimit = nullptr;
    QLabel* m_undoNote = nullptr;
    QComboBox* m_language = nullptr;
    QLabel* m_languageNote = nullptr;
    QComboBox* m_newProjectStyle = nullptr;
    ShortcutList* m_shortcutList = nullptr;
    QTreeWidget* m_shortcutTree = nullptr;
    QMap<QString, QKeySequenceEdit*> m_shortcutEdits; ///< by action object name
    QMap<QKeySequenceEdit*, QTreeWidgetItem*> m_shortcutItems;
    QLabel* m_conflicts = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

} // namespace celform::app
