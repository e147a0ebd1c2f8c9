// The Depth dock (paper 3, chapter 4) driven in the real window under Xvfb with the
// bundled sample: the analysis follows the viewport's camera off the GUI thread, the overlays show
// over the model, and the figures equal those of `celform analyze` for the same camera and size.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"

#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/document/document.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/depth_chart.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/timeline/timeline_ruler.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QProcess>
#include <QProgressDialog>
#include <QToolButton>
#include <QUndoStack>
#include <QSpinBox>
#include <QTableWidget>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

using namespace celform;

namespace {

bool showDepthDock(app::MainWindow& window)
{
    if (!test::showSample(window))
        return false;
    window.activateWindow();
    QApplication::setActiveWindow(&window);
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("depthDock"));
    if (!dock)
        return false;
    dock->show();
    dock->raise();
    QApplication::processEvents();
    return true;
}

/// Waits for an analysis made through the viewport's current camera.
bool waitForCurrent(views::DepthAnalysisRunner* runner, int timeoutMs = 60000)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeoutMs) {
        QTest::qWait(20);
        if (!runner->isBusy() && runner->isCurrent())
            return true;
    }
    return false;
}

/// Fraction of the overlay's pixels inside a widget rectangle that are strongly coloured
/// (saturated: not the grey look of the sample).
double colouredShare(const QImage& image, const QRect& area)
{
    int coloured = 0, total = 0;
    for (int y = area.top(); y <= area.bottom(); y += 3)
        for (int x = area.left(); x <= area.right(); x += 3) {
            const QColor c = image.pixelColor(x, y);
            ++total;
            if (c.hsvSaturation() > 60 && c.value() > 60)
                ++coloured;
        }
    return total ? double(coloured) / total : 0.0;
}

} // namespace

