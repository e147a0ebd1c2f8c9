// The depth analysis along the shot for the Depth tab's chart (issue 26, "along the timeline"):
// every frame of the scene's range analysed through the shot camera on a thread of its own
// (model::analyseProjectFrames on a copy of the project), with progress and Cancel. The result
// is kept until the document changes (the shape, the look or the camera path: anything but the
// playhead), so showing the chart again costs nothing.
#pragma once

#include "celform/algorithms/progress.h"
#include "celform/model/analysis/depth_analysis.h"

#include <QObject>
#include <QSize>

#include <atomic>
#include <memory>
#include <thread>
#include <vector>

namespace celform::model {
class Document;
struct ChangeSet;
} // namespace celform::model

namespace celform::views {

/// One analysed frame of the shot.
struct ShotDepthSample {
    int frame = 0;
    double mse = 0.0; ///< the depth error (thesis 4.4)
    double inWindow = 0.0; ///< the share of segments inside the window, 0..1
    int segments = 0;
};

class ShotDepthRunner : public QObject {
    Q_OBJECT
public:
    explicit ShotDepthRunner(model::Document* document, QObject* parent = nullptr);
    ~ShotDepthRunner() override;

    /// Analyses frames first..last every step at size with settings; a run in progress is
    /// cancelled first. Nothing when the same request's result is current.
    void start(int first, int last, int step, QSize size, const model::AnalysisSettings& settings);
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_running; }
    /// The samples of the last finished run (empty while none is current).
    [[nodiscard]] const std::vector<ShotDepthSample>& samples() const { return m_samples; }
    /// Whether samples() still describe the document.
    [[nodiscard]] bool isCurrent() const { return m_current; }

signals:
    void progressed(int done, int total);
    /// A run ended: completed (samples() current), cancelled or failed (error not empty).
    void finished(bool completed, const QString& error);
    /// The samples no longer describe the document.
    void staled();

private:
    class Progress;
    void documentChanged(const model::ChangeSet& change);
    void join();

    model::Document* m_document;
    std::thread m_worker;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    bool m_running = false;
    bool m_current = false;
    int m_run = 0;
    std::vector<ShotDepthSample> m_samples;
};

} // namespace celform::views
