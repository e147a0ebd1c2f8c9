// A render on a worker thread behind a progress dialog (render_runner.h).
#include "editor/jobs/render_runner.h"

#include "editor/dialogs/progress_dialog.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QThread>
#include <QUrl>
#include <QtConcurrent/QtConcurrentRun>

namespace celform::app {

RenderRunner::RenderRunner(model::ProjectData data, QString source, model::RenderJob job, QWidget* parent)
    : QObject(parent)
    , m_data(std::move(data))
    , m_source(std::move(source))
    , m_job(std::move(job))
    , m_parent(parent)
{ }

RenderRunner::~RenderRunner()
{
    if (!m_running)
        return;
    m_cancel = true;
    m_destroying = true;
    // The worker may be waiting for noteWritten on this thread: deliver that call, nothing else.
    while (!m_future.isFinished()) {
        QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
        QThread::msleep(5);
    }
    delete m_progress;
}

bool RenderRunner::isRunning() const
{
    return m_running;
}

void RenderRunner::start()
{
    if (m_running)
        return;
    m_running = true;
    m_cancel = false;
    m_written.clear();
    m_error.clear();
    const bool sequence = m_job.isSequence();
    m_progress = makeProgressDialog(m_parent, QStringLiteral("renderProgress"),
        sequence ? tr("Render Sequence") : tr("Render Image"),
        sequence ? tr("Rendering frame %1 (1 of %2)…").arg(m_job.firstFrame).arg(m_job.frameCount())
                 : tr("Rendering %1 (%2 × %3)…")
                       .arg(QFileInfo(m_job.framePath(m_job.firstFrame)).fileName())
                       .arg(m_job.size.width())
                       .arg(m_job.size.height()),
        m_job.frameCount());
    connect(m_progress, &QProgressDialog::canceled, this, &RenderRunner::cancel);
    m_progress->show();

    m_future = QtConcurrent::run([this] {
        Outcome outcome;
        model::RenderCallbacks callbacks;
        // The worker waits until the GUI thread has taken note of each file, so a Cancel given
        // then is seen before the next frame.
        callbacks.written = [this](int frame, const QString& file, int done) {
            QMetaObject::invokeMethod(
                this, [this, frame, file, done] { noteWritten(frame, file, done); }, Qt::BlockingQueuedConnection);
        };
        callbacks.cancelled = [this] { return m_cancel.load(); };
        try {
            outcome.written = model::renderFrames(m_data, m_source, m_job, callbacks);
        } catch (const model::IoError& e) {
            outcome.error = e.message();
        } catch (const std::bad_alloc&) {
            outcome.error = tr("%1: not enough memory to render %2 × %3 pixels")
                                .arg(m_source)
                                .arg(m_job.size.width())
                                .arg(m_job.size.height());
        }
        QMetaObject::invokeMethod(
            this, [this, outcome] { workerFinished(outcome); }, Qt::QueuedConnection);
    });
}

void RenderRunner::cancel()
{
    if (!m_running || m_cancel)
        return;
    m_cancel = true;
    emit message(tr("Stopping the render after the frame being drawn…"));
}

void RenderRunner::noteWritten(int frame, const QString& file, int done)
{
    m_written << file;
    if (m_destroying)
        return;
    if (m_progress) {
        m_progress->setValue(done);
        if (done < m_job.frameCount())
            m_progress->setLabelText(
                tr("Rendering frame %1 (%2 of %3)…").arg(frame + 1).arg(done + 1).arg(m_job.frameCount()));
    }
    emit frameWritten(frame, file);
}

void RenderRunner::workerFinished(const Outcome& outcome)
{
    m_running = false;
    if (m_progress) {
        m_progress->hide();
        m_progress->deleteLater();
    }
    const bool sequence = m_job.isSequence();
    if (!outcome.error.isEmpty()) {
        m_error = outcome.error;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Render Failed"), tr("The render could not be finished."),
            QMessageBox::Ok, m_parent);
        box->setObjectName(QStringLiteral("renderErrorBox"));
        QString details = m_error;
        // The frames written before the error (renderFrames threw: count them here).
        if (sequence && !m_written.isEmpty())
            details += QStringLiteral("\n\n")
                + tr("The frames written before the error are kept (%L1).").arg(m_written.size());
        box->setInformativeText(details);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        emit message(tr("Render failed: %1").arg(m_error));
        emit failed(m_error);
        emit finished(false);
        return;
    }
    const bool completed = outcome.written == m_job.frameCount();
    if (!completed) {
        emit message(tr("Render cancelled; the files written are kept (%L1).").arg(m_written.size()));
        emit finished(false);
        return;
    }
    const QString first = m_written.value(0);
    emit message(sequence ? tr("Rendered %L1 frames to %2")
                                .arg(m_written.size())
                                .arg(QDir::toNativeSeparators(QFileInfo(first).absolutePath()))
                          : tr("Rendered %1").arg(QDir::toNativeSeparators(QFileInfo(first).absoluteFilePath())));
    if (m_openWhenDone)
        QDesktopServices::openUrl(
            QUrl::fromLocalFile(sequence ? QFileInfo(first).absolutePath() : QFileInfo(first).absoluteFilePath()));
    emit finished(true);
}

} // namespace celform::app
