// A list of commands grouped by menu under a filter line: the shortcuts dialog's list and the
// preferences' key editors. The filter matches each row's search text (its name, menu, keys and
// description), case-insensitively; groups without a matching row hide.
#pragma once

#include <QStringList>
#include <QWidget>

class QLabel;
class QLineEdit;
class QTreeWidget;
class QTreeWidgetItem;

namespace celform::app {

class ShortcutList : public QWidget {
    Q_OBJECT
public:
    ShortcutList(const QStringList& headers, QWidget* parent = nullptr);

    [[nodiscard]] QLineEdit* filterEdit() const { return m_filter; }
    [[nodiscard]] QTreeWidget* tree() const { return m_tree; }

    /// Adds a row under its group (made, in bold, the first time), matched by the filter against
    /// search (besides the group's name and the row's columns).
    QTreeWidgetItem* addRow(const QString& group, const QStringList& columns, const QString& search = {});
    /// Replaces a row's extra search text (a key that was edited).
    static void setSearchText(QTreeWidgetItem* item, const QString& search);
    void clear();
    /// Expands the groups and fits the first columns (at most maxWidths[i] pixels).
    void finish(const QList<int>& maxWidths);

    /// The rows shown now, as "column 0: column 1".
    [[nodiscard]] QStringList visibleRows() const;

public slots:
    void setFilter(const QString& text);

private:
    QLineEdit* m_filter;
    QTreeWidget* m_tree;
    QLabel* m_empty;
};

} // namespace celform::app
