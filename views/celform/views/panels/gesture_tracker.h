// Gestures for controls (DESIGN.md, "The document": one slider drag, one press-and-hold of a spin
// box arrow, one run of key repeats or one burst of wheel ticks is one undo step). The tracker
// opens a document gesture when such a run starts and ends it when the run ends; the edits the
// control makes in between merge, and nothing else does.
#pragma once

#include <QObject>
#include <QTimer>

class QWidget;

namespace celform::model {
class Document;
}

namespace celform::views {

class GestureTracker : public QObject {
    Q_OBJECT
public:
    /// Tracks control (a QAbstractSpinBox or QAbstractSlider; owned by it from now on).
    static GestureTracker* track(QWidget* control, model::Document* document);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    GestureTracker(QWidget* control, model::Document* document);
    void begin();
    void end();

    model::Document* m_document;
    int m_gesture = 0;
    QTimer m_wheelEnd; ///< a pause in wheel ticks ends their gesture
};

} // namespace celform::views
