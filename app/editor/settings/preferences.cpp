// The editor's preferences (preferences.h).
#include "editor/settings/preferences.h"

#include "editor/main_window.h"
#include "editor/recovery_manager.h"

#include "celform/model/document/document.h"

#include <QAction>
#include <QChildEvent>
#include <QSettings>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace celform::app {
namespace {

const char* const kNavigationStyleKey = "navigation/style";
const char* const kOrbitModeKey = "navigation/orbitMode";
const char* const kOrbitSpeedKey = "navigation/orbitSpeed";
const char* const kOrbitAroundCursorKey = "navigation/orbitAroundCursor";
const char* const kAutosaveKey = "autosave/minutes"; // read by MainWindow at start too
const char* const kUndoLimitKey = "editing/undoLimit";
const char* const kLanguageKey = "ui/language";
const char* const kNewProjectStyleKey = "project/newStyle";
const QString kShortcutsGroup = QStringLiteral("shortcuts");

/// Stable names of the stored choices (not translated, not enum numbers).
template <typename Enum> struct Names {
    std::vector<std::pair<Enum, const char*>> entries;

    [[nodiscard]] QString name(Enum value) const
    {
        for (const auto& [e, n] : entries)
            if (e == value)
                return QString::fromLatin1(n);
        return QString::fromLatin1(entries.front().second);
    }
    [[nodiscard]] Enum value(const QString& name, Enum fallback) const
    {
        for (const auto& [e, n] : entries)
            if (name == QLatin1String(n))
                return e;
        return fallback;
    }
};

const Names<views::NavigationStyle> kNavigationNames{
    {{views::NavigationStyle::Maya, "maya"}, {views::NavigationStyle::Blender, "blender"}}};
const Names<views::OrbitMode> kOrbitNames{
    {{views::OrbitMode::Turntable, "turntable"}, {views::OrbitMode::Trackball, "trackball"}}};
const Names<Preferences::Language> kLanguageNames{{{Preferences::Language::System, "system"},
    {Preferences::Language::English, "en"}, {Preferences::Language::Japanese, "ja"}}};
const Names<model::ShadingStyle> kStyleNames{
    {{model::ShadingStyle::Toon, "toon"}, {model::ShadingStyle::Gooch, "gooch"}, {model::ShadingStyle::Comic, "comic"},
        {model::ShadingStyle::Lambert, "lambert"}}};

} // namespace

Preferences Preferences::load()
{
    QSettings settings;
    return load(settings);
}

Preferences Preferences::load(QSettings& settings)
{
    Preferences p;
    p.navigationStyle
        = kNavigationNames.value(settings.value(kNavigationStyleKey).toString(), views::NavigationStyle::Maya);
    p.orbitMode = kOrbitNames.value(settings.value(kOrbitModeKey).toString(), views::OrbitMode::Turntable);
    const double speed = settings.value(kOrbitSpeedKey, 1.0).toDouble();
    p.orbitSpeed = std::isfinite(speed) ? std::clamp(speed, kMinOrbitSpeed, kMaxOrbitSpeed) : 1.0;
    p.orbitAroundCursor = settings.value(kOrbitAroundCursorKey, false).toBool();
    p.autosaveMinutes = std::clamp(settings.value(kAutosaveKey, 3).toInt(), 0, kMaxAutosaveMinutes);
    p.undoLimit = std::clamp(settings.value(kUndoLimitKey, 0).toInt(), 0, kMaxUndoLimit);
    p.language = kLanguageNames.value(settings.value(kLanguageKey).toString(), Language::System);
    p.newProjectStyle = kStyleNames.value(settings.value(kNewProjectStyleKey).toString(), model::ShadingStyle::Toon);
    settings.beginGroup(kShortcutsGroup);
    for (const QString& name : settings.childKeys())
        p.shortcuts.insert(name, QKeySequence::fromString(settings.value(name).toString(), QKeySequence::PortableText));
    settings.endGroup();
    return p;
}

