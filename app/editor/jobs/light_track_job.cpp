// Optimise Light Along Shot as a job of the JobRunner (light_track_job.h).
#include "editor/jobs/light_track_job.h"

#include "editor/jobs/job_runner.h"

#include <QCoreApplication>

namespace celform::app {
namespace {

struct TrackText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::LightTrackRunner)
};

/// The progress steps of one frame (model::optimiseLightTrack scales each frame into as many).
constexpr std::int64_t kFrameSteps = 1000;

} // namespace

QString summariseLightTrack(const model::LightTrackReport& report)
{
    return TrackText::tr("Light track: %n frame(s) keyed; mean depth error MSE %1 → %2; largest turn between keys "
                         "%3° (%4 ms)",
        nullptr, int(report.frames.size()))
        .arg(report.meanMseOriginal(), 0, 'g', 4)
        .arg(report.meanMse(), 0, 'g', 4)
        .arg(report.largestTurnDegrees(), 0, 'f', 1)
        .arg(report.milliseconds, 0, 'f', 0);
}

JobRunner* startLightTrackOptimisation(
    LightTrackJob job, QWidget* parent, LightTrackApply apply, std::function<void(const QString&)> showError)
{
    const int step = std::max(1, job.frames.step);
    const int count
        = job.frames.lastFrame < job.frames.firstFrame ? 0 : (job.frames.lastFrame - job.frames.firstFrame) / step + 1;
    const int first = job.frames.firstFrame;
    JobSpec spec;
    spec.progressName = QStringLiteral("lightTrackProgress");
    spec.title = TrackText::tr("Optimise Light Along Shot");
    spec.label = TrackText::tr("Optimising the light at %n frame(s)…", nullptr, count);
    spec.steps = std::int64_t(count) * kFrameSteps;
    spec.delayMs = 0;
    spec.describe = [first, step, count](std::int64_t done, std::int64_t, const QString&) {
        const int index = std::min(count - 1, int(done / kFrameSteps));
        return TrackText::tr("Optimising the light at frame %1 (%2 of %3)…")
            .arg(first + index * step)
            .arg(index + 1)
            .arg(count);
    };
    spec.outOfMemory = TrackText::tr("Not enough memory to analyse %1 × %2 pixels")
                           .arg(job.frames.size.width())
                           .arg(job.frames.size.height());
    spec.showError = std::move(showError);

    auto work = [job = std::move(job), apply = std::move(apply)](algo::Progress& progress) -> JobRunner::Finish {
        auto report = std::make_shared<const model::LightTrackReport>(
            model::optimiseLightTrack(job.data, TrackText::tr("the project"), job.frames, job.request, &progress));
        return [report, apply] {
            apply(report);
            return !report->cancelled;
        };
    };
    auto* runner = new JobRunner(std::move(spec), std::move(work), parent);
    runner->setObjectName(QStringLiteral("lightTrackRunner"));
    QObject::connect(runner, &JobRunner::finished, runner, &QObject::deleteLater);
    runner->start();
    return runner;
}

} // namespace celform::app
