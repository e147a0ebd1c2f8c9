// The preferences dialog (preferences_dialog.h).
#include "editor/dialogs/preferences_dialog.h"

#include "editor/main_window.h"
#include "editor/settings/shortcut_list.h"
#include "editor/settings/shortcuts.h"

#include "celform/model/document/document.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStyle>
#include <QTabWidget>
#include <QTreeWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <set>

namespace celform::app {
namespace {

const char* const kActionProperty = "celformAction";

void selectData(QComboBox* combo, const QVariant& value)
{
    const int index = combo->findData(value);
    if (index >= 0)
        combo->setCurrentIndex(index);
}

QLabel* noteLabel(QWidget* parent, const QString& name)
{
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setForegroundRole(QPalette::PlaceholderText);
    return label;
}

} // namespace

PreferencesDialog::PreferencesDialog(PreferencesApplier* applier, MainWindow* window, QWidget* parent)
    : QDialog(parent)
    , m_applier(applier)
    , m_window(window)
{
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    m_tabs = new QTabWidget(this);
    m_tabs->addTab(buildNavigationPage(), tr("&Navigation"));
    m_tabs->addTab(buildGeneralPage(), tr("&General"));
    m_tabs->addTab(buildShortcutsPage(), tr("&Shortcuts"));

    m_buttons = new QDialogButtonBox(
        QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::Apply | QDialogButtonBox::RestoreDefaults,
        this);
    m_buttons->button(QDialogButtonBox::Apply)->setToolTip(tr("Store and apply the preferences, keep the dialog open"));
    m_buttons->button(QDialogButtonBox::RestoreDefaults)
        ->setToolTip(tr("Put every preference and key back to Celform's default (stored on OK or Apply)"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &PreferencesDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &PreferencesDialog::reject);
    connect(m_buttons->button(QDialogButtonBox::Apply), &QPushButton::clicked, this, &PreferencesDialog::apply);
    connect(m_buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
        &PreferencesDialog::restoreDefaults);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_tabs, 1);
    layout->addWidget(m_buttons);
    showValues(m_applier->current());
    resize(760, 600);
}

QWidget* PreferencesDialog::buildNavigationPage()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    m_navigationStyle = new QComboBox(page);
    m_navigationStyle->setObjectName(QStringLiteral("prefNavigationStyle"));
    m_navigationStyle->addItem(tr("Maya"), int(views::NavigationStyle::Maya));
    m_navigationStyle->addItem(tr("Blender"), int(views::NavigationStyle::Blender));
    m_navigationStyle->setToolTip(tr("Which mouse buttons and keys move the viewport's camera"));
    form->addRow(tr("Navigation &style:"), m_navigationStyle);
    m_navigationHelp = noteLabel(page, QStringLiteral("prefNavigationHelp"));
    form->addRow(QString(), m_navigationHelp);

    m_orbitMode = new QComboBox(page);
    m_orbitMode->setObjectName(QStringLiteral("prefOrbitMode"));
    m_orbitMode->addItem(tr("Turntable (around the up axis)"), int(views::OrbitMode::Turntable));
    m_orbitMode->addItem(tr("Trackball (free, can roll over)"), int(views::OrbitMode::Trackball));
    m_orbitMode->setToolTip(tr("Turntable keeps the model upright as Maya and Blender do by default; trackball "
                               "turns freely about the view's axes"));
    form->addRow(tr("&Orbit:"), m_orbitMode);

    m_orbitSpeed = new QDoubleSpinBox(page);
    m_orbitSpeed->setObjectName(QStringLiteral("prefOrbitSpeed"));
    m_orbitSpeed->setRange(Preferences::kMinOrbitSpeed, Preferences::kMaxOrbitSpeed);
    m_orbitSpeed->setSingleStep(0.1);
    m_orbitSpeed->setDecimals(2);
    m_orbitSpeed->setSuffix(tr(" ×"));
    m_orbitSpeed->setToolTip(tr("How fast the camera turns for a drag: 1 is 0.4 degrees per pixel"));
    form->addRow(tr("Orbit s&peed:"), m_orbitSpeed);

