// Playing the scene at its frame rate (playback.h).
#include "celform/views/timeline/playback.h"

#include "celform/model/document/document.h"

#include <cmath>

namespace celform::views {

Playback::Playback(model::Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &Playback::tick);
    connect(m_document, &model::Document::changed, this, [this](const model::ChangeSet& change) {
        if (!isPlaying())
            return;
        if (change.reset) {
            pause();
            return;
        }
        // A new rate, a new range or a scrub while playing: go on from where the playhead is.
        if (change.has(model::Part::SceneTime) || (change.has(model::Part::Playhead) && !m_moving)) {
            restartClock();
            scheduleNext();
        }
    });
}

void Playback::setLooping(bool on)
{
    if (on == m_looping)
        return;
    m_looping = on;
    emit loopingChanged(on);
}

void Playback::restartClock()
{
    m_originFrame = m_document->currentFrame();
    m_clock.start();
}

void Playback::scheduleNext()
{
    // Ticks land just after a frame begins, not at a fixed interval: an interval a little shorter
    // than a frame (41 ms at 24 fps) drifts until ticks fall just before frame boundaries, where
    // any paint that runs a few milliseconds late makes the next tick skip a frame. Landing after
    // the boundary leaves the whole frame's time as slack.
    const double fps = std::max(1e-3, m_document->data().time.fps);
    const double elapsed = double(m_clock.nsecsElapsed()) * 1e-9 * fps; // in frames
    const double toNext = (std::floor(elapsed) + 1.0 - elapsed) * 1000.0 / fps; // in ms
    m_timer.start(int(std::ceil(toNext)) + 1);
}

void Playback::play()
{
    if (isPlaying() || !m_document->hasMesh())
        return;
    const model::SceneTime& time = m_document->data().time;
    const int frame = m_document->currentFrame();
    if (frame < time.firstFrame || frame >= time.lastFrame) {
        m_moving = true;
        m_document->setCurrentFrame(time.firstFrame);
        m_moving = false;
    }
    restartClock();
    m_steps = 0;
    m_windowSteps = 0;
    m_windowClock.start();
    m_achievedFps = 0.0;
    m_playing = true;
    scheduleNext();
    emit playingChanged(true);
}

void Playback::pause()
{
    if (!isPlaying())
        return;
    m_playing = false;
    m_timer.stop();
    m_achievedFps = 0.0;
    emit playingChanged(false);
    emit achievedFpsChanged(0.0);
}

void Playback::toggle()
{
    if (isPlaying())
        pause();
    else
        play();
}

void Playback::tick()
{
    const model::SceneTime& time = m_document->data().time;
    const int first = time.firstFrame, last = time.lastFrame;
    // The frame the clock says it is: frames skipped while the previous one was drawn are dropped.
    const long long elapsedFrames = (long long)(std::floor(double(m_clock.nsecsElapsed()) * 1e-9 * time.fps));
    long long target = (long long)(m_originFrame) + elapsedFrames;
    bool stop = false;
    if (target > last) {
        if (m_looping) {
            const long long length = (long long)(last)-first + 1;
            target = first + (target - first) % length;
        } else {
            target = last;
            stop = true;
        }
    }
    if (int(target) != m_document->currentFrame()) {
        m_moving = true;
        m_document->setCurrentFrame(int(target));
        m_moving = false;
        ++m_steps;
        ++m_windowSteps;
    }
    const qint64 window = m_windowClock.elapsed();
    if (window >= 500) {
        m_achievedFps = 1000.0 * m_windowSteps / double(window);
        m_windowSteps = 0;
        m_windowClock.restart();
        emit achievedFpsChanged(m_achievedFps);
    }
    if (stop)
        pause();
    else if (m_playing && !m_timer.isActive())
        scheduleNext();
}

} // namespace celform::views