class TestDepthPanel : public QObject {
    Q_OBJECT

private slots:
    void analysisMatchesTheCommandLine()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showDepthDock(window));
        views::DepthPanel* panel = window.depthPanel();
        views::DepthAnalysisRunner* runner = panel->runner();
        QVERIFY(runner->isActive());
        // The command line analyses the view-dependent shape for its camera: show the same.
        window.viewport()->setPreview(true);
        QVERIFY(waitForCurrent(runner));
        const auto result = runner->result();
        QVERIFY(result);
        QVERIFY2(result->error.isEmpty(), qPrintable(result->error));
        QVERIFY(result->segmentStats.size() >= 3);
        QVERIFY(result->meanSquaredError > 0.0);
        QVERIFY(panel->errorLabel()->text().contains(QString::number(result->meanSquaredError, 'g', 4)));
        QCOMPARE(panel->segmentTable()->rowCount(), int(result->segmentStats.size()));

        // The same camera and size through the command line: the same segments and error.
        const model::Camera c = window.viewport()->camera();
        auto vec = [](const Eigen::Vector3d& v) {
            return QStringLiteral("%1,%2,%3").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17);
        };
        QStringList args = {QStringLiteral("analyze"), test::sampleProject(), QStringLiteral("--eye"), vec(c.eye),
            QStringLiteral("--target"), vec(c.target), QStringLiteral("--up"), vec(c.up), QStringLiteral("--size"),
            QStringLiteral("%1x%2").arg(result->width).arg(result->height), QStringLiteral("--json")};
        QCOMPARE(c.projection, model::Projection::Perspective);
        QCOMPARE(c.fovYDegrees, model::Camera().fovYDegrees); // the command line's camera
        QProcess cli;
        cli.start(QStringLiteral(CELFORM_EXECUTABLE), args);
        QVERIFY(cli.waitForFinished(120000));
        QCOMPARE(cli.exitCode(), 0);
        const QJsonObject json = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
        const QJsonArray segments = json.value(QStringLiteral("segments")).toArray();
        QCOMPARE(segments.size(), qsizetype(result->segmentStats.size()));
        for (qsizetype i = 0; i < segments.size(); ++i) {
            const QJsonObject s = segments[i].toObject();
            QCOMPARE(s.value(QStringLiteral("pixels")).toInt(), result->segmentStats[std::size_t(i)].pixels);
            QCOMPARE(float(s.value(QStringLiteral("ratio")).toDouble()), result->segmentStats[std::size_t(i)].ratio);
        }
        const double mse = json.value(QStringLiteral("depth_error")).toObject().value(QStringLiteral("mse")).toDouble();
        QVERIFY2(std::abs(mse - result->meanSquaredError) <= 1e-12 + 1e-9 * mse,
            qPrintable(
                QStringLiteral("CLI %1, editor %2").arg(mse, 0, 'g', 12).arg(result->meanSquaredError, 0, 'g', 12)));
    }

    void overlaysFollowTheViewWithoutBlockingIt()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showDepthDock(window));
        views::DepthPanel* panel = window.depthPanel();
        views::DepthAnalysisRunner* runner = panel->runner();
        views::Viewport* viewport = window.viewport();
        QVERIFY(waitForCurrent(runner));

        // Shift+D cycles: none -> segments.
        QAction* next = window.findChild<QAction*>(QStringLiteral("actionDepthOverlayNext"));
        QVERIFY(next);
        QCOMPARE(next->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_D));
        next->trigger();
        QCOMPARE(panel->overlay()->kind(), views::DepthOverlay::Kind::Segments);
        QVERIFY(window.findChild<QAction*>(QStringLiteral("actionDepthOverlaySegments"))->isChecked());
        QTest::qWait(50);
        QImage shot = window.grab().toImage();
        const QRect area(viewport->mapTo(&window, QPoint(0, 0)), viewport->size());
        const double segmentsShare = colouredShare(shot, area);
        test::keepScreenshot(&window, "depth-segments");
        QVERIFY2(segmentsShare > 0.03, qPrintable(QString::number(segmentsShare)));
        // None shows the grey look only.
        panel->setOverlayKind(views::DepthOverlay::Kind::None);
        QTest::qWait(50);
        QVERIFY(colouredShare(window.grab().toImage(), area) < segmentsShare / 4);

        // Orbiting: each step returns at once while the analysis runs on its own thread, and the
        // overlay catches up with the camera.
        panel->setOverlayKind(views::DepthOverlay::Kind::DepthError);
        const model::Camera start = viewport->camera();
        QElapsedTimer step;
        qint64 slowest = 0;
        int busySeen = 0;
        for (int i = 1; i <= 12; ++i) {
            model::Camera c = start;
            const Eigen::AngleAxisd turn(0.05 * i, Eigen::Vector3d::UnitY());
            c.eye = c.target + turn * (start.eye - start.target);
            step.start();
            viewport->setCamera(c);
            QApplication::processEvents();
            slowest = std::max(slowest, step.elapsed());
            busySeen += runner->isBusy() ? 1 : 0;
        }
        QVERIFY(busySeen > 0);
        QVERIFY(waitForCurrent(runner));
        QVERIFY(runner->result()->camera == viewport->camera());
        test::keepScreenshot(&window, "depth-error");
        QVERIFY(colouredShare(window.grab().toImage(), area) > 0.0);
        qInfo("slowest camera step with the analysis running: %lld ms; analysis %.1f ms", slowest,
            runner->result()->milliseconds);

        // The curvature overlay and its legend.
        panel->setOverlayKind(views::DepthOverlay::Kind::Curvature);
        QTest::qWait(50);
        test::keepScreenshot(&window, "depth-curvature");
        QVERIFY(colouredShare(window.grab().toImage(), area) > 0.01);

        // Hiding the dock with no overlay stops the analysis.
        panel->setOverlayKind(views::DepthOverlay::Kind::None);
        window.findChild<QDockWidget*>(QStringLiteral("depthDock"))->hide();
        QApplication::processEvents();
        QVERIFY(!runner->isActive());
    }

    void settingsChangeTheSegments()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showDepthDock(window));
        views::DepthAnalysisRunner* runner = window.depthPanel()->runner();
        QVERIFY(waitForCurrent(runner));
        const std::size_t before = runner->result()->segmentStats.size();
        // A smallest segment larger than any part of the picture leaves none.
        auto* minimum = window.depthPanel()->findChild<QSpinBox*>(QStringLiteral("minSegmentPixels"));
        QVERIFY(minimum);
        minimum->setValue(minimum->maximum());
        QCOMPARE(runner->settings().minSegmentPixels, minimum->maximum());
        QTRY_VERIFY_WITH_TIMEOUT(!runner->isBusy() && runner->result()->segmentStats.empty(), 60000);
        minimum->setValue(algo::kMinSegmentPixels);
        QTRY_VERIFY_WITH_TIMEOUT(!runner->isBusy() && runner->result()->segmentStats.size() == before, 60000);
    }

    void optimiseLightForStereoLowersTheError()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showDepthDock(window));
        views::DepthAnalysisRunner* runner = window.depthPanel()->runner();
        model::Document* doc = window.document();
        QVERIFY(waitForCurrent(runner));
        const double mseBefore = runner->result()->meanSquaredError;
        const model::Light start = doc->data().look.light;
        const int steps = doc->undoStack()->count();

        // Cancel straight away: the first analysis is still running, nothing changes.
        QAction* optimise = window.action(QStringLiteral("actionOptimiseLight"));
        QVERIFY(optimise);
        QCOMPARE(optimise->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+L")));
        optimise->trigger();
        auto* progress = window.findChild<QProgressDialog*>(QStringLiteral("lightOptimisationProgress"));
        QVERIFY(progress);
        emit progress->canceled(); // what its Cancel button sends
        QTRY_VERIFY_WITH_TIMEOUT(
            !window.findChild<QProgressDialog*>(QStringLiteral("lightOptimisationProgress")), 60000);
        QCOMPARE(doc->data().look.light, start);
        QCOMPARE(doc->undoStack()->count(), steps);

        // The Depth tab's button runs the action: one undo step, and the live error falls.
        auto* button = window.depthPanel()->findChild<QToolButton*>(QStringLiteral("optimiseLightButton"));
        QVERIFY(button);
        QCOMPARE(button->defaultAction(), optimise);
        QTest::mouseClick(button, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(doc->undoStack()->count() == steps + 1, 60000);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Optimise Light for Stereo"));
        QVERIFY(!(doc->data().look.light == start));
        QVERIFY(waitForCurrent(runner));
        const double mseAfter = runner->result()->meanSquaredError;
        QVERIFY2(mseAfter < mseBefore, qPrintable(QStringLiteral("%1 -> %2").arg(mseBefore).arg(mseAfter)));
        test::keepScreenshot(&window, "depth-optimised-light");
        doc->undoStack()->undo();
        QCOMPARE(doc->data().look.light, start);
    }

    void optimiseLightAlongShotAndChartIt()
    {
        // issue 26: the Depth tab charts the depth error over the shot, clicking the chart moves
        // the playhead, and Look > Optimise Light Along Shot keys the light at every frame as one
        // undo step, cancellable, marked on the Timeline. Three frames of the sample's turntable
        // keep it quick.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showDepthDock(window));
        model::Document* doc = window.document();
        model::SceneTime time = doc->data().time;
        time.firstFrame = 0;
        time.lastFrame = 2;
        doc->animation().setSceneTime(time);
        views::DepthPanel* panel = window.depthPanel();

        auto* chartButton = panel->findChild<QToolButton*>(QStringLiteral("chartShotButton"));
        QVERIFY(chartButton);
        QTest::mouseClick(chartButton, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel->shotRunner()->isCurrent(), 60000);
        views::DepthChart* chart = panel->chart();
        QCOMPARE(chart->samples().size(), std::size_t(3));
        for (const views::ShotDepthSample& s : chart->samples())
            QVERIFY(s.mse > 0.0 && s.inWindow >= 0.0 && s.inWindow <= 1.0);
        QCOMPARE(chart->samples()[2].frame, 2);
        QTest::mouseClick(chart, Qt::LeftButton, {}, QPoint(int(chart->xForFrame(2)), chart->height() / 2));
        QCOMPARE(doc->currentFrame(), 2);
        QTest::mouseClick(chart, Qt::LeftButton, {}, QPoint(int(chart->xForFrame(0)), chart->height() / 2));
        QCOMPARE(doc->currentFrame(), 0);

        // Cancel straight away: nothing changes.
        QAction* along = window.action(QStringLiteral("actionOptimiseLightAlongShot"));
        QVERIFY(along);
        const int steps = doc->undoStack()->count();
        along->trigger();
        auto* progress = window.findChild<QProgressDialog*>(QStringLiteral("lightTrackProgress"));
        QVERIFY(progress);
        emit progress->canceled();
        QTRY_VERIFY_WITH_TIMEOUT(!window.findChild<QProgressDialog*>(QStringLiteral("lightTrackProgress")), 60000);
        QVERIFY(doc->data().look.lightTrack.empty());
        QCOMPARE(doc->undoStack()->count(), steps);

        // The run: a key per frame in one undo step, each turning at most 3° a frame.
        along->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(doc->undoStack()->count() == steps + 1, 120000);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Optimise Light Along Shot"));
        const model::LightTrack& track = doc->data().look.lightTrack;
        QCOMPARE(track.keys.size(), std::size_t(3));
        const Eigen::Vector3d centre = doc->data().baseMesh->centre();
        for (std::size_t k = 1; k < track.keys.size(); ++k)
            QVERIFY(model::lightTurnDegrees(track.keys[k - 1].light, track.keys[k].light, centre) <= 3.0 + 1e-6
                || track.keys[k].light.type == model::LightType::Point);
        // The chart now shows an older light; the Timeline marks the keys.
        QVERIFY(!panel->shotRunner()->isCurrent());
        auto* ruler = window.findChild<views::TimelineRuler*>(QStringLiteral("timelineRuler"));
        QVERIFY(ruler);
        int lightMarks = 0;
        for (const views::TimelineMark& mark : ruler->marks())
            lightMarks += mark.kind == views::TimelineMarkKind::Light ? 1 : 0;
        QCOMPARE(lightMarks, 3);
        test::keepScreenshot(&window, "depth-light-track");
        doc->undoStack()->undo();
        QVERIFY(doc->data().look.lightTrack.empty());
    }
};

QTEST_MAIN(TestDepthPanel)
#include "test_depth_panel.moc"
