// The threads of a render job (frame_schedule.h). Frames are taken in order from one counter, so
// with one thread this is the plain loop over the frames. Files are written, atomically
// (render_output.h), by one writer thread in the order the frames were rendered, while their
// render threads go on with the next frames; the threads share the counter, the progress, the
// listener and the first failure, all behind one mutex.
#include "celform/model/render/frame_schedule.h"
#include "celform/model/render/render_output.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <new>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace celform::model {
namespace {

struct ScheduleText {
    Q_DECLARE_TR_FUNCTIONS(celform::model::RenderJob)
};

struct Failure {
    int frame;
    QString file;
    QString problem;
};

/// How much lower the writer thread runs than the render threads (nice levels).
constexpr int kWriterNiceness = 10;

/// Lowers the calling thread's priority by kWriterNiceness, and that of the threads it starts
/// after (OpenEXR's compression threads, which OpenImageIO starts on the first EXR write). The
/// render threads are a sequence's critical path; the writer fills the time they leave (issue 29):
/// with the writer's EXR compression at the render's priority, three threads shared two cores and
/// the render thread lost a third of its core (10 dragon frames of every pass at 1920x1080: 2.89 s
/// at equal priority, 2.55 s with the writer 10 levels lower). Linux keeps a nice value per thread;
/// elsewhere this does nothing.
void yieldToRenderThreads()
{
#if defined(__linux__)
    const auto self = id_t(::syscall(SYS_gettid));
    errno = 0;
    const int current = ::getpriority(PRIO_PROCESS, self);
    if (errno == 0)
        ::setpriority(PRIO_PROCESS, self, std::min(current + kWriterNiceness, 19));
#endif
}

/// The job's one writer thread: runs the writes handed to it, in order. Without a thread to be had,
/// a write runs on the thread that hands it over.
class Writer {
public:
    Writer()
    {
        try {
            m_thread = std::thread([this] { run(); });
        } catch (const std::system_error&) { }
    }
    ~Writer()
    {
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            m_closing = true;
        }
        m_wake.notify_one();
        if (m_thread.joinable())
            m_thread.join();
    }
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;

    /// Queues task; the future is ready once it has run.
    std::future<void> submit(std::function<void()> task)
    {
        std::packaged_task<void()> packaged(std::move(task));
        std::future<void> done = packaged.get_future();
        if (!m_thread.joinable()) {
            packaged();
            return done;
        }
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            m_tasks.push_back(std::move(packaged));
        }
        m_wake.notify_one();
        return done;
    }

private:
    void run()
    {
        yieldToRenderThreads();
        for (;;) {
            std::packaged_task<void()> task;
            {
                std::unique_lock<std::mutex> lock(m_mutex);
                m_wake.wait(lock, [this] { return m_closing || !m_tasks.empty(); });
                if (m_tasks.empty())
                    return; // closing, and nothing left
                task = std::move(m_tasks.front());
                m_tasks.pop_front();
            }
            task();
        }
    }

    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<std::packaged_task<void()>> m_tasks;
    bool m_closing = false;
    std::thread m_thread;
};

class Schedule {
public:
    Schedule(const RenderJob& job, algo::Progress* progress, RenderFrameListener* listener, Writer& writer)
        : m_job(job)
        , m_writer(writer)
        , m_progress(progress)
        , m_listener(listener)
        , m_count(job.frameCount())
    { }

    /// One thread's loop: the next frame until none is left, the render is cancelled or a
    /// frame has failed. Its frames' writes go to the writer, one at a time: the next frame renders
    /// while the last one is written.
    void work(const std::function<FrameRenderer()>& makeRenderer)
    {
        FrameRenderer render;
        std::future<void> writing; // this thread's frame being written
        const std::function<bool()> cancelled = [this] {
            const std::lock_guard<std::mutex> lock(m_mutex);
            return userCancelled();
        };
        while (const std::optional<int> index = nextIndex()) {
            const int frame = m_job.frameAt(*index);
            const QString file = m_job.framePath(frame);
            try {
                // Only a whole image is a frame done: one cut short by an earlier run (a full disk,
                // a killed node) is rendered again (issue 27). Checked with the mutex held: the
                // decoder silences standard error while it runs, and the listener prints under it.
                if (m_job.skipExisting && QFileInfo(file).isFile()) {
                    const std::lock_guard<std::mutex> lock(m_mutex);
                    if (incompleteImageProblem(file).isEmpty()) {
                        ++m_done;
                        frameDone(frame, file, true);
                        continue;
                    }
                }
                if (!render)
                    render = makeRenderer();
                FrameWrite write = render(frame, file, cancelled);
                if (!write)
                    break; // cancelled before the write: userCancelled() has set m_stop
                if (writing.valid())
                    writing.wait(); // the renderer's buffers of the frame before last are free again
                writing = m_writer.submit(
                    [this, frame, file, write = std::move(write)] { writeFrame(frame, file, write); });
            } catch (...) {
                failWith(frame, file);
            }
        }
        // The renderer (whose buffers the write reads) goes when this thread's loop ends.
        if (writing.valid())
            writing.wait();
    }

