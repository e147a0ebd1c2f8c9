// The editor's one runner of long jobs (app/editor/jobs/job_runner.h) driven in the real window
// under Xvfb with the bundled sample: the job runs off the GUI thread, its result is applied on
// the GUI thread as one undo step, Cancel stops it with nothing changed, and a failure is shown.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/jobs/auto_offsets_job.h"
#include "editor/jobs/job_runner.h"
#include "editor/jobs/light_optimisation_job.h"
#include "editor/main_window.h"

#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QRegularExpression>
#include <QStatusBar>
#include <QTimer>
#include <QApplication>
#include <QDialog>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QThread>
#include <QUndoStack>

#include <atomic>

using namespace celform;

namespace {

/// A light other than start, for an edit that makes one undo step.
model::Light movedLight(const model::Light& start)
{
    model::Light moved = start;
    moved.vector = (start.vector + Eigen::Vector3d(0.3, -0.2, 0.1)).normalized();
    return moved;
}

} // namespace

class TestJobRunner : public QObject {
    Q_OBJECT

private slots:
    void appliesTheResultOnTheGuiThreadAsOneUndoStep()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        const int steps = doc->undoStack()->count();
        const model::Light start = doc->data().look.light;
        QThread* gui = QThread::currentThread();
        std::atomic<QThread*> worker{nullptr};
        QThread* applied = nullptr;

