// The editor's preferences (Edit > Preferences), stored with QSettings: viewport navigation,
// autosave, undo depth, language, the look of new projects and the user's keyboard shortcuts.
// Everything but the language applies to a running window at once (apply()); the undo limit waits
// for an empty history (QUndoStack refuses a new limit while it holds steps).
#pragma once

#include "editor/settings/shortcuts.h"

#include "celform/model/data/project_data.h"
#include "celform/views/viewport/viewport.h"

#include <QLocale>
#include <QObject>
#include <QString>

class QSettings;

namespace celform::app {

class MainWindow;

struct Preferences {
    enum class Language { System, English, Japanese };

    views::NavigationStyle navigationStyle = views::NavigationStyle::Maya;
    views::OrbitMode orbitMode = views::OrbitMode::Turntable;
    double orbitSpeed = 1.0; ///< multiplies the orbit's degrees per pixel, 0.1 to 5
    bool orbitAroundCursor = false; ///< Maya's tumble pivot: orbit around the point under the cursor
    int autosaveMinutes = 3; ///< 0: no autosave
    int undoLimit = 0; ///< steps kept; 0: no limit
    Language language = Language::System; ///< applied at the next start
    model::ShadingStyle newProjectStyle = model::ShadingStyle::Toon; ///< the look's style of new projects
    ShortcutOverrides shortcuts; ///< by action object name; only keys that differ from the defaults

    static constexpr double kMinOrbitSpeed = 0.1;
    static constexpr double kMaxOrbitSpeed = 5.0;
    static constexpr int kMaxAutosaveMinutes = 120;
    static constexpr int kMaxUndoLimit = 10000;

    /// The stored preferences (defaults where nothing is stored or a value is out of range).
    [[nodiscard]] static Preferences load();
    [[nodiscard]] static Preferences load(QSettings& settings);
    void save() const;
    void save(QSettings& settings) const;

    /// The locale the editor's translations follow (the system's for Language::System).
    [[nodiscard]] QLocale locale() const;

    bool operator==(const Preferences& o) const;
    bool operator!=(const Preferences& o) const { return !(*this == o); }
};

/// Keeps a main window in step with the preferences: applies them at once, again to viewports
/// shown later (the stereo review) and the undo limit when the history next becomes empty.
class PreferencesApplier : public QObject {
    Q_OBJECT
public:
    /// Notes the window's default shortcuts and applies the stored preferences.
    explicit PreferencesApplier(MainWindow* window);

    /// Applies prefs to the window (not the language: that needs a restart).
    void apply(const Preferences& prefs);
    [[nodiscard]] const Preferences& current() const { return m_prefs; }
    /// The undo limit waiting for an empty history, or -1.
    [[nodiscard]] int pendingUndoLimit() const { return m_pendingUndoLimit; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void applyToViewports(QObject* root);
    void applyUndoLimit();

    MainWindow* m_window;
    Preferences m_prefs;
    int m_pendingUndoLimit = -1;
};

} // namespace celform::app
