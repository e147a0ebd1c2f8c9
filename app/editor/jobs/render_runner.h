// Runs a render of the editor's document on a worker thread (model::renderFrames, the code path
// of `celform render`) behind a progress dialog with Cancel: per-frame progress, Cancel stops
// between frames and keeps the files already written, errors in a message box naming the file,
// and the output opened when done.
#pragma once

#include "celform/model/data/project_data.h"
#include "celform/model/render/render_job.h"

#include <QFuture>
#include <QObject>
#include <QPointer>
#include <QProgressDialog>
#include <QStringList>

#include <atomic>

class QWidget;

namespace celform::app {

class RenderRunner : public QObject {
    Q_OBJECT
public:
    /// A render of a copy of data (the document as it is now); source names it in errors.
    RenderRunner(model::ProjectData data, QString source, model::RenderJob job, QWidget* parent);
    /// Stops a running render (between frames) and waits for it.
    ~RenderRunner() override;

    /// Opens the output (the image, or a sequence's folder) with the desktop's viewer when the
    /// render completes. Off by default.
    void setOpenWhenDone(bool on) { m_openWhenDone = on; }
    [[nodiscard]] bool openWhenDone() const { return m_openWhenDone; }

    /// Starts the worker and shows the progress dialog (window-modal on the parent).
    void start();
    /// Asks the render to stop: the frame being rendered is dropped, the files written stay.
    void cancel();

    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] const model::RenderJob& job() const { return m_job; }
    [[nodiscard]] QStringList writtenFiles() const { return m_written; }
    [[nodiscard]] QProgressDialog* progressDialog() const { return m_progress; }
    /// The last error's message ("file: problem"), empty when none.
    [[nodiscard]] QString errorMessage() const { return m_error; }

signals:
    /// After each frame's file is written (on the GUI thread; the worker waits for the slots, so a
    /// cancel from a slot stops the render before the next frame is written).
    void frameWritten(int frame, const QString& file);
    /// The render ended: every frame written (completed), or cancelled, or failed (see failed).
    void finished(bool completed);
    void failed(const QString& message);
    /// A line for the status bar.
    void message(const QString& text);

private:
    struct Outcome {
        int written = 0;
        QString error;
    };
    void noteWritten(int frame, const QString& file, int done);
    void workerFinished(const Outcome& outcome);

    model::ProjectData m_data;
    QString m_source;
    model::RenderJob m_job;
    QPointer<QWidget> m_parent;
    QPointer<QProgressDialog> m_progress;
    QFuture<void> m_future;
    std::atomic<bool> m_cancel{false};
    bool m_openWhenDone = false;
    bool m_running = false;
    bool m_destroying = false;
    QStringList m_written;
    QString m_error;
};

} // namespace celform::app
