// Optimise Light for Stereo as a job of the JobRunner (light_optimisation_job.h).
#include "editor/jobs/light_optimisation_job.h"

#include "editor/jobs/job_runner.h"

#include <QCoreApplication>
#include <QStringList>

namespace celform::app {
namespace {

/// The context its strings were translated in (translations/celform_ja.ts) before the JobRunner.
struct LightText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::LightOptimisationRunner)
};

} // namespace

LightOptimisationSummary summariseLightOptimisation(const model::LightOptimisationReport& report)
{
    LightOptimisationSummary summary;
    const int before = algo::segmentsInWindow(report.segmentsBefore);
    const int after = algo::segmentsInWindow(report.segmentsAfter);
    const int segments = int(report.segmentsBefore.size());
    // The ratios' objective of the light kept, which with the default objective (both) may be
    // the depth-error search's rather than the ratios' run's best.
    const double distanceBefore = report.ratiosBefore;
    const double distanceAfter = report.ratiosAfter;
    const double closer = distanceBefore > 0.0 ? 100.0 * (distanceBefore - distanceAfter) / distanceBefore : 0.0;
    // What the optimiser lowers comes first (paper 3, 4.1: the segments' distance from the window),
    // then the count inside it, which may fall while the whole comes closer.
    summary.text = LightText::tr("Light optimised: the segments' bright/dark ratios are %1 % closer to the window "
                                 "(distance %2 → %3); %4 of %5 segments inside it (before: %6); depth error MSE "
                                 "%7 → %8 (%9 ms)")
                       .arg(closer, 0, 'f', 0)
                       .arg(distanceBefore, 0, 'g', 3)
                       .arg(distanceAfter, 0, 'g', 3)
                       .arg(after)
                       .arg(segments)
                       .arg(before)
                       .arg(report.mseBefore, 0, 'g', 4)
                       .arg(report.mseAfter, 0, 'g', 4)
                       .arg(report.milliseconds, 0, 'f', 0);
    if (!report.search.visits.empty())
        summary.text += LightText::tr("; the ratios' light raised the depth error, so a search kept the light with "
                                      "the lowest depth error it met");
    QStringList warnings;
    if (after < before)
        warnings << LightText::tr("Fewer segments are inside the window than before (%1 → %2 of %3): the ratios "
                                  "came closer overall, but some that were inside left it. Undo if those mattered, "
                                  "or weight the segments by area in the Depth tab.")
                        .arg(before)
                        .arg(after)
                        .arg(segments);
    if (report.mseAfter > report.mseBefore)
        warnings << LightText::tr("The segments' ratios improved but the depth error rose: try another start light "
                                  "(move it, then optimise again) or a more lenient window in the Depth tab.");
    summary.warning = warnings.join(QLatin1Char(' '));
    return summary;
}

JobRunner* startLightOptimisation(LightOptimisationJob job, QWidget* parent, LightOptimisationApply apply,
    std::function<void(const QString&)> showError)
{
    const int iterations = job.request.optimiser.iterations;
    JobSpec spec;
    spec.progressName = QStringLiteral("lightOptimisationProgress");
    spec.title = LightText::tr("Optimise Light for Stereo");
    spec.label = LightText::tr("Analysing the picture (%1 × %2)…").arg(job.width).arg(job.height);
    // The two analyses around the iterations count as an iteration each (model::optimiseLight).
    spec.steps = iterations + 2;
    spec.delayMs = 300;
    spec.describe = [iterations](std::int64_t done, std::int64_t, const QString&) {
        return done <= iterations ? LightText::tr("Moving the light: iteration %1 of %2…").arg(done).arg(iterations)
                                  : LightText::tr("Analysing the picture with the new light…");
    };
    spec.outOfMemory = LightText::tr("Not enough memory to analyse %1 × %2 pixels").arg(job.width).arg(job.height);
    spec.showError = std::move(showError);

    auto work = [job = std::move(job), apply = std::move(apply)](algo::Progress& progress) -> JobRunner::Finish {
        model::DepthAnalyser analyser;
        auto report = std::make_shared<const model::LightOptimisationReport>(
            model::optimiseLight(job.data, job.data.look, job.shape, job.generation, job.frame, job.camera, job.width,
                job.height, job.request, analyser, &progress, job.offsets.empty() ? nullptr : &job.offsets));
        return [report, apply] {
            apply(report);
            return !report->cancelled();
        };
    };
    auto* runner = new JobRunner(std::move(spec), std::move(work), parent);
    runner->setObjectName(QStringLiteral("lightOptimisationRunner"));
    QObject::connect(runner, &JobRunner::finished, runner, &QObject::deleteLater);
    runner->start();
    return runner;
}

} // namespace celform::app
