// The operations of the selected highlight layer at the playhead (Anjyo & Hiramitsu 2003,
// "Highlight operations": translation, rotation, directional scaling, split, squaring, applied in
// order): one row per operation with its parameters (keyed), and buttons that reorder, remove or
// add operations in every key so that the keys keep interpolating.
#pragma once

#include "celform/algorithms/highlights.h"
#include "celform/model/data/object_id.h"

#include <QGroupBox>

#include <functional>
#include <utility>
#include <vector>

class QDoubleSpinBox;
class QToolButton;
class QVBoxLayout;

namespace celform::model {
class Document;
}

namespace celform::views {

class HighlightOperationsBox : public QGroupBox {
    Q_OBJECT
public:
    HighlightOperationsBox(model::Document* document, QWidget* parent = nullptr);

    /// Shows a layer's operations at the playhead (0: none); rows are rebuilt only when the
    /// operation types change, so a spin box being edited survives a refresh.
    void showLayer(model::ObjectId layer);

private:
    void rebuildRows(const std::vector<algo::HighlightOperationType>& types);
    /// Runs a document operation; a refused edit puts the rows back.
    void run(const std::function<void()>& operation);

    model::Document* m_document;
    model::ObjectId m_layer = 0;
    QVBoxLayout* m_rows;
    QToolButton* m_add;
    std::vector<algo::HighlightOperationType> m_types; ///< the rows' types
    std::vector<std::pair<QDoubleSpinBox*, QDoubleSpinBox*>> m_spins;
};

} // namespace celform::views
