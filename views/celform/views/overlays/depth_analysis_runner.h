// Runs the stereo depth analysis (model::DepthAnalyser, paper 3 chapter 4) of what a viewport
// shows, on a worker thread of its own, so that orbiting never waits for it. Requests coalesce:
// while one analysis runs, only the newest request waits, and it starts when the first ends.
// It is the editor's one long job without a dialog: the analysis reports through the same
// algo::Progress as every other job, and closing the window cancels it between its steps.
#pragma once

#include "celform/model/data/camera.h"
#include "celform/model/analysis/depth_analysis.h"

#include <QImage>
#include <QObject>
#include <QPointer>
#include <QSize>
#include <QTimer>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

class Viewport;

/// One finished analysis, ready to show: the overlays as images and the figures.
struct DepthAnalysisResult {
    model::Camera camera; ///< the camera it was made through
    int frame = 0;
    int width = 0;
    int height = 0;
    QImage segments; ///< premultiplied ARGB overlays, transparent off the model
    QImage curvature;
    QImage depthError;
    float curvatureScale = 0.f; ///< |K| where the curvature overlay saturates
    float depthErrorScale = 0.f; ///< |error| where the depth-error overlay saturates
    std::vector<algo::SegmentStats> segmentStats;
    algo::RatioWindow window;
    double meanSquaredError = 0.0;
    double maxAbsError = 0.0;
    std::int64_t modelPixels = 0;
    std::int64_t featurePixels = 0;
    double depthThreshold = 0.0; ///< model units
    double milliseconds = 0.0;
    double curvatureMilliseconds = 0.0;
    QString error; ///< why there is no analysis (no model, keys that cannot be blended)
};

class DepthAnalysisRunner : public QObject {
    Q_OBJECT
public:
    DepthAnalysisRunner(model::Document* document, Viewport* viewport, QObject* parent = nullptr);
    ~DepthAnalysisRunner() override;

    /// Off (the default): nothing is analysed. On: the viewport's picture is analysed now and
    /// after every change of its camera, size, shape, the look or the playhead.
    void setActive(bool on);
    [[nodiscard]] bool isActive() const { return m_active; }
    /// Held (while the timeline plays): changes are noted but not analysed, so playback keeps
    /// the cores; released, the picture then on screen is analysed once.
    void setHeld(bool held);
    [[nodiscard]] bool isHeld() const { return m_held; }
    void setSettings(const model::AnalysisSettings& settings);
    [[nodiscard]] const model::AnalysisSettings& settings() const { return m_settings; }
    /// The longest side of the analysed picture (the viewport's size scaled down to it, 1024 by
    /// default; pixels are logical).
    void setMaximumSide(int pixels);
    /// The size the viewport's picture is analysed at (its size scaled down to the longest side).
    [[nodiscard]] QSize analysisSize() const;

    /// The newest result, or null before the first.
    [[nodiscard]] std::shared_ptr<const DepthAnalysisResult> result() const { return m_result; }
    /// Whether an analysis is running or waiting.
    [[nodiscard]] bool isBusy() const { return m_busy; }
    /// Whether the newest result was made through the viewport's current camera and size.
    [[nodiscard]] bool isCurrent() const;

public slots:
    /// Asks for an analysis of the viewport as it is when the event loop next turns.
    void requestUpdate();

signals:
    void analysed();
    void busyChanged(bool busy);

private:
    struct Job;
    class WorkerProgress;
    void documentChanged(const model::ChangeSet& change);
    void submit();
    void workerLoop();
    void deliver(std::shared_ptr<const DepthAnalysisResult> result);

    model::Document* m_document;
    QPointer<Viewport> m_viewport;
    bool m_active = false;
    bool m_held = false;
    bool m_missed = false; ///< a change came while held
    bool m_busy = false;
    int m_maximumSide = 1024;
    model::AnalysisSettings m_settings;
    QTimer m_coalesce;
    std::shared_ptr<const DepthAnalysisResult> m_result;

    // Shared with the worker under m_mutex.
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::unique_ptr<Job> m_pending;
    bool m_running = false;
    bool m_stop = false; ///< the runner is going: the worker leaves, the analysis under way stops
    std::thread m_worker;
};

} // namespace celform::views