    m_orbitAroundCursor = new QCheckBox(tr("Orbit around the point under the &cursor"), page);
    m_orbitAroundCursor->setObjectName(QStringLiteral("prefOrbitAroundCursor"));
    m_orbitAroundCursor->setToolTip(tr("An orbit turns around the surface point where the drag starts (Maya's "
                                       "tumble pivot); elsewhere around the framed centre"));
    form->addRow(QString(), m_orbitAroundCursor);
    connect(m_navigationStyle, qOverload<int>(&QComboBox::currentIndexChanged), this, &PreferencesDialog::updateState);
    return page;
}

QWidget* PreferencesDialog::buildGeneralPage()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    m_autosave = new QSpinBox(page);
    m_autosave->setObjectName(QStringLiteral("prefAutosave"));
    m_autosave->setRange(0, Preferences::kMaxAutosaveMinutes);
    m_autosave->setSpecialValueText(tr("Off"));
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setToolTip(tr("How often unsaved work is copied to a recovery file, offered after a crash; "
                              "0 turns autosave off"));
    form->addRow(tr("&Autosave every:"), m_autosave);

    m_undoLimit = new QSpinBox(page);
    m_undoLimit->setObjectName(QStringLiteral("prefUndoLimit"));
    m_undoLimit->setRange(0, Preferences::kMaxUndoLimit);
    m_undoLimit->setSpecialValueText(tr("Unlimited"));
    m_undoLimit->setSingleStep(10);
    m_undoLimit->setToolTip(tr("How many steps Undo can go back; older steps are forgotten"));
    form->addRow(tr("&Undo steps kept:"), m_undoLimit);
    m_undoNote = noteLabel(page, QStringLiteral("prefUndoNote"));
    form->addRow(QString(), m_undoNote);

    m_language = new QComboBox(page);
    m_language->setObjectName(QStringLiteral("prefLanguage"));
    const QString system = QLocale().nativeLanguageName();
    m_language->addItem(
        system.isEmpty() ? tr("System") : tr("System (%1)").arg(system), int(Preferences::Language::System));
    // Each language in its own name, so it can be found whatever the interface shows now.
    m_language->addItem(QStringLiteral("English"), int(Preferences::Language::English));
    m_language->addItem(QStringLiteral("日本語 (Japanese)"), int(Preferences::Language::Japanese));
    m_language->setToolTip(tr("The language of the editor's menus, panels and messages"));
    form->addRow(tr("&Language:"), m_language);
    m_languageNote = noteLabel(page, QStringLiteral("prefLanguageNote"));
    form->addRow(QString(), m_languageNote);

    m_newProjectStyle = new QComboBox(page);
    m_newProjectStyle->setObjectName(QStringLiteral("prefNewProjectStyle"));
    const std::pair<model::ShadingStyle, QString> styles[]
        = {{model::ShadingStyle::Toon, tr("Toon")}, {model::ShadingStyle::Gooch, tr("Gooch")},
            {model::ShadingStyle::Comic, tr("Comic")}, {model::ShadingStyle::Lambert, tr("Lambert")}};
    for (const auto& [style, label] : styles)
        m_newProjectStyle->addItem(label, int(style));
    m_newProjectStyle->setToolTip(tr("The shading style a project started from a mesh begins with (File ▸ New "
                                     "from Mesh); the rest of its look has Celform's defaults"));
    form->addRow(tr("New projects' &shading:"), m_newProjectStyle);
    connect(m_language, qOverload<int>(&QComboBox::currentIndexChanged), this, &PreferencesDialog::updateState);
    connect(m_undoLimit, qOverload<int>(&QSpinBox::valueChanged), this, &PreferencesDialog::updateState);
    return page;
}

