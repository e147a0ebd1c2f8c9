// The scene dock: the base model, the reference drawings and the key viewpoints as a tree.
// Renames, deletions and enabling go through the Document, so each one is an undo step.
#pragma once

#include "celform/model/document/document.h"

#include <QWidget>

class QTreeWidget;
class QTreeWidgetItem;

namespace celform::views {

class DrawingOverlay;

class ScenePanel : public QWidget {
    Q_OBJECT
public:
    enum class ItemKind { None, BaseModel, Drawing, Key };
    struct Selection {
        ItemKind kind = ItemKind::None;
        model::ObjectId id = 0;
        bool operator==(const Selection& o) const { return kind == o.kind && id == o.id; }
    };

    explicit ScenePanel(model::Document* document, QWidget* parent = nullptr);

    [[nodiscard]] Selection selection() const;
    void select(Selection selection);
    /// Removes the selected drawing or key (Delete key, Edit menu).
    void removeSelected();
    [[nodiscard]] QTreeWidget* tree() const { return m_tree; }
    /// The viewport's drawing overlay, whose drawing each drawing's eye shows and hides.
    void setDrawingOverlay(DrawingOverlay* overlay);
    /// The column of the drawings' eyes.
    static constexpr int kEyeColumn = 1;

signals:
    void selectionChanged(celform::views::ScenePanel::Selection selection);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void documentChanged(const model::ChangeSet& change);
    void rebuild();
    /// Refreshes one object's item (tooltip) without rebuilding the tree.
    void updateItem(model::ObjectId id);
    static QString drawingTip(const model::Drawing& drawing);
    static QString keyTip(const model::KeyViewpoint& key);
    void onItemChanged(QTreeWidgetItem* item, int column);
    /// Each drawing's eye: open when the overlay shows it.
    void updateEyes();

    model::Document* m_document;
    QTreeWidget* m_tree;
    QTreeWidgetItem* m_modelRoot = nullptr;
    QTreeWidgetItem* m_drawingsRoot = nullptr;
    QTreeWidgetItem* m_keysRoot = nullptr;
    bool m_rebuilding = false;
    DrawingOverlay* m_overlay = nullptr;
};

} // namespace celform::views
