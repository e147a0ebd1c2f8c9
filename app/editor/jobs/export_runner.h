// An export of the editor's document on a worker thread (model::exportProject, the code path of
// `celform export`) behind a progress dialog with Cancel; errors in a message box naming the file.
#pragma once

#include "celform/model/export/export.h"
#include "celform/model/data/project_data.h"

#include <QFuture>
#include <QObject>
#include <QPointer>
#include <QProgressDialog>

#include <atomic>

namespace celform::app {

/// An export of a copy of the document on a worker thread, behind a window-modal progress dialog.
class ExportRunner : public QObject {
    Q_OBJECT
public:
    ExportRunner(model::ProjectData data, QString source, model::ExportJob job, QWidget* parent);
    /// Stops a running export and waits for it.
    ~ExportRunner() override;
    void start();
    /// Asks the export to stop before the next frame; a one-file format leaves no file.
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] QProgressDialog* progressDialog() const { return m_progress; }
    /// The error's message ("file: problem"), empty when none.
    [[nodiscard]] QString errorMessage() const { return m_error; }

signals:
    /// The export ended: completed, or cancelled or failed.
    void finished(bool completed);
    /// A line for the status bar.
    void message(const QString& text);

private:
    void workerFinished(const model::ExportResult& result, const QString& error);

    model::ProjectData m_data;
    QString m_source;
    model::ExportJob m_job;
    QPointer<QWidget> m_parent;
    QPointer<QProgressDialog> m_progress;
    QFuture<void> m_future;
    std::atomic<bool> m_cancel{false};
    bool m_running = false;
    QString m_error;
};

} // namespace celform::app
