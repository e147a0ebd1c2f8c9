// The editor's one way to run a long job the user starts (render, export, light optimisation,
// automatic shading offsets, opening and importing files): the job runs on a worker thread with
// an algo::Progress, a window-modal progress dialog with Cancel shows after a short delay, and
// the result is applied on the GUI thread by the job's own finish step (one call to the
// Document, so one undo step). A failure is shown in a message box naming what failed.
// docs/architecture.md, "Long jobs", says how to add one.
#pragma once

#include "celform/algorithms/progress.h"

#include <QFuture>
#include <QObject>
#include <QPointer>
#include <QProgressDialog>
#include <QString>

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>

class QWidget;

namespace celform::app {

/// How a job shows itself: its progress dialog and what a failure says.
struct JobSpec {
    QString progressName; ///< the progress dialog's object name
    QString title; ///< of the progress dialog and of the error box
    QString label; ///< the dialog's text until the job reports
    std::int64_t steps = 0; ///< the dialog's range; 0: busy until the job reports a total
    int delayMs = 300; ///< the dialog shows once the job has run this long; 0: at once
    /// The worker waits until the GUI thread has shown each step, so that a Cancel given then (or
    /// by a slot of progressed) is seen before the next step: for jobs of few, long steps.
    bool waitForEachStep = false;
    /// The dialog's text for a step (done of total, the job's label); null: the job's label.
    std::function<QString(std::int64_t done, std::int64_t total, const QString& label)> describe;
    QString outOfMemory; ///< the error when the job runs out of memory (empty: a plain one)
    QString errorBoxName; ///< the error box's object name
    QString errorTitle; ///< the error box's title (empty: title)
    QString errorText; ///< the error box's text above the error
    /// The error box's details for an error (null: the error itself).
    std::function<QString(const QString& error)> errorDetails;
    /// Shows an error instead of the error box (the window's own way, for file errors).
    std::function<void(const QString& error)> showError;
};

class JobRunner : public QObject {
    Q_OBJECT
public:
    /// The GUI thread's end of a job that ran without error: applies the result (one call to the
    /// Document) and says whether the job ran to its end (false: cancelled, nothing changed). It
    /// may throw model::EditRefused, shown as the job's error.
    using Finish = std::function<bool()>;
    /// The job, on the worker thread: it reports to progress, stops when progress says so, and
    /// returns its finish step. It may throw model::IoError, model::EditRefused or std::bad_alloc.
    using Work = std::function<Finish(algo::Progress& progress)>;

    JobRunner(JobSpec spec, Work work, QWidget* parent);
    /// Cancels a running job and waits for it.
    ~JobRunner() override;

    /// Starts the job and returns; finished tells the end.
    void start();
    /// Starts the job and waits for its end (user input to the windows waits too), then returns
    /// whether it completed: for jobs whose caller needs the result before it goes on.
    bool exec();
    /// Asks the job to stop at its next check.
    void cancel();

    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] bool isCancelRequested() const { return m_cancel.load(); }
    [[nodiscard]] QProgressDialog* progressDialog() const { return m_dialog; }
    /// The failure's message ("file: problem"), empty when none.
    [[nodiscard]] QString errorMessage() const { return m_error; }

signals:
    /// The dialog shows done of total (on the GUI thread, once the dialog shows it).
    void progressed(qint64 done, qint64 total);
    /// Cancel was asked for; the job stops at its next check.
    void cancelling();
    /// The job failed with message (shown already); finished(false) follows.
    void failed(const QString& message);
    /// The job ended: completed and applied, or cancelled, or failed.
    void finished(bool completed);

private:
    class WorkerProgress;
    void report(std::int64_t done, std::int64_t total, const std::string& label);
    void showProgress();
    void workerFinished(const Finish& finish, const QString& error);
    void fail(const QString& error);

    JobSpec m_spec;
    Work m_work;
    QPointer<QWidget> m_parent;
    QPointer<QProgressDialog> m_dialog;
    QFuture<void> m_future;
    std::atomic<bool> m_cancel{false};
    bool m_running = false;
    bool m_destroying = false;
    QString m_error;

    // The newest step, shared with the worker under m_mutex.
    std::mutex m_mutex;
    std::int64_t m_done = 0;
    std::int64_t m_total = 0;
    QString m_label;
    bool m_updatePosted = false;
};

} // namespace celform::app
