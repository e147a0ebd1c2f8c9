// Fit Camera and Fit Shape to Drawing as jobs of the JobRunner (fit_job.h).
#include "editor/jobs/fit_job.h"

#include "editor/jobs/job_runner.h"

#include "celform/model/data/io_error.h"

#include <QCoreApplication>

#include <memory>

namespace celform::app {
namespace {

struct FitText {
    Q_DECLARE_TR_FUNCTIONS(celform::app::FitActions)
};

/// The runner of a fit whose work returns a result with ok, cancelled and error; apply gets it
/// when it succeeded.
template <typename Result>
JobRunner* startFit(JobSpec spec, const char* name, QWidget* parent, std::function<Result(algo::Progress&)> solve,
    std::function<void(const Result&)> apply)
{
    auto work = [solve = std::move(solve), apply = std::move(apply)](algo::Progress& progress) -> JobRunner::Finish {
        auto result = std::make_shared<const Result>(solve(progress));
        return [result, apply] {
            if (result->cancelled)
                return false;
            if (!result->ok)
                throw model::EditRefused(result->error);
            apply(*result);
            return true;
        };
    };
    auto* runner = new JobRunner(std::move(spec), std::move(work), parent);
    runner->setObjectName(QString::fromLatin1(name));
    QObject::connect(runner, &JobRunner::finished, runner, &QObject::deleteLater);
    runner->start();
    return runner;
}

JobSpec fitSpec(const QString& title, const QString& label, std::function<void(const QString&)> showError)
{
    JobSpec spec;
    spec.progressName = QStringLiteral("fitProgress");
    spec.title = title;
    spec.label = label;
    spec.steps = 0; // busy until the fit reports its total
    spec.delayMs = 300;
    spec.outOfMemory = FitText::tr("Not enough memory to fit the model to the drawing.");
    spec.showError = std::move(showError);
    return spec;
}

} // namespace

JobRunner* startFitCamera(model::ProjectData data, model::ObjectId drawingId, model::ObjectId keyId, QWidget* parent,
    std::function<void(const model::CameraFit&)> apply, std::function<void(const QString&)> showError)
{
    JobSpec spec = fitSpec(FitText::tr("Fit Camera to Drawing"),
        FitText::tr("Fitting the camera to the drawing's outline…"), std::move(showError));
    spec.describe = [](std::int64_t done, std::int64_t total, const QString&) {
        return FitText::tr("Fitting the camera: step %1 of %2…").arg(done).arg(total);
    };
    std::function<model::CameraFit(algo::Progress&)> solve
        = [data = std::move(data), drawingId, keyId](
              algo::Progress& progress) { return model::fitCameraToDrawing(data, drawingId, keyId, &progress); };
    return startFit<model::CameraFit>(std::move(spec), "fitCameraRunner", parent, std::move(solve), std::move(apply));
}

JobRunner* startFitShape(model::ProjectData data, model::ObjectId keyId, model::ObjectId drawingId,
    const model::ShapeFitRequest& request, QWidget* parent, std::function<void(const model::ShapeFit&)> apply,
    std::function<void(const QString&)> showError)
{
    JobSpec spec = fitSpec(FitText::tr("Fit Shape to Drawing"),
        FitText::tr("Fitting the key's shape to the drawing's outline…"), std::move(showError));
    spec.describe = [](std::int64_t done, std::int64_t total, const QString&) {
        return FitText::tr("Fitting the shape: round %1 of %2…").arg(done).arg(total);
    };
    std::function<model::ShapeFit(algo::Progress&)> solve
        = [data = std::move(data), keyId, drawingId, request](algo::Progress& progress) {
              return model::fitShapeToDrawing(data, keyId, drawingId, request, &progress);
          };
    return startFit<model::ShapeFit>(std::move(spec), "fitShapeRunner", parent, std::move(solve), std::move(apply));
}

} // namespace celform::app
