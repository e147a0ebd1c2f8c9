// Gestures for controls (DESIGN.md, "The document": one slider drag, one press-and-hold of a spin
// box arrow, one run of key repeats or one burst of wheel ticks is one undo step). The tracker
// opens a document gesture when such a run starts and ends it when the run ends; the edits the
// control makes in between merge (the control's handler passes GestureTracker::of(control) to
// the document), and nothing else does.
#pragma once

#include "celform/model/document/gesture.h"

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
    /// The gesture open on a tracked control (none when no run is on or it is not tracked): what
    /// the control's edits hand to the document.
    [[nodiscard]] static model::GestureId of(const QObject* control);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    GestureTracker(QWidget* control, model::Document* document);
    void begin();
    void end();

    model::Document* m_document;
    model::Gesture m_gesture;
    QTimer m_wheelEnd; ///< a pause in wheel ticks ends their gesture
};

} // namespace celform::views
