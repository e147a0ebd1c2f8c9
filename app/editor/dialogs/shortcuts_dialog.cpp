// The keyboard shortcuts dialog (shortcuts_dialog.h).
#include "editor/dialogs/shortcuts_dialog.h"

#include "editor/settings/shortcut_list.h"
#include "editor/settings/shortcuts.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace celform::app {

ShortcutsDialog::ShortcutsDialog(QWidget* window, QWidget* parent)
    : QDialog(parent)
    , m_window(window)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard Shortcuts"));
    m_list = new ShortcutList({tr("Command"), tr("Shortcut"), tr("Description")}, this);
    m_list->filterEdit()->setObjectName(QStringLiteral("shortcutsFilter"));
    m_list->filterEdit()->setPlaceholderText(tr("Filter by name, menu or key (save, view, ctrl+s)"));
    m_list->filterEdit()->setToolTip(tr("Shows the shortcuts whose name, menu, key or description contains the text"));
    m_list->tree()->setObjectName(QStringLiteral("shortcutsTree"));
    m_list->tree()->setUniformRowHeights(true);
    m_list->tree()->setAlternatingRowColors(true);
    m_list->tree()->setToolTip(tr("Change the keys in Edit ▸ Preferences ▸ Shortcuts"));

    auto* note = new QLabel(tr("Keys of menu commands can be changed in Edit ▸ Preferences ▸ Shortcuts. The "
                               "viewport's and the stereo review's own keys are fixed; Help ▸ Navigation shows "
                               "the mouse."),
        this);
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_list, 1);
    layout->addWidget(note);
    layout->addWidget(buttons);
    resize(880, 680);
    refresh();
    m_list->filterEdit()->setFocus();
}

QLineEdit* ShortcutsDialog::filterEdit() const
{
    return m_list->filterEdit();
}

QTreeWidget* ShortcutsDialog::tree() const
{
    return m_list->tree();
}

void ShortcutsDialog::refresh()
{
    m_list->clear();
    for (const ShortcutEntry& entry : collectShortcuts(m_window)) {
        QStringList keys;
        QString search;
        for (const QKeySequence& key : entry.keys) {
            keys << key.toString(QKeySequence::NativeText);
            search += QLatin1Char(' ') + key.toString(QKeySequence::PortableText);
        }
        QTreeWidgetItem* item
            = m_list->addRow(entry.group, {entry.name, keys.join(QStringLiteral(", ")), entry.description}, search);
        item->setToolTip(0, entry.description.isEmpty() ? entry.name : entry.description);
        item->setToolTip(2, entry.description);
    }
    m_list->finish({300, 180});
}

void ShortcutsDialog::setFilter(const QString& text)
{
    m_list->filterEdit()->setText(text);
}

int ShortcutsDialog::visibleCount() const
{
    return int(visibleEntries().size());
}

QStringList ShortcutsDialog::visibleEntries() const
{
    return m_list->visibleRows();
}

} // namespace celform::app
