// The filtered command list (shortcut_list.h).
#include "editor/settings/shortcut_list.h"

#include <QHBoxLayout>
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

ShortcutList::ShortcutList(const QStringList& headers, QWidget* parent)
    : QWidget(parent)
{
    m_filter = new QLineEdit(this);
    m_filter->setClearButtonEnabled(true);
    auto* filterLabel = new QLabel(tr("&Filter:"), this);
    filterLabel->setBuddy(m_filter);
    auto* filterRow = new QHBoxLayout;
    filterRow->addWidget(filterLabel);
    filterRow->addWidget(m_filter, 1);

    m_tree = new QTreeWidget(this);
    m_tree->setColumnCount(int(headers.size()));
    m_tree->setHeaderLabels(headers);
    m_tree->setRootIsDecorated(false);
    m_tree->setItemsExpandable(false);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->header()->setStretchLastSection(true);
    m_empty = new QLabel(this);
    m_empty->setAlignment(Qt::AlignCenter);
    m_empty->hide();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(filterRow);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_empty);
    connect(m_filter, &QLineEdit::textChanged, this, &ShortcutList::setFilter);
}

QTreeWidgetItem* ShortcutList::addRow(const QString& group, const QStringList& columns, const QString& search)
{
    QTreeWidgetItem* parent = nullptr;
    for (int g = 0; g < m_tree->topLevelItemCount() && !parent; ++g)
        if (m_tree->topLevelItem(g)->text(0) == group)
            parent = m_tree->topLevelItem(g);
    if (!parent) {
        parent = new QTreeWidgetItem(m_tree, {group});
        parent->setFirstColumnSpanned(true);
        QFont bold = font();
        bold.setBold(true);
        parent->setFont(0, bold);
        parent->setFlags(Qt::ItemIsEnabled);
    }
    auto* item = new QTreeWidgetItem(parent, columns);
    setSearchText(item, search);
    return item;
}

void ShortcutList::setSearchText(QTreeWidgetItem* item, const QString& search)
{
    QString text = item->parent() ? item->parent()->text(0) : QString();
    for (int column = 0; column < item->columnCount(); ++column)
        text += QLatin1Char(' ') + item->text(column);
    item->setData(0, kSearchRole, (text + QLatin1Char(' ') + search).toLower());
}

void ShortcutList::clear()
{
    m_tree->clear();
}

void ShortcutList::finish(const QList<int>& maxWidths)
{
    m_tree->expandAll();
    // Long descriptions would push the keys out of sight: the full text is the tooltip.
    for (int column = 0; column < maxWidths.size(); ++column) {
        m_tree->resizeColumnToContents(column);
        m_tree->setColumnWidth(column, std::min(m_tree->columnWidth(column) + 16, maxWidths[column]));
    }
    setFilter(m_filter->text());
}

void ShortcutList::setFilter(const QString& text)
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
    m_empty->setText(tr("No command matches “%1”.").arg(text.trimmed()));
    m_empty->setVisible(shown == 0);
}

QStringList ShortcutList::visibleRows() const
{
    QStringList rows;
    for (int g = 0; g < m_tree->topLevelItemCount(); ++g) {
        const QTreeWidgetItem* group = m_tree->topLevelItem(g);
        for (int i = 0; i < group->childCount(); ++i)
            if (!group->isHidden() && !group->child(i)->isHidden())
                rows << group->child(i)->text(0) + QStringLiteral(": ") + group->child(i)->text(1);
    }
    return rows;
}

} // namespace celform::app
