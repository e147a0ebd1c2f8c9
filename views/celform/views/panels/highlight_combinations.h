// The Boolean combinations of the selected highlight layer (Anjyo & Hiramitsu 2003, "union" and
// "subtraction" of highlight areas): each row unites this layer's area with, or subtracts from it,
// another layer's area at the same frame.
#pragma once

#include "celform/model/data/object_id.h"

#include <QGroupBox>
#include <QString>

#include <vector>

class QPushButton;
class QVBoxLayout;

namespace celform::model {
class Document;
}

namespace celform::views {

class HighlightCombinationsBox : public QGroupBox {
    Q_OBJECT
public:
    HighlightCombinationsBox(model::Document* document, QWidget* parent = nullptr);

    /// Shows a layer's combinations (0: none); rows are rebuilt only when they or the other
    /// layers' names change.
    void showLayer(model::ObjectId layer);

private:
    void rebuildRows();

    model::Document* m_document;
    model::ObjectId m_layer = 0;
    QVBoxLayout* m_rows;
    QPushButton* m_add;
    /// What the rows show: layer, its combinations and the other layers' names, as text.
    QString m_shown;
};

} // namespace celform::views
