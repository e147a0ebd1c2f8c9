// Automatic Shading Offsets as a job of the JobRunner (auto_offsets_job.h).
#include "editor/jobs/auto_offsets_job.h"

#include "editor/jobs/job_runner.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPointer>

#include <memory>

namespace celform::app {
namespace {

/// The context of the action's strings (translations/celform_ja.ts), shared with offset_actions.
struct OffsetText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::OffsetActions)
};

} // namespace

JobRunner* startAutoOffsets(model::ProjectData data, const model::AutoOffsetsRequest& request, QWidget* parent,
    std::function<void(const model::AutoOffsetsResult&)> apply)
{
    JobSpec spec;
    spec.progressName = QStringLiteral("autoOffsetsProgress");
    spec.title = OffsetText::tr("Automatic Shading Offsets");
    spec.label = OffsetText::tr("Analysing the picture (%1 × %2)…").arg(request.width).arg(request.height);
    spec.steps = 3; // three analyses (solveAutoOffsets)
    spec.delayMs = 300;
    spec.outOfMemory
        = OffsetText::tr("Not enough memory to analyse %1 × %2 pixels").arg(request.width).arg(request.height);
    QPointer<QWidget> window = parent;
    spec.showError = [window](const QString& error) {
        QMessageBox::warning(window, OffsetText::tr("Automatic Shading Offsets"), error);
    };

    auto work
        = [data = std::move(data), request, apply = std::move(apply)](algo::Progress& progress) -> JobRunner::Finish {
        auto result
            = std::make_shared<const model::AutoOffsetsResult>(model::solveAutoOffsets(data, request, &progress));
        return [result, apply] {
            if (result->cancelled)
                return false;
            apply(*result);
            return true;
        };
    };
    auto* runner = new JobRunner(std::move(spec), std::move(work), parent);
    runner->setObjectName(QStringLiteral("autoOffsetsRunner"));
    QObject::connect(runner, &JobRunner::finished, runner, &QObject::deleteLater);
    runner->start();
    return runner;
}

} // namespace celform::app
