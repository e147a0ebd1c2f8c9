// Optimise Light for Stereo in the editor (paper 3, 4.1; issue 12): model::optimiseLight on a
// worker thread with a copy of what it reads, behind a progress dialog with Cancel (one step per
// iteration). The finished report is handed back on the GUI thread; the caller stores it with
// Document::applyLightOptimisation (one undo step). Cancel leaves the document as it was.
#pragma once

#include "celform/model/analysis/light_optimisation.h"

#include <QFuture>
#include <QObject>
#include <QPointer>
#include <QProgressDialog>

#include <atomic>
#include <memory>

class QWidget;

namespace celform::app {

/// Everything a run reads, copied from the document and the viewport when it starts.
struct LightOptimisationJob {
    model::ProjectData data; ///< the mesh (shared), face sets and look
    algo::Positions shape; ///< the shape on screen
    std::vector<float> offsets; ///< the shading offsets in effect for it (Viewport::displayedShadingOffsets)
    std::uint64_t generation = 0;
    int frame = 0;
    model::Camera camera;
    int width = 0;
    int height = 0;
    model::LightOptimisationRequest request;
};

class LightOptimisationRunner : public QObject {
    Q_OBJECT
public:
    LightOptimisationRunner(LightOptimisationJob job, QWidget* parent);
    /// Cancels a running optimisation and waits for the worker.
    ~LightOptimisationRunner() override;

    /// Starts the worker and shows the progress dialog (window-modal on the parent).
    void start();
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] QProgressDialog* progressDialog() const { return m_progress; }

signals:
    /// The run ended: with a report (completed or cancelled), or with an error message.
    void finished(const std::shared_ptr<const model::LightOptimisationReport>& report);
    void failed(const QString& message);

private:
    void noteProgress(int done);
    void workerFinished(std::shared_ptr<const model::LightOptimisationReport> report, const QString& error);

    LightOptimisationJob m_job;
    QPointer<QWidget> m_parent;
    QPointer<QProgressDialog> m_progress;
    QFuture<void> m_future;
    std::atomic<bool> m_cancel{false};
    std::atomic<int> m_done{0};
    bool m_running = false;
};

} // namespace celform::app
