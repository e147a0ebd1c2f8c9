// An export as a job of the JobRunner (export_job.h).
#include "editor/jobs/export_job.h"

#include "editor/jobs/job_runner.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QStatusBar>

namespace celform::app {
namespace {

/// The context its strings were translated in (translations/celform_ja.ts) before the JobRunner.
struct ExportText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::ExportRunner)
};

} // namespace

JobRunner* startExport(QMainWindow* window, model::ProjectData data, const QString& source, const model::ExportJob& job)
{
    const auto status = [window](const QString& text) { window->statusBar()->showMessage(text, 10000); };
    JobSpec spec;
    spec.progressName = QStringLiteral("exportProgress");
    spec.title = ExportText::tr("Export");
    spec.label = ExportText::tr("Exporting %1…").arg(QFileInfo(job.output).fileName());
    spec.steps = job.frameCount();
    spec.delayMs = 0;
    spec.outOfMemory = ExportText::tr("%1: not enough memory to export").arg(job.output);
    spec.errorBoxName = QStringLiteral("exportErrorBox");
    spec.errorTitle = ExportText::tr("Export Failed");
    spec.errorText = ExportText::tr("The export could not be finished.");

    auto work = [data = std::move(data), source, job, status](algo::Progress& progress) -> JobRunner::Finish {
        const model::ExportResult result = model::exportProject(data, source, job, &progress);
        return [result, job, status] {
            if (result.cancelled) {
                status(ExportText::tr("Export cancelled."));
                return false;
            }
            QString text = ExportText::tr("Exported %L1 frames to %2")
                               .arg(result.frames)
                               .arg(QDir::toNativeSeparators(job.output));
            for (const QString& w : result.warnings)
                text += QStringLiteral(" — ") + w;
            status(text);
            return true;
        };
    };
    auto* runner = new JobRunner(std::move(spec), std::move(work), window);
    runner->setObjectName(QStringLiteral("exportRunner"));
    QObject::connect(runner, &JobRunner::failed, window,
        [status](const QString& error) { status(ExportText::tr("Export failed: %1").arg(error)); });
    QObject::connect(runner, &JobRunner::finished, runner, &QObject::deleteLater);
    runner->start();
    return runner;
}

} // namespace celform::app
