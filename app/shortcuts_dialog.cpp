// The keyboard shortcuts dialog (shortcuts_dialog.h).
#include "shortcuts_dialog.h"

#include "shortcuts.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace celform::app {
namespace {

/// Item data: what the filter matches, lower case.
constexpr int kSearchRole = Qt::UserRole + 1;

} // namespace

ShortcutsDialog::ShortcutsDialog(QWidget* window, QWidget* parent)
    : QDialog(parent)
    , m_window(window)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard Shortcuts"));
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("shortcutsFilter"));
    m_filter->setPlaceholderText(tr("Filter by name, menu or key (save, view, ctrl+s)"));
    m_filter->setToolTip(tr("Shows the shortcuts whose name, menu, key or description contains the text"));
    m_filter->setClearButtonEnabled(true);
    auto* filterLabel = new QLabel(tr("&Filter:"), this);
    filterLabel->setBuddy(m_filter);
    auto* filterRow = new QHBoxLayout;
    filterRow->addWidget(filterLabel);
    filterRow->addWidget(m_filter, 1);

    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("shortcutsTree"));
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Command"), tr("Shortcut"), tr("Description")});
    m_tree->setRootIsDecorated(false);
    m_tree->setItemsExpandable(false);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->header()->setStretchLastSection(true);
    m_tree->setToolTip(tr("Change the keys in Edit ▸ Preferences ▸ Shortcuts"));
    m_empty = new QLabel(this);
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->hide();

    auto* note = new QLabel(tr("Keys of menu commands can be changed in Edit ▸ Preferences ▸ Shortcuts. The "
                               "viewport's and the stereo review's own keys are fixed."),
        this);
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(filterRow);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_empty);
    layout->addWidget(note);
    layout->addWidget(buttons);
    connect(m_filter, &QLineEdit::textChanged, this, &ShortcutsDialog::setFilter);
    resize(880, 680);
    refresh();
    m_filter->setFocus();
}

void ShortcutsDialog::refresh()
{
    m_tree->clear();
    QMap<QString, QTreeWidgetItem*> groups;
    QFont bold = font();
    bold.setBold(true);
    for (const ShortcutEntry& entry : collectShortcuts(m_window)) {
        QTreeWidgetItem*& group = groups[entry.group];
        if (!group) {
            group = new QTreeWidgetItem(m_tree, {entry.group});
            group->setFirstColumnSpanned(true);
            group->setFont(0, bold);
            group->setFlags(Qt::ItemIsEnabled);
        }
        QStringList keys;
        QString search = entry.group + QLatin1Char(' ') + entry.name + QLatin1Char(' ') + entry.description;
        for (const QKeySequence& key : entry.keys) {
            keys << key.toString(QKeySequence::NativeText);
            search += QLatin1Char(' ') + key.toString(QKeySequence::NativeText) + QLatin1Char(' ')
                + key.toString(QKeySequence::PortableText);
        }
        auto* item = new QTreeWidgetItem(group, {entry.name, keys.join(QStringLiteral(", ")), entry.description});
        item->setToolTip(0, entry.description.isEmpty() ? entry.name : entry.description);
        item->setToolTip(2, entry.description);
        item->setData(0, kSearchRole, search.toLower());
    }
    m_tree->expandAll();
    // The review's long descriptions would push the keys out of sight: their full text is the
    // tooltip.
    for (int column = 0; column < 2; ++column) {
        m_tree->resizeColumnToContents(column);
        m_tree->setColumnWidth(column, std::min(m_tree->columnWidth(column) + 16, column == 0 ? 300 : 180));
    }
    setFilter(m_filter->text());
}

void ShortcutsDialog::setFilter(const QString& text)
{
    const QString needle = text.trimmed().toLower();
    int shown = 0;
    for (int g = 0; g < m_tree->topLevelItemCount(); ++g) {
        QTreeWidgetItem* group = m_tree->topLevelItem(g);
        int inGroup = 0;
        for (int i = 0; i < group->childCount(); ++i) {
            QTreeWidgetItem* item = group->child(i);
            const bool match = needle.isEmpty() || item->data(0, kSearchRole).toString().contains(needle);
            item->setHidden(!match);
            inGroup += match ? 1 : 0;
        }
        group->setHidden(inGroup == 0);
        shown += inGroup;
    }
    m_empty->setText(tr("No shortcut matches “%1”.").arg(text.trimmed()));
    m_empty->setVisible(shown == 0);
}

int ShortcutsDialog::visibleCount() const
{
    return int(visibleEntries().size());
}

QStringList ShortcutsDialog::visibleEntries() const
{
    QStringList entries;
    for (int g = 0; g < m_tree->topLevelItemCount(); ++g) {
        const QTreeWidgetItem* group = m_tree->topLevelItem(g);
        for (int i = 0; i < group->childCount(); ++i)
            if (!group->isHidden() && !group->child(i)->isHidden())
                entries << group->child(i)->text(0) + QStringLiteral(": ") + group->child(i)->text(1);
    }
    return entries;
}

} // namespace celform::app