QWidget* PreferencesDialog::buildShortcutsPage()
{
    auto* page = new QWidget(this);
    m_shortcutList = new ShortcutList({tr("Command"), tr("Shortcut"), tr("Default")}, page);
    m_shortcutList->filterEdit()->setObjectName(QStringLiteral("prefShortcutFilter"));
    m_shortcutList->filterEdit()->setPlaceholderText(tr("Filter by name, menu or key"));
    m_shortcutTree = m_shortcutList->tree();
    m_shortcutTree->setObjectName(QStringLiteral("prefShortcutTree"));
    for (const ShortcutEntry& entry : collectShortcuts(m_window, /*withoutKeys=*/true)) {
        if (!entry.action)
            continue; // the viewport's and the review's own keys are fixed
        QStringList defaults;
        for (const QKeySequence& key : defaultShortcuts(entry.action))
            defaults << key.toString(QKeySequence::NativeText);
        QTreeWidgetItem* item
            = m_shortcutList->addRow(entry.group, {entry.name, QString(), defaults.join(QStringLiteral(", "))});
        item->setToolTip(0, entry.description);
        auto* edit = new QKeySequenceEdit(m_shortcutTree);
        edit->setObjectName(QStringLiteral("shortcut:") + entry.action->objectName());
        edit->setProperty(kActionProperty, QVariant::fromValue(static_cast<QObject*>(entry.action)));
        edit->setClearButtonEnabled(true);
        edit->setToolTip(
            tr("Click and press the new key for “%1”; the clear button removes it. Tab moves on.").arg(entry.name));
        // The key editor's line edit has the focus: Tab is caught there (eventFilter).
        for (QLineEdit* line : edit->findChildren<QLineEdit*>())
            line->installEventFilter(this);
        m_shortcutTree->setItemWidget(item, 1, edit);
        m_shortcutEdits.insert(entry.action->objectName(), edit);
        m_shortcutItems.insert(edit, item);
        connect(edit, &QKeySequenceEdit::keySequenceChanged, this, [item](const QKeySequence& key) {
            ShortcutList::setSearchText(item, key.toString(QKeySequence::PortableText));
        });
        connect(edit, &QKeySequenceEdit::keySequenceChanged, this, &PreferencesDialog::updateState);
    }
    m_shortcutList->finish({260, 220});

    auto* reset = new QPushButton(tr("&Reset to Default"), page);
    reset->setToolTip(tr("Give the selected command its default key again"));
    connect(reset, &QPushButton::clicked, this, [this] {
        QTreeWidgetItem* item = m_shortcutTree->currentItem();
        auto* edit = item ? qobject_cast<QKeySequenceEdit*>(m_shortcutTree->itemWidget(item, 1)) : nullptr;
        if (!edit)
            return;
        const auto* action = qobject_cast<const QAction*>(edit->property(kActionProperty).value<QObject*>());
        edit->setKeySequence(defaultShortcuts(action).value(0));
    });
    m_conflicts = new QLabel(page);
    m_conflicts->setObjectName(QStringLiteral("prefConflicts"));
    m_conflicts->setWordWrap(true);
    m_conflicts->setTextFormat(Qt::RichText);

    auto* note = noteLabel(page, QString());
    note->setText(tr("Commands with several keys keep their other defaults (the view presets' keypad keys, "
                     "Redo's Ctrl+Y). The viewport's own keys are listed in Help ▸ Keyboard Shortcuts."));
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_shortcutList, 1);
    auto* resetRow = new QHBoxLayout;
    resetRow->addWidget(m_conflicts, 1);
    resetRow->addWidget(reset, 0, Qt::AlignRight | Qt::AlignTop);
    layout->addLayout(resetRow);
    layout->addWidget(note);
    return page;
}

