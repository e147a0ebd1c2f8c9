// Playing the scene: moves the document's playhead at the scene's frames per second.
// The playhead follows the clock, not the ticks: when drawing a frame takes longer than a frame
// lasts, frames are dropped rather than the animation slowing down.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class Playback : public QObject {
    Q_OBJECT
public:
    explicit Playback(model::Document* document, QObject* parent = nullptr);

    [[nodiscard]] bool isPlaying() const { return m_playing; }
    /// Looping: after the last frame comes the first again. Otherwise playing stops at the last.
    void setLooping(bool on);
    [[nodiscard]] bool isLooping() const { return m_looping; }
    /// Frames actually shown per second while playing (playhead moves), over the last half
    /// second or so; 0 when stopped.
    [[nodiscard]] double achievedFps() const { return m_achievedFps; }
    /// Playhead moves since play() (each one a frame drawn).
    [[nodiscard]] int stepsPlayed() const { return m_steps; }

public slots:
    /// Starts from the playhead (from the first frame when it is at the end or outside the range).
    void play();
    void pause();
    void toggle();

signals:
    void playingChanged(bool playing);
    void achievedFpsChanged(double fps);
    void loopingChanged(bool on);

private:
    void tick();
    void restartClock();
    /// Arms the timer for just after the next frame begins on the clock.
    void scheduleNext();

    model::Document* m_document;
    QTimer m_timer; ///< single shot, armed by scheduleNext()
    bool m_playing = false;
    QElapsedTimer m_clock; ///< since m_originFrame
    int m_originFrame = 0;
    bool m_looping = true;
    bool m_moving = false; ///< the playhead is being moved by this player
    int m_steps = 0;
    // The achieved rate over a window of steps.
    QElapsedTimer m_windowClock;
    int m_windowSteps = 0;
    double m_achievedFps = 0.0;
};

} // namespace celform::views
