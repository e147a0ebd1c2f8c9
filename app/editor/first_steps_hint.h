// The empty states of the editor: a line at the bottom of the viewport saying what to do next
// while the project lacks a model, a drawing or a key (following the first key's steps: select a
// drawing, align, create the key); hidden once it has all three, and while a tool shows its own
// banner. A project opened with keys and a camera path (the showcase) gets a caption saying what
// to try, until the first click or key press.
#pragma once

#include "celform/model/data/object_id.h"

#include "celform/algorithms/tri_mesh.h"

#include <Eigen/Geometry>

#include <QLabel>
#include <QRect>

#include <memory>

namespace celform::model {
class Document;
}
namespace celform::views {
class Viewport;
}

namespace celform::app {

class FirstStepsHint : public QLabel {
    Q_OBJECT
public:
    FirstStepsHint(model::Document* document, views::Viewport* viewport);

    /// Text for the document's state now (empty: nothing to suggest).
    [[nodiscard]] QString hintText() const;
    /// The drawing selected in the Scene panel (0: none), whose alignment says the next step.
    void setSelectedDrawing(model::ObjectId drawing);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh();
    void place();
    /// The base model's bounding box as it falls in the viewport (empty without a model).
    [[nodiscard]] QRect modelRect();
    /// The first action after opening a showcase: its caption goes.
    void endShowcase();

    model::Document* m_document;
    views::Viewport* m_viewport;
    model::ObjectId m_selectedDrawing = 0;
    bool m_showcase = false;
    std::weak_ptr<const algo::TriMesh> m_boxOf; ///< the model m_box was measured on
    Eigen::AlignedBox3d m_box;
};

} // namespace celform::app
