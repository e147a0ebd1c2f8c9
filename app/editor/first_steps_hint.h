// The empty states of the editor: a line at the bottom of the viewport saying what to do next
// while the project lacks a model, a drawing or a key; hidden once it has all three, and while
// a tool shows its own banner.
#pragma once

#include <QLabel>

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

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh();
    void place();

    model::Document* m_document;
    views::Viewport* m_viewport;
};

} // namespace celform::app