        app::JobSpec spec;
        spec.progressName = QStringLiteral("testProgress");
        spec.title = QStringLiteral("Test Job");
        spec.steps = 3;
        spec.delayMs = 0;
        auto* runner = new app::JobRunner(
            spec,
            [&, start](algo::Progress& progress) -> app::JobRunner::Finish {
                worker = QThread::currentThread();
                for (int i = 1; i <= 3; ++i) {
                    QThread::msleep(20);
                    progress.progress(i, 3, "step");
                }
                const model::Light found = movedLight(start);
                return [&, start, found] {
                    applied = QThread::currentThread();
                    doc->look().applyOptimisedLight(start, found, 0);
                    return true;
                };
            },
            &window);
        QSignalSpy progressed(runner, &app::JobRunner::progressed);
        QSignalSpy finished(runner, &app::JobRunner::finished);
        runner->start();
        QVERIFY(runner->isRunning());
        QVERIFY(runner->progressDialog() && runner->progressDialog()->isVisible());
        QCOMPARE(runner->progressDialog()->maximum(), 3);
        QVERIFY(finished.wait(30000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(worker.load() && worker.load() != gui);
        QCOMPARE(applied, gui);
        QVERIFY(!progressed.isEmpty());
        QCOMPARE(progressed.last().at(0).toLongLong(), 3);
        // One undo step, the document's own.
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Optimise Light for Stereo"));
        QVERIFY(!(doc->data().look.light == start));
        QVERIFY(!runner->isRunning());
        QTRY_VERIFY(!window.findChild<QProgressDialog*>(QStringLiteral("testProgress")));
        delete runner;
        doc->undoStack()->undo();
        QCOMPARE(doc->data().look.light, start);
    }

    void cancelStopsTheJobAndChangesNothing()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        const int steps = doc->undoStack()->count();
        const model::Light start = doc->data().look.light;

        app::JobSpec spec;
        spec.progressName = QStringLiteral("testProgress");
        spec.steps = 1000;
        spec.delayMs = 0;
        auto* runner = new app::JobRunner(
            spec,
            [&, start](algo::Progress& progress) -> app::JobRunner::Finish {
                // A job that checks for Cancel after each step, as every long job does.
                bool cancelled = false;
                for (int i = 1; i <= 1000 && !cancelled; ++i) {
                    QThread::msleep(10);
                    progress.progress(i, 1000, {});
                    cancelled = progress.isCancelRequested();
                }
                return [&, start, cancelled] {
                    if (cancelled)
                        return false;
                    doc->look().applyOptimisedLight(start, movedLight(start), 0);
                    return true;
                };
            },
            &window);
        QSignalSpy cancelling(runner, &app::JobRunner::cancelling);
        QSignalSpy finished(runner, &app::JobRunner::finished);
        runner->start();
        QProgressDialog* progress = runner->progressDialog();
        QVERIFY(progress);
        QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 0, 30000);
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel);
        cancel->click();
        QCOMPARE(cancelling.count(), 1);
        QVERIFY(runner->isCancelRequested());
        QVERIFY(finished.count() > 0 || finished.wait(30000));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(doc->undoStack()->count(), steps);
        QCOMPARE(doc->data().look.light, start);
        delete runner;
    }

    void showsAFailureNamingTheFile()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        const int steps = window.document()->undoStack()->count();
        app::JobSpec spec;
        spec.progressName = QStringLiteral("testProgress");
        spec.title = QStringLiteral("Test Job");
        spec.errorBoxName = QStringLiteral("testErrorBox");
        spec.errorTitle = QStringLiteral("Test Failed");
        spec.errorText = QStringLiteral("The test job could not be finished.");
        auto* runner = new app::JobRunner(
            spec,
            [](algo::Progress&) -> app::JobRunner::Finish {
                throw model::IoError(QStringLiteral("/somewhere/shot.png"), QStringLiteral("disk full"));
            },
            &window);
        QSignalSpy failed(runner, &app::JobRunner::failed);
        QSignalSpy finished(runner, &app::JobRunner::finished);
        runner->start();
        QVERIFY(failed.wait(30000));
        QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("/somewhere/shot.png: disk full"));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(runner->errorMessage(), QStringLiteral("/somewhere/shot.png: disk full"));
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("testErrorBox"));
        QVERIFY(box);
        QTRY_VERIFY(box->isVisible());
        QCOMPARE(box->windowTitle(), QStringLiteral("Test Failed"));
        QCOMPARE(box->text(), QStringLiteral("The test job could not be finished."));
        QVERIFY(box->informativeText().contains(QStringLiteral("shot.png")));
        test::keepScreenshot(box, "job-error");
        box->accept();
        QCOMPARE(window.document()->undoStack()->count(), steps);
        delete runner;

        // A refusal of the document when the result is applied is the job's error too.
        spec.showError = [](const QString&) {};
        runner = new app::JobRunner(
            spec,
            [](algo::Progress&) -> app::JobRunner::Finish {
                return []() -> bool { throw model::EditRefused(QStringLiteral("refused")); };
            },
            &window);
        QSignalSpy refused(runner, &app::JobRunner::failed);
        runner->start();
        QVERIFY(refused.wait(30000));
        QCOMPARE(refused.at(0).at(0).toString(), QStringLiteral("refused"));
        delete runner;
    }

    void execWaitsForTheResult()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        int value = 0;
        app::JobSpec spec;
        spec.progressName = QStringLiteral("testProgress");
        app::JobRunner runner(
            spec,
            [&value](algo::Progress&) -> app::JobRunner::Finish {
                QThread::msleep(50);
                return [&value] {
                    value = 42;
                    return true;
                };
            },
            &window);
        QVERIFY(runner.exec());
        QCOMPARE(value, 42);
        QVERIFY(!runner.isRunning());
    }

    void destroyingARunningJobStopsIt()
    {
        // A job that waits for each step to be shown must not hang the window that closes.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        std::atomic<bool> stopped{false};
        app::JobSpec spec;
        spec.progressName = QStringLiteral("testProgress");
        spec.steps = 100000;
        spec.delayMs = 0;
        spec.waitForEachStep = true;
        auto* runner = new app::JobRunner(
            spec,
            [&stopped](algo::Progress& progress) -> app::JobRunner::Finish {
                for (int i = 1; i <= 100000 && !progress.isCancelRequested(); ++i)
                    progress.progress(i, 100000, {});
                stopped = progress.isCancelRequested();
                return {};
            },
            &window);
        runner->start();
        QTRY_VERIFY_WITH_TIMEOUT(runner->progressDialog() && runner->progressDialog()->value() > 10, 30000);
        delete runner;
        QVERIFY(stopped.load());
        QVERIFY(!window.findChild<QProgressDialog*>(QStringLiteral("testProgress")));
    }

    void automaticShadingOffsetsRunOffTheGuiThread()
    {
        // The action's job: the solve on the worker, the values stored on the GUI thread.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        const int steps = doc->undoStack()->count();
        model::AutoOffsetsRequest request;
        request.target = {model::ObjectId(0), doc->currentFrame()};
        request.camera = window.viewport()->camera();
        request.width = 256;
        request.height = 192;
        QThread* applied = nullptr;
        app::JobRunner* runner
            = app::startAutoOffsets(doc->data(), request, &window, [&](const model::AutoOffsetsResult& result) {
                  applied = QThread::currentThread();
                  doc->shading().applyAutoOffsets(result.target, result.values);
              });
        QVERIFY(runner);
        QCOMPARE(runner->objectName(), QStringLiteral("autoOffsetsRunner"));
        QVERIFY(runner->isRunning());
        QSignalSpy finished(runner, &app::JobRunner::finished);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QCOMPARE(applied, QThread::currentThread());
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Automatic Shading Offsets (base)"));
    }

    // Automatic Shading Offsets says the figures the Depth tab then shows: one analysis (the tab's
    // size and settings), one set of numbers.
    void automaticOffsetsAgreeWithTheDepthTab()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        views::DepthAnalysisRunner* depth = window.depthPanel()->runner();
        // The artist's own analysis settings in the Depth tab (not the defaults) and a smaller
        // picture: the action must analyse as the tab does.
        model::AnalysisSettings settings = depth->settings();
        settings.depthThreshold = 0.005;
        settings.minSegmentPixels *= 4;
        depth->setSettings(settings);
        depth->setMaximumSide(400);
        depth->setActive(true);
        QTRY_VERIFY_WITH_TIMEOUT(depth->result() && depth->isCurrent() && !depth->isBusy(), 60000);
        const double mseBefore = depth->result()->meanSquaredError;
        QTimer::singleShot(0, &window, [] {
            for (QWidget* w : QApplication::topLevelWidgets())
                if (auto* dialog = qobject_cast<QDialog*>(w); dialog && dialog->isVisible())
                    dialog->accept();
        });
        window.action(QStringLiteral("actionAutoOffsets"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(
            window.statusBar()->currentMessage().startsWith(QStringLiteral("Automatic shading")), 120000);
        const QString said = window.statusBar()->currentMessage();
        const QRegularExpression figures(
            QStringLiteral("(\\d+) segments; depth error MSE (\\S+) before, (\\S+) after"));
        const QRegularExpressionMatch m = figures.match(said);
        QVERIFY2(m.hasMatch(), qPrintable(said));
        QTRY_VERIFY_WITH_TIMEOUT(depth->result() && depth->isCurrent() && !depth->isBusy()
                && std::abs(depth->result()->meanSquaredError - mseBefore) > 0.0,
            60000);
        const auto& after = *depth->result();
        QCOMPARE(m.captured(1).toInt(), int(after.segmentStats.size()));
        QVERIFY2(std::abs(m.captured(2).toDouble() - mseBefore) <= 1e-3 * mseBefore, qPrintable(said));
        QVERIFY2(std::abs(m.captured(3).toDouble() - after.meanSquaredError) <= 1e-3 * after.meanSquaredError,
            qPrintable(said + QStringLiteral(" / tab: ") + QString::number(after.meanSquaredError)));
    }

    // Optimise Light for Stereo says what it lowered first, and warns when fewer segments end
    // inside the window ("10 -> 6 of 23 segments" read as a failure).
    void lightOptimisationSaysWhatImproved()
    {
        model::LightOptimisationReport report;
        report.ratiosBefore = 2.0;
        report.ratiosAfter = 0.5;
        report.mseBefore = 3e-4;
        report.mseAfter = 2e-4;
        auto segments = [](int inside, int total) {
            std::vector<algo::SegmentStats> s(static_cast<std::size_t>(total));
            for (int i = 0; i < total; ++i)
                s[std::size_t(i)].inWindow = i < inside;
            return s;
        };
        report.segmentsBefore = segments(10, 23);
        report.segmentsAfter = segments(6, 23);
        app::LightOptimisationSummary summary = app::summariseLightOptimisation(report);
        QVERIFY2(summary.text.contains(QStringLiteral("75 % closer")), qPrintable(summary.text));
        QVERIFY2(summary.warning.contains(QStringLiteral("10 → 6 of 23")), qPrintable(summary.warning));
        report.segmentsAfter = segments(14, 23);
        summary = app::summariseLightOptimisation(report);
        QVERIFY(summary.warning.isEmpty());
        QVERIFY(summary.text.contains(QStringLiteral("14 of 23 segments inside it (before: 10)")));
        report.mseAfter = 4e-4;
        QVERIFY(app::summariseLightOptimisation(report).warning.contains(QStringLiteral("depth error rose")));
        // With the default objective (both) a search that ran is said (issue 26).
        report.mseAfter = 2e-4;
        report.search.visits.resize(3);
        QVERIFY(app::summariseLightOptimisation(report).text.contains(QStringLiteral("lowest depth error")));
    }
};

QTEST_MAIN(TestJobRunner)
#include "test_job_runner.moc"
