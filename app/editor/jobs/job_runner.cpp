// A long job on a worker thread behind a progress dialog (job_runner.h).
#include "editor/jobs/job_runner.h"

#include "editor/dialogs/progress_dialog.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QMessageBox>
#include <QProgressDialog>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <climits>
#include <new>

namespace celform::app {

/// The job's algo::Progress: hands each step to the GUI thread and answers Cancel.
class JobRunner::WorkerProgress : public algo::Progress {
public:
    explicit WorkerProgress(JobRunner* runner)
        : m_runner(runner)
    { }
    void progress(std::int64_t done, std::int64_t total, const std::string& label) override
    {
        m_runner->report(done, total, label);
    }
    [[nodiscard]] bool isCancelRequested() const override { return m_runner->m_cancel.load(); }

private:
    JobRunner* m_runner;
};

JobRunner::JobRunner(JobSpec spec, Work work, QWidget* parent)
    : QObject(parent)
    , m_spec(std::move(spec))
    , m_work(std::move(work))
    , m_parent(parent)
{ }

JobRunner::~JobRunner()
{
    if (!m_running)
        return;
    m_cancel = true;
    m_destroying = true;
    // The worker may be waiting for a step to be shown on this thread: deliver that, nothing else.
    while (!m_future.isFinished()) {
        QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
        QThread::msleep(5);
    }
    delete m_dialog;
}

void JobRunner::start()
{
    if (m_running)
        return;
    m_running = true;
    m_cancel = false;
    m_error.clear();
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_done = 0;
        m_total = m_spec.steps;
        m_label.clear();
        m_updatePosted = false;
    }
    const int maximum = int(std::clamp<std::int64_t>(m_spec.steps, 0, INT_MAX));
    m_dialog = makeProgressDialog(m_parent, m_spec.progressName, m_spec.title, m_spec.label, maximum, m_spec.delayMs);
    connect(m_dialog, &QProgressDialog::canceled, this, &JobRunner::cancel);
    if (m_spec.delayMs <= 0)
        m_dialog->show();

    m_future = QtConcurrent::run([this] {
        WorkerProgress progress(this);
        Finish finish;
        QString error;
        try {
            finish = m_work(progress);
        } catch (const model::IoError& e) {
            error = e.message();
        } catch (const model::EditRefused& e) {
            error = e.message();
        } catch (const std::bad_alloc&) {
            error = m_spec.outOfMemory.isEmpty() ? tr("Not enough memory.") : m_spec.outOfMemory;
        }
        QMetaObject::invokeMethod(
            this, [this, finish, error] { workerFinished(finish, error); }, Qt::QueuedConnection);
    });
}

bool JobRunner::exec()
{
    bool completed = false;
    QEventLoop loop;
    const auto connection = connect(this, &JobRunner::finished, &loop, [&](bool done) {
        completed = done;
        loop.quit();
    });
    start();
    // Input waits, as for a modal dialog before it shows: the window must not change under the job.
    if (m_running)
        loop.exec(QEventLoop::ExcludeUserInputEvents);
    disconnect(connection);
    return completed;
}

void JobRunner::cancel()
{
    if (!m_running || m_cancel.exchange(true))
        return;
    emit cancelling();
}

void JobRunner::report(std::int64_t done, std::int64_t total, const std::string& label)
{
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_done = done;
        m_total = total;
        if (!label.empty())
            m_label = QString::fromStdString(label);
        if (!m_spec.waitForEachStep) {
            // One update waits at a time: a job of many quick steps must not flood the GUI thread.
            if (m_updatePosted)
                return;
            m_updatePosted = true;
        }
    }
    QMetaObject::invokeMethod(
        this, [this] { showProgress(); }, m_spec.waitForEachStep ? Qt::BlockingQueuedConnection : Qt::QueuedConnection);
}

void JobRunner::showProgress()
{
    std::int64_t done = 0, total = 0;
    QString label;
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_updatePosted = false;
        done = m_done;
        total = m_total;
        label = m_label;
    }
    if (m_destroying || !m_running || !m_dialog)
        return;
    if (m_dialog->wasCanceled()) // closed with Escape rather than its button
        cancel();
    const int maximum = int(std::clamp<std::int64_t>(total, 0, INT_MAX));
    if (m_dialog->maximum() != maximum)
        m_dialog->setMaximum(maximum);
    m_dialog->setValue(int(std::clamp<std::int64_t>(done, 0, maximum)));
    const QString text = m_spec.describe ? m_spec.describe(done, total, label) : label;
    if (!text.isEmpty())
        m_dialog->setLabelText(text);
    emit progressed(done, total);
}

void JobRunner::workerFinished(const Finish& finish, const QString& error)
{
    m_running = false;
    if (m_dialog) {
        m_dialog->hide();
        m_dialog->deleteLater();
    }
    if (!error.isEmpty())
        return fail(error);
    bool completed = true;
    try {
        if (finish)
            completed = finish();
    } catch (const model::EditRefused& e) {
        return fail(e.message());
    } catch (const model::IoError& e) {
        return fail(e.message());
    }
    emit finished(completed);
}

void JobRunner::fail(const QString& error)
{
    m_error = error;
    if (m_spec.showError) {
        m_spec.showError(error);
    } else {
        auto* box
            = new QMessageBox(QMessageBox::Warning, m_spec.errorTitle.isEmpty() ? m_spec.title : m_spec.errorTitle,
                m_spec.errorText, QMessageBox::Ok, m_parent);
        box->setObjectName(m_spec.errorBoxName);
        box->setInformativeText(m_spec.errorDetails ? m_spec.errorDetails(error) : error);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
    emit failed(error);
    emit finished(false);
}

} // namespace celform::app
