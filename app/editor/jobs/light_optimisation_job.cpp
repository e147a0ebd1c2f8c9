// Optimise Light for Stereo as a job of the JobRunner (light_optimisation_job.h).
#include "editor/jobs/light_optimisation_job.h"

#include "editor/jobs/job_runner.h"

#include <QCoreApplication>

namespace celform::app {
namespace {

/// The context its strings were translated in (translations/celform_ja.ts) before the JobRunner.
struct LightText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::LightOptimisationRunner)
};

} // namespace

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
                job.height, job.request, analyser, &progress));
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
