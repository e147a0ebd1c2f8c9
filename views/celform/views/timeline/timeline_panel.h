// The Timeline dock: the scene's frame range and frames per second (each edit one undo
// step through AnimationEdits::setSceneTime), the transport (play/pause, loop, start/end, previous/next
// frame and key) and the ruler with the key marks of every kind. The playhead is the document's.
#pragma once

#include "celform/views/timeline/timeline_ruler.h"

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QToolButton;

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class Playback;

class TimelinePanel : public QWidget {
    Q_OBJECT
public:
    explicit TimelinePanel(model::Document* document, QWidget* parent = nullptr);

    [[nodiscard]] Playback* playback() const { return m_playback; }
    [[nodiscard]] TimelineRuler* ruler() const { return m_ruler; }
    [[nodiscard]] QSpinBox* firstFrameBox() const { return m_first; }
    [[nodiscard]] QSpinBox* lastFrameBox() const { return m_last; }
    [[nodiscard]] QDoubleSpinBox* fpsBox() const { return m_fps; }
    [[nodiscard]] QSpinBox* currentFrameBox() const { return m_current; }
    [[nodiscard]] QToolButton* playButton() const { return m_play; }
    [[nodiscard]] QToolButton* loopButton() const { return m_loop; }
    /// The key marks shown (every kind), as on the ruler.
    [[nodiscard]] const std::vector<TimelineMark>& marks() const { return m_ruler->marks(); }
    /// The achieved-rate readout while playing.
    [[nodiscard]] QString fpsReadout() const;

public slots:
    void jumpToStart();
    void jumpToEnd();
    /// One frame on (delta 1) or back (-1), within the range (wrapping when looping).
    void stepFrame(int delta);
    /// To the next (direction 1) or previous (-1) keyed frame of any kind; nothing when none.
    void jumpToKey(int direction);

private:
    void documentChanged(const model::ChangeSet& change);
    /// Spin boxes and ruler from the document.
    void refreshTime();
    void refreshMarks();
    void applySceneTime();
    void setFrame(int frame);

    model::Document* m_document;
    Playback* m_playback;
    TimelineRuler* m_ruler;
    QSpinBox* m_first;
    QSpinBox* m_last;
    QDoubleSpinBox* m_fps;
    QSpinBox* m_current;
    QToolButton* m_play;
    QToolButton* m_loop;
    QLabel* m_achieved;
    bool m_refreshing = false;
};

} // namespace celform::views