void PreferencesDialog::showValues(const Preferences& prefs)
{
    selectData(m_navigationStyle, int(prefs.navigationStyle));
    selectData(m_orbitMode, int(prefs.orbitMode));
    m_orbitSpeed->setValue(prefs.orbitSpeed);
    m_orbitAroundCursor->setChecked(prefs.orbitAroundCursor);
    m_autosave->setValue(prefs.autosaveMinutes);
    m_undoLimit->setValue(prefs.undoLimit);
    selectData(m_language, int(prefs.language));
    selectData(m_newProjectStyle, int(prefs.newProjectStyle));
    for (auto it = m_shortcutEdits.constBegin(); it != m_shortcutEdits.constEnd(); ++it) {
        const auto* action = qobject_cast<const QAction*>(it.value()->property(kActionProperty).value<QObject*>());
        const auto user = prefs.shortcuts.constFind(it.key());
        const QSignalBlocker block(it.value());
        it.value()->setKeySequence(user != prefs.shortcuts.constEnd() ? *user : defaultShortcuts(action).value(0));
    }
    updateState();
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.navigationStyle = views::NavigationStyle(m_navigationStyle->currentData().toInt());
    p.orbitMode = views::OrbitMode(m_orbitMode->currentData().toInt());
    p.orbitSpeed = m_orbitSpeed->value();
    p.orbitAroundCursor = m_orbitAroundCursor->isChecked();
    p.autosaveMinutes = m_autosave->value();
    p.undoLimit = m_undoLimit->value();
    p.language = Preferences::Language(m_language->currentData().toInt());
    p.newProjectStyle = model::ShadingStyle(m_newProjectStyle->currentData().toInt());
    // Only keys that differ from the default are stored: a new default reaches the user.
    for (auto it = m_shortcutEdits.constBegin(); it != m_shortcutEdits.constEnd(); ++it) {
        const auto* action = qobject_cast<const QAction*>(it.value()->property(kActionProperty).value<QObject*>());
        if (it.value()->keySequence() != defaultShortcuts(action).value(0))
            p.shortcuts.insert(it.key(), it.value()->keySequence());
    }
    return p;
}

QMap<const QAction*, QList<QKeySequence>> PreferencesDialog::editedKeys() const
{
    QMap<const QAction*, QList<QKeySequence>> keys;
    for (QKeySequenceEdit* edit : m_shortcutEdits) {
        const auto* action = qobject_cast<const QAction*>(edit->property(kActionProperty).value<QObject*>());
        keys.insert(action, keysWith(action, edit->keySequence()));
    }
    return keys;
}

QStringList PreferencesDialog::conflicts() const
{
    QStringList texts;
    for (const ShortcutConflict& conflict : shortcutConflicts(m_window, editedKeys()))
        texts << conflict.text();
    return texts;
}

QKeySequenceEdit* PreferencesDialog::shortcutEdit(const QString& actionName) const
{
    return m_shortcutEdits.value(actionName);
}