    [[nodiscard]] int written() const { return m_written; }
    [[nodiscard]] const std::optional<Failure>& failure() const { return m_failure; }

private:
    /// On the writer thread: writes a frame unless the render was cancelled or failed meanwhile.
    void writeFrame(int frame, const QString& file, const FrameWrite& write)
    {
        {
            const std::lock_guard<std::mutex> lock(m_mutex);
            // Rendered but not written: dropped when cancelled, or when it comes after a frame
            // that failed (the files written stay the frames before the failure).
            if (userCancelled() || (m_failure && m_failure->frame < frame))
                return;
        }
        try {
            write();
            const std::lock_guard<std::mutex> lock(m_mutex);
            ++m_done;
            ++m_written;
            frameDone(frame, file, false);
        } catch (...) {
            failWith(frame, file);
        }
    }

    /// The failure being handled (in a catch block) as the frame's.
    void failWith(int frame, const QString& file)
    {
        try {
            throw;
        } catch (const IoError& e) {
            fail({frame, e.file(), e.problem()});
        } catch (const std::bad_alloc&) {
            fail({frame, file, ScheduleText::tr("not enough memory to render it")});
        } catch (const std::exception& e) {
            fail({frame, file, QString::fromLocal8Bit(e.what())});
        } catch (...) {
            fail({frame, file, ScheduleText::tr("the render failed")});
        }
    }

    /// The next frame's index, or none when the threads are to stop.
    std::optional<int> nextIndex()
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        if (m_stop || m_next >= m_count || userCancelled())
            return std::nullopt;
        return m_next++;
    }

    /// Tells the listener and the progress, with m_mutex held (never two at a time).
    void frameDone(int frame, const QString& file, bool skipped)
    {
        if (m_listener)
            m_listener->frameDone(frame, file, skipped);
        algo::report(m_progress, m_done, m_count);
    }

    /// Asks the caller, with m_mutex held (never two at a time).
    bool userCancelled()
    {
        if (!m_stop && algo::cancelRequested(m_progress))
            m_stop = true;
        return m_stop && !m_failure;
    }

    void fail(Failure failure)
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        // The lowest frame, so that the message does not depend on which thread came first.
        if (!m_failure || failure.frame < m_failure->frame)
            m_failure = std::move(failure);
        m_stop = true;
    }

    const RenderJob& m_job;
    Writer& m_writer;
    algo::Progress* m_progress;
    RenderFrameListener* m_listener;
    const int m_count;
    std::mutex m_mutex;
    int m_next = 0;
    int m_done = 0;
    int m_written = 0;
    bool m_stop = false;
    std::optional<Failure> m_failure;
};

} // namespace

int scheduleFrames(const RenderJob& job, algo::Progress* progress, RenderFrameListener* listener,
    const std::function<FrameRenderer()>& makeRenderer)
{
    Writer writer;
    Schedule schedule(job, progress, listener, writer);
    const int threads = std::clamp(job.threads, 1, std::max(job.frameCount(), 1));
    std::vector<std::thread> helpers;
    helpers.reserve(std::size_t(threads - 1));
    for (int t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back([&schedule, &makeRenderer] { schedule.work(makeRenderer); });
        } catch (const std::system_error&) {
            break; // no more threads to be had: the ones running share the frames
        }
    }
    schedule.work(makeRenderer);
    for (std::thread& helper : helpers)
        helper.join();
    if (const std::optional<Failure>& failure = schedule.failure())
        throw RenderFrameError(failure->frame, failure->file, failure->problem);
    return schedule.written();
}

int concurrentFrames(const RenderJob& job, qint64 availableBytes)
{
    const qint64 wanted = std::clamp(job.threads, 1, std::max(job.frameCount(), 1));
    const qint64 perFrame = std::max<qint64>(job.bytesNeeded(), 0) + kRenderThreadOverheadBytes;
    return int(std::clamp<qint64>(availableBytes / perFrame, 1, wanted));
}

} // namespace celform::model
