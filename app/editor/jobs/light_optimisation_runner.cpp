// Optimise Light for Stereo on a worker thread (light_optimisation_runner.h).
#include "editor/jobs/light_optimisation_runner.h"

#include "editor/dialogs/progress_dialog.h"

#include <QCoreApplication>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

namespace celform::app {

LightOptimisationRunner::LightOptimisationRunner(LightOptimisationJob job, QWidget* parent)
    : QObject(parent)
    , m_job(std::move(job))
    , m_parent(parent)
{ }

LightOptimisationRunner::~LightOptimisationRunner()
{
    m_cancel = true;
    m_future.waitForFinished();
    delete m_progress;
}

void LightOptimisationRunner::start()
{
    if (m_running)
        return;
    m_running = true;
    m_cancel = false;
    m_done = 0;
    const int iterations = m_job.request.optimiser.iterations;
    // Two analyses around the iterations: they count as an iteration each.
    m_progress
        = makeProgressDialog(m_parent, QStringLiteral("lightOptimisationProgress"), tr("Optimise Light for Stereo"),
            tr("Analysing the picture (%1 × %2)…").arg(m_job.width).arg(m_job.height), iterations + 2, 300);
    connect(m_progress, &QProgressDialog::canceled, this, &LightOptimisationRunner::cancel);

    m_future = QtConcurrent::run([this] {
        std::shared_ptr<model::LightOptimisationReport> report;
        QString error;
        try {
            model::DepthAnalyzer analyzer;
            const algo::LightProgress progress = [this](int done, int) {
                m_done = done + 1;
                QMetaObject::invokeMethod(
                    this, [this] { noteProgress(m_done.load()); }, Qt::QueuedConnection);
                return !m_cancel.load();
            };
            report = std::make_shared<model::LightOptimisationReport>(
                model::optimiseLight(m_job.data, m_job.data.look, m_job.shape, m_job.generation, m_job.frame,
                    m_job.camera, m_job.width, m_job.height, m_job.request, analyzer, progress));
            if (m_cancel.load())
                report->run.cancelled = true; // cancelled during the last analysis
        } catch (const std::bad_alloc&) {
            error = tr("Not enough memory to analyse %1 × %2 pixels").arg(m_job.width).arg(m_job.height);
        }
        QMetaObject::invokeMethod(
            this, [this, report, error] { workerFinished(report, error); }, Qt::QueuedConnection);
    });
}

void LightOptimisationRunner::cancel()
{
    if (m_running)
        m_cancel = true;
}

void LightOptimisationRunner::noteProgress(int done)
{
    if (!m_progress || !m_running)
        return;
    if (m_progress->wasCanceled()) // closed with Escape rather than its button
        cancel();
    m_progress->setValue(done);
    m_progress->setLabelText(done <= m_job.request.optimiser.iterations
            ? tr("Moving the light: iteration %1 of %2…").arg(done).arg(m_job.request.optimiser.iterations)
            : tr("Analysing the picture with the new light…"));
}

void LightOptimisationRunner::workerFinished(
    std::shared_ptr<const model::LightOptimisationReport> report, const QString& error)
{
    m_running = false;
    if (m_progress) {
        m_progress->hide();
        m_progress->deleteLater();
    }
    if (!error.isEmpty())
        emit failed(error);
    else
        emit finished(report);
}

} // namespace celform::app
