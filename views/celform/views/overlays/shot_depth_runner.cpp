// The depth analysis along the shot for the Depth tab's chart (shot_depth_runner.h).
#include "celform/views/overlays/shot_depth_runner.h"

#include "celform/model/document/change_set.h"
#include "celform/model/document/document.h"
#include "celform/model/render/render_job.h"

#include <QMetaObject>
#include <QPointer>

#include <exception>
#include <new>

namespace celform::views {

/// Reports each frame to the GUI thread and stops at the shared cancel flag.
class ShotDepthRunner::Progress : public algo::Progress {
public:
    Progress(ShotDepthRunner* runner, int run, std::shared_ptr<std::atomic<bool>> cancel)
        : m_runner(runner)
        , m_run(run)
        , m_cancel(std::move(cancel))
    { }
    void progress(std::int64_t done, std::int64_t total, const std::string&) override
    {
        QPointer<ShotDepthRunner> runner = m_runner;
        const int run = m_run;
        QMetaObject::invokeMethod(m_runner, [runner, run, done, total] {
            if (runner && runner->m_run == run)
                emit runner->progressed(int(done), int(total));
        });
    }
    [[nodiscard]] bool isCancelRequested() const override { return m_cancel->load(); }

private:
    ShotDepthRunner* m_runner;
    int m_run;
    std::shared_ptr<std::atomic<bool>> m_cancel;
};

ShotDepthRunner::ShotDepthRunner(model::Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
    connect(m_document, &model::Document::changed, this, &ShotDepthRunner::documentChanged);
}

ShotDepthRunner::~ShotDepthRunner()
{
    cancel();
    join();
}

void ShotDepthRunner::join()
{
    if (m_worker.joinable())
        m_worker.join();
}

void ShotDepthRunner::cancel()
{
    if (m_cancel)
        m_cancel->store(true);
}

void ShotDepthRunner::documentChanged(const model::ChangeSet& change)
{
    // The playhead alone changes no frame of the shot; anything else may.
    if (change.onlyPlayhead() || change.empty())
        return;
    cancel();
    if (m_current) {
        m_current = false;
        emit staled();
    }
}

void ShotDepthRunner::start(int first, int last, int step, QSize size, const model::AnalysisSettings& settings)
{
    cancel();
    join();
    const model::ProjectData& data = m_document->data();
    if (!data.baseMesh) {
        emit finished(false, tr("Open a model first."));
        return;
    }
    const int run = ++m_run;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    m_running = true;
    m_current = false;
    // A copy of what the analysis reads, so that the document may change meanwhile.
    auto copy = std::make_shared<const model::ProjectData>(data);
    model::RenderJob job;
    job.firstFrame = first;
    job.lastFrame = last;
    job.step = std::max(1, step);
    job.size = size;
    job.pass = QStringLiteral("segments");
    auto progress = std::make_shared<Progress>(this, run, m_cancel);
    QPointer<ShotDepthRunner> self = this;
    m_worker = std::thread([self, run, copy, job, settings, progress] {
        std::vector<ShotDepthSample> samples;
        QString error;
        try {
            model::analyseProjectFrames(
                *copy, tr("the project"), job, settings,
                [&](int frame, const model::AnalysisView&, const model::FrameAnalysis& analysed) {
                    const algo::DepthAnalysis& a = analysed.analysis;
                    ShotDepthSample s;
                    s.frame = frame;
                    s.mse = a.meanSquaredError;
                    s.segments = int(a.stats.size());
                    s.inWindow = a.stats.empty() ? 0.0 : double(algo::segmentsInWindow(a.stats)) / a.stats.size();
                    samples.push_back(s);
                },
                progress.get());
        } catch (const std::bad_alloc&) {
            error = tr("Not enough memory to analyse the shot.");
        } catch (const std::exception& e) {
            error = QString::fromLocal8Bit(e.what());
        }
        const bool cancelled = progress->isCancelRequested();
        if (!self)
            return;
        QMetaObject::invokeMethod(self.data(), [self, run, samples = std::move(samples), error, cancelled]() mutable {
            if (!self || self->m_run != run)
                return;
            self->m_running = false;
            const bool completed = error.isEmpty() && !cancelled;
            if (completed) {
                self->m_samples = std::move(samples);
                self->m_current = true;
            }
            emit self->finished(completed, error);
        });
    });
}

} // namespace celform::views