void Preferences::save() const
{
    QSettings settings;
    save(settings);
}

void Preferences::save(QSettings& settings) const
{
    settings.setValue(kNavigationStyleKey, kNavigationNames.name(navigationStyle));
    settings.setValue(kOrbitModeKey, kOrbitNames.name(orbitMode));
    settings.setValue(kOrbitSpeedKey, orbitSpeed);
    settings.setValue(kOrbitAroundCursorKey, orbitAroundCursor);
    settings.setValue(kAutosaveKey, autosaveMinutes);
    settings.setValue(kUndoLimitKey, undoLimit);
    settings.setValue(kLanguageKey, kLanguageNames.name(language));
    settings.setValue(kNewProjectStyleKey, kStyleNames.name(newProjectStyle));
    settings.remove(kShortcutsGroup);
    settings.beginGroup(kShortcutsGroup);
    for (auto it = shortcuts.constBegin(); it != shortcuts.constEnd(); ++it)
        settings.setValue(it.key(), it.value().toString(QKeySequence::PortableText));
    settings.endGroup();
}

QLocale Preferences::locale() const
{
    switch (language) {
    case Language::English:
        return QLocale(QLocale::English, QLocale::UnitedStates);
    case Language::Japanese:
        return QLocale(QLocale::Japanese, QLocale::Japan);
    case Language::System:
        break;
    }
    return QLocale();
}

bool Preferences::operator==(const Preferences& o) const
{
    return navigationStyle == o.navigationStyle && orbitMode == o.orbitMode && orbitSpeed == o.orbitSpeed
        && orbitAroundCursor == o.orbitAroundCursor && autosaveMinutes == o.autosaveMinutes && undoLimit == o.undoLimit
        && language == o.language && newProjectStyle == o.newProjectStyle && shortcuts == o.shortcuts;
}

// --- applying them ------------------------------------------------------------------------------

PreferencesApplier::PreferencesApplier(MainWindow* window)
    : QObject(window)
    , m_window(window)
{
    setObjectName(QStringLiteral("preferencesApplier"));
    rememberDefaultShortcuts(window);
    // Viewports shown later (the stereo review, a child window) get the navigation settings too.
    window->installEventFilter(this);
    QUndoStack* stack = window->document()->undoStack();
    connect(stack, &QUndoStack::indexChanged, this, &PreferencesApplier::applyUndoLimit);
    connect(window->document(), &model::Document::changed, this, &PreferencesApplier::applyUndoLimit);
    apply(Preferences::load());
}

void PreferencesApplier::apply(const Preferences& prefs)
{
    m_prefs = prefs;
    applyToViewports(m_window);
    // Batch windows (screenshots, tests) never autosave.
    if (m_window->mode() == MainWindow::Mode::Interactive)
        m_window->recovery()->setInterval(prefs.autosaveMinutes * 60 * 1000);
    m_pendingUndoLimit = prefs.undoLimit;
    applyUndoLimit();
    applyShortcuts(m_window, prefs.shortcuts);
}

void PreferencesApplier::applyToViewports(QObject* root)
{
    for (views::Viewport* viewport : root->findChildren<views::Viewport*>()) {
        viewport->setNavigation(
            {m_prefs.navigationStyle, m_prefs.orbitMode, m_prefs.orbitSpeed, m_prefs.orbitAroundCursor});
    }
}

void PreferencesApplier::applyUndoLimit()
{
    QUndoStack* stack = m_window->document()->undoStack();
    if (m_pendingUndoLimit < 0 || stack->count() > 0)
        return;
    stack->setUndoLimit(m_pendingUndoLimit);
    m_pendingUndoLimit = -1;
}

bool PreferencesApplier::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_window && event->type() == QEvent::ChildPolished)
        if (QObject* child = static_cast<QChildEvent*>(event)->child())
            applyToViewports(child);
    return QObject::eventFilter(watched, event);
}

} // namespace celform::app
