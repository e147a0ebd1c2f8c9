// What every part of the celform module shares: the Qt application the model needs (made on first
// use when the host has none), the module's exceptions and how C++ errors become them, the Python
// progress callback as the model's algo::Progress, and conversions of strings and JSON.
#pragma once

#include "celform/algorithms/progress.h"

#include <pybind11/pybind11.h>

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>
#include <optional>

namespace celform::python {

namespace py = pybind11;

/// Makes a QCoreApplication (no display, no platform plug-in) when the process has none, with the
/// command line's identity and translations; the model's child processes and tr() rely on it.
void ensureApplication();

/// Defines celform.Error and its subclasses UsageError (also a ValueError: exit code 2 of the
/// command line), IoError (also an OSError: exit code 3) and Cancelled, and translates the model's
/// and the command line's C++ errors into them with the command line's messages.
void registerExceptions(py::module_& module);

/// Raises celform.UsageError / celform.IoError with message (for the command line's checks made
/// here, as the same words).
[[noreturn]] void throwUsage(const QString& message);
[[noreturn]] void throwIo(const QString& message);

/// A str or os.PathLike as a QString.
QString toQString(const py::handle& value);
py::str toPython(const QString& text);
py::list toPython(const QStringList& list);
/// A JSON object as Python dicts and lists (through the json module: numbers, strings, nulls).
py::object toPython(const QJsonObject& object);

/// A Python progress callback, callback(done, total, label), as the model's Progress. Returning
/// False cancels the job; raising cancels it too, and rethrow() raises that exception once the job
/// has returned. Called with the GIL taken, from whichever thread reports; the job runs with the
/// GIL released (runJob) so that its threads can report.
class CallbackProgress : public algo::Progress {
public:
    explicit CallbackProgress(py::object callback);
    ~CallbackProgress() override;
    void progress(std::int64_t done, std::int64_t total, const std::string& label) override;
    [[nodiscard]] bool isCancelRequested() const override { return m_cancel.load(); }
    /// The progress to hand the model.
    [[nodiscard]] algo::Progress* get() { return this; }
    /// Whether the callback (or a signal) stopped the job.
    [[nodiscard]] bool cancelled() const { return m_cancel.load(); }
    /// Raises the callback's exception, if it raised one. Needs the GIL.
    void rethrow();
    /// Runs Python's signal handlers (on the main thread): an exception they raise (Ctrl+C's
    /// KeyboardInterrupt) stops the job and is raised by rethrow(). Takes the GIL.
    void checkSignals();

private:
    py::object m_callback;
    std::atomic<bool> m_cancel{false};
    std::optional<py::error_already_set> m_error;
};

/// Runs a long job (a render, an export) on a thread of its own with the GIL released, while this
/// thread keeps Python's signals answered: Ctrl+C stops the job at its next progress step and its
/// KeyboardInterrupt is raised once the job has returned, as is an exception of the callback.
/// The job's own C++ exceptions come through as they are.
template <typename Job> auto runJob(CallbackProgress& progress, Job job) -> decltype(job())
{
    using Result = decltype(job());
    std::packaged_task<Result()> task(std::move(job));
    std::future<Result> done = task.get_future();
    {
        py::gil_scoped_release release;
        std::thread worker(std::move(task));
        while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready)
            progress.checkSignals();
        worker.join();
    }
    progress.rethrow();
    return done.get();
}

} // namespace celform::python
