// An export on a worker thread behind a progress dialog (export_runner.h).
#include "editor/jobs/export_runner.h"

#include "editor/dialogs/progress_dialog.h"

#include "celform/model/data/io_error.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace celform::app {

ExportRunner::ExportRunner(model::ProjectData data, QString source, model::ExportJob job, QWidget* parent)
    : QObject(parent)
    , m_data(std::move(data))
    , m_source(std::move(source))
    , m_job(std::move(job))
    , m_parent(parent)
{ }

ExportRunner::~ExportRunner()
{
    if (!m_running)
        return;
    m_cancel = true;
    m_future.waitForFinished();
    delete m_progress;
}

void ExportRunner::start()
{
    if (m_running)
        return;
    m_running = true;
    m_cancel = false;
    m_error.clear();
    m_progress = makeProgressDialog(m_parent, QStringLiteral("exportProgress"), tr("Export"),
        tr("Exporting %1…").arg(QFileInfo(m_job.output).fileName()), m_job.frameCount());
    connect(m_progress, &QProgressDialog::canceled, this, &ExportRunner::cancel);
    m_progress->show();

    m_future = QtConcurrent::run([this] {
        model::ExportCallbacks callbacks;
        // At most one update per percent: a long range must not flood the GUI thread's queue.
        callbacks.progress = [this, shown = -1](int done, int total) mutable {
            const int percent = int(qint64(done) * 100 / std::max(1, total));
            if (percent == shown && done != total)
                return;
            shown = percent;
            QMetaObject::invokeMethod(
                this,
                [this, done] {
                    if (m_progress)
                        m_progress->setValue(done);
                },
                Qt::QueuedConnection);
        };
        callbacks.cancelled = [this] { return m_cancel.load(); };
        model::ExportResult result;
        QString error;
        try {
            result = model::exportProject(m_data, m_source, m_job, callbacks);
        } catch (const model::IoError& e) {
            error = e.message();
        } catch (const std::bad_alloc&) {
            error = tr("%1: not enough memory to export").arg(m_job.output);
        }
        QMetaObject::invokeMethod(
            this, [this, result, error] { workerFinished(result, error); }, Qt::QueuedConnection);
    });
}

void ExportRunner::cancel()
{
    if (m_running)
        m_cancel = true;
}

void ExportRunner::workerFinished(const model::ExportResult& result, const QString& error)
{
    m_running = false;
    if (m_progress) {
        m_progress->hide();
        m_progress->deleteLater();
    }
    if (!error.isEmpty()) {
        m_error = error;
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Export Failed"), tr("The export could not be finished."),
            QMessageBox::Ok, m_parent);
        box->setObjectName(QStringLiteral("exportErrorBox"));
        box->setInformativeText(error);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        emit message(tr("Export failed: %1").arg(error));
        emit finished(false);
        return;
    }
    if (result.cancelled) {
        emit message(tr("Export cancelled."));
        emit finished(false);
        return;
    }
    QString text = tr("Exported %L1 frames to %2").arg(result.frames).arg(QDir::toNativeSeparators(m_job.output));
    for (const QString& w : result.warnings)
        text += QStringLiteral(" — ") + w;
    emit message(text);
    emit finished(true);
}

} // namespace celform::app