void PreferencesDialog::updateState()
{
    const bool maya = views::NavigationStyle(m_navigationStyle->currentData().toInt()) == views::NavigationStyle::Maya;
    QString navigation = maya
        ? tr("Alt + left drag orbits, Alt + middle drag pans, Alt + right drag dollies; the middle button "
             "alone (with Shift: pan, Ctrl: dolly) and the wheel work too.")
        : tr("Middle drag orbits, Shift + middle drag pans, Ctrl + middle drag dollies, the wheel dollies; "
             "Alt + left drag goes to the tool.");
    // Linux desktops (GNOME, KDE, Xfce, ...) move windows with Alt + drag by default, before the
    // viewport sees it; Qt cannot ask the window manager, so a running desktop is reason to say so.
    if (maya && !qEnvironmentVariableIsEmpty("XDG_CURRENT_DESKTOP"))
        navigation += QLatin1Char(' ')
            + tr("Your desktop (%1) may take Alt + drag to move windows: if the viewport does not orbit, "
                 "choose Blender, which needs no Alt.")
                  .arg(qEnvironmentVariable("XDG_CURRENT_DESKTOP"));
    m_navigationHelp->setText(navigation);
    const Preferences::Language started = m_applier->current().language;
    const bool languageChanged = Preferences::Language(m_language->currentData().toInt()) != started;
    m_languageNote->setText(languageChanged ? tr("<b>Restart Celform to use the new language.</b>")
                                            : tr("A new language applies the next time Celform starts."));
    const QUndoStack* stack = m_window->document()->undoStack();
    m_undoNote->setText(stack->count() > 0 && m_undoLimit->value() != stack->undoLimit()
            ? tr("The history holds steps now: the new limit applies when it is next empty (a project opened "
                 "or started).")
            : tr("Fewer steps use less memory after long brushing sessions."));

    // Conflicts: the rows in red, the sentences below; OK and Apply wait until they are solved.
    const std::vector<ShortcutConflict> found = shortcutConflicts(m_window, editedKeys());
    std::set<const QAction*> conflicting;
    QStringList lines;
    for (const ShortcutConflict& conflict : found) {
        conflicting.insert(conflict.actions.begin(), conflict.actions.end());
        lines << conflict.text().toHtmlEscaped();
    }
    for (const QString& note : shadowedViewportKeys(m_window, editedKeys()))
        lines << QStringLiteral("<span style=\"color:#8a6d00\">%1</span>").arg(note.toHtmlEscaped());
    for (auto it = m_shortcutItems.constBegin(); it != m_shortcutItems.constEnd(); ++it) {
        const auto* action = qobject_cast<const QAction*>(it.key()->property(kActionProperty).value<QObject*>());
        const bool bad = conflicting.count(action) > 0;
        it.value()->setForeground(0, bad ? QBrush(QColor(0xc0, 0x39, 0x2b)) : QBrush());
        it.value()->setIcon(0, bad ? style()->standardIcon(QStyle::SP_MessageBoxWarning) : QIcon());
    }
    m_conflicts->setText(found.empty()
            ? lines.join(QStringLiteral("<br>"))
            : QStringLiteral("<span style=\"color:#c0392b\">%1</span>").arg(lines.join(QStringLiteral("<br>"))));
    m_conflicts->setVisible(!lines.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(found.empty());
    m_buttons->button(QDialogButtonBox::Apply)->setEnabled(found.empty());
    if (!found.empty())
        m_buttons->button(QDialogButtonBox::Ok)->setToolTip(tr("Give each key to one command first"));
    else
        m_buttons->button(QDialogButtonBox::Ok)->setToolTip(QString());
}

bool PreferencesDialog::apply()
{
    if (!conflicts().isEmpty()) {
        m_tabs->setCurrentIndex(2);
        return false;
    }
    const Preferences prefs = preferences();
    prefs.save();
    m_applier->apply(prefs);
    updateState();
    return true;
}

void PreferencesDialog::accept()
{
    if (apply())
        QDialog::accept();
}

void PreferencesDialog::restoreDefaults()
{
    showValues(Preferences());
}

bool PreferencesDialog::eventFilter(QObject* watched, QEvent* event)
{
    // A key editor records every key, Tab included: let Tab and Shift+Tab move on instead, so the
    // page stays usable from the keyboard (Tab alone is no use as a shortcut).
    if (event->type() == QEvent::KeyPress && qobject_cast<QKeySequenceEdit*>(watched->parent())) {
        auto* key = static_cast<QKeyEvent*>(event);
        const Qt::KeyboardModifiers mods = key->modifiers() & ~Qt::ShiftModifier;
        if ((key->key() == Qt::Key_Tab || key->key() == Qt::Key_Backtab) && mods == Qt::NoModifier) {
            focusNextPrevChild(key->key() == Qt::Key_Tab);
            return true;
        }
    }
    return QDialog::eventFilter(watched, event);
}

} // namespace celform::app
