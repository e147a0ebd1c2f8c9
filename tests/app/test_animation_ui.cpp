// The editor's animation driven through the real window under Xvfb with the bundled
// sample: the Timeline dock's range and rate (undoable), its key marks of every kind and key
// jumps, playback with and without looping, looking through the shot camera at the playhead,
// keying the camera, the Observer's camera path, and the frame rate playback reaches.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"

#include "celform/model/document/document.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/data/blend_evaluator.h"
#include "celform/views/overlays/camera_path_overlay.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/panels/depth_panel.h"
#include "celform/views/timeline/playback.h"
#include "celform/views/timeline/timeline_panel.h"
#include "celform/views/panels/view_sphere_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoStack>

#include <vtkCellArray.h>
#include <vtkPolyData.h>

#include <algorithm>

using namespace celform;
using views::TimelineMark;
using views::TimelineMarkKind;

using test::showActive;

namespace {

views::TimelinePanel* timeline(const app::MainWindow& window)
{
    return window.findChild<views::TimelinePanel*>();
}

bool hasMark(const std::vector<TimelineMark>& marks, int frame, TimelineMarkKind kind)
{
    return std::find(marks.begin(), marks.end(), TimelineMark{frame, kind}) != marks.end();
}

double aspectOf(const views::Viewport* v)
{
    return double(v->width()) / double(v->height());
}

} // namespace

class TestAnimationUi : public QObject {
    Q_OBJECT
private slots:
    void rangeAndRateEditsAreUndoSteps()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        views::TimelinePanel* panel = timeline(window);
        QVERIFY(panel);
        QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("timelineDock"))->isVisible());
        const model::SceneTime before = doc->data().time;
        const int steps = doc->undoStack()->count();
        panel->lastFrameBox()->setValue(30);
        QCOMPARE(doc->data().time.lastFrame, 30);
        panel->firstFrameBox()->setValue(4);
        QCOMPARE(doc->data().time.firstFrame, 4);
        panel->fpsBox()->setValue(12.0);
        QCOMPARE(doc->data().time.fps, 12.0);
        QCOMPARE(doc->undoStack()->count(), steps + 3);
        // The boxes bound each other: the first frame cannot pass the last.
        QCOMPARE(panel->firstFrameBox()->maximum(), 30);
        QCOMPARE(panel->lastFrameBox()->minimum(), 4);
        QCOMPARE(panel->ruler()->firstFrame(), 4);
        QCOMPARE(panel->ruler()->lastFrame(), 30);
        doc->undoStack()->undo();
        QCOMPARE(doc->data().time.fps, before.fps);
        QCOMPARE(panel->fpsBox()->value(), before.fps);
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QVERIFY(doc->data().time == before);
        QCOMPARE(panel->lastFrameBox()->value(), before.lastFrame);
    }

    void keyMarksOfEveryKindAndKeyJumps()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        views::TimelinePanel* panel = timeline(window);
        // A key deformation at frame 12 (one vertex moved), a highlight key at 5, a camera key at 9.
        model::Camera side = window.viewport()->camera();
        const model::ObjectId key = doc->keys().createKey(QStringLiteral("test key"), side);
        model::SparseOffsets moved;
        moved.indices.push_back(0);
        moved.deltas.emplace_back(0.01f, 0.f, 0.f);
        doc->keys().setKeyDeformation(key, 12, moved, QStringLiteral("test"));
        doc->highlights().addHighlightLayer(QStringLiteral("test highlight"), 5);
        doc->animation().setCameraKey(9, window.viewport()->camera());
        const std::vector<TimelineMark>& marks = panel->marks();
        QVERIFY(hasMark(marks, 12, TimelineMarkKind::Deformation));
        QVERIFY(hasMark(marks, 5, TimelineMarkKind::Highlight));
        QVERIFY(hasMark(marks, 9, TimelineMarkKind::Camera));
        QCOMPARE(panel->ruler()->marks().size(), marks.size());
        std::vector<int> frames = views::markFrames(marks);
        QVERIFY(frames.size() >= 3);

        // Next/previous key over the union of the kinds, by action and by the keys in the viewport.
        doc->setCurrentFrame(frames.front() - 1);
        for (int f : frames) {
            window.action(QStringLiteral("actionNextKeyFrame"))->trigger();
            QCOMPARE(doc->currentFrame(), f);
        }
        window.action(QStringLiteral("actionNextKeyFrame"))->trigger(); // none after the last
        QCOMPARE(doc->currentFrame(), frames.back());
        window.viewport()->setFocus();
        QApplication::processEvents();
        QTest::keyClick(window.viewport(), Qt::Key_Down);
        QCOMPARE(doc->currentFrame(), frames[frames.size() - 2]);
        QTest::keyClick(window.viewport(), Qt::Key_Up);
        QCOMPARE(doc->currentFrame(), frames.back());
        QTest::keyClick(window.viewport(), Qt::Key_Left);
        QCOMPARE(doc->currentFrame(), frames.back() - 1);
        QTest::keyClick(window.viewport(), Qt::Key_Right, Qt::ShiftModifier);
        QCOMPARE(doc->currentFrame(), doc->data().time.lastFrame);
        QTest::keyClick(window.viewport(), Qt::Key_Left, Qt::ShiftModifier);
        QCOMPARE(doc->currentFrame(), doc->data().time.firstFrame);

        // Scrubbing the ruler moves the playhead to the frame under the cursor.
        views::TimelineRuler* ruler = panel->ruler();
        QTest::mouseClick(ruler, Qt::LeftButton, {}, QPoint(int(ruler->xForFrame(9)), ruler->height() / 2));
        QCOMPARE(doc->currentFrame(), 9);
        test::keepScreenshot(panel, "timeline-panel");
    }

    void playLoopsAndStops()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        views::TimelinePanel* panel = timeline(window);
        views::Playback* playback = panel->playback();
        doc->animation().setSceneTime({24.0, 0, 3});
        std::vector<int> seen;
        connect(doc, &model::Document::changed, this, [&](const model::ChangeSet& change) {
            if (change.has(model::Part::Playhead))
                seen.push_back(doc->currentFrame());
        });
        QVERIFY(playback->isLooping());
        window.viewport()->setFocus();
        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QVERIFY(playback->isPlaying());
        QVERIFY(panel->playButton()->isChecked());
        // Wraps: some frame follows a later one.
        QTRY_VERIFY_WITH_TIMEOUT(std::adjacent_find(seen.begin(), seen.end(), std::greater<>()) != seen.end(), 5000);
        QVERIFY(std::all_of(seen.begin(), seen.end(), [](int f) { return f >= 0 && f <= 3; }));
        // The rate reached shows while playing.
        QTRY_VERIFY_WITH_TIMEOUT(panel->fpsReadout().contains(QStringLiteral("fps")), 5000);
        QVERIFY(playback->achievedFps() > 0.0);
        QTest::keyClick(window.viewport(), Qt::Key_Space);
        QVERIFY(!playback->isPlaying());

        window.action(QStringLiteral("actionLoopPlayback"))->setChecked(false);
        QVERIFY(!playback->isLooping());
        QVERIFY(!panel->loopButton()->isChecked());
        doc->setCurrentFrame(0);
        window.action(QStringLiteral("actionPlayPause"))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!playback->isPlaying(), 5000);
        QCOMPARE(doc->currentFrame(), 3);
    }

    void newFromMeshOpensAnAnimatedCharacter()
    {
        // The bundled skinned glTF: a new project on it moves with the playhead, at its rate.
        const QString glb = QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-trunk.glb");
        {
            app::MainWindow window(app::MainWindow::Mode::Batch);
            window.resize(1400, 900);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QVERIFY(window.openFile(glb));
            const model::ProjectData& data = window.document()->data();
            QVERIFY(data.animated());
            QCOMPARE(data.time.fps, 24.0);
            QCOMPARE(data.time.firstFrame, 0);
            QCOMPARE(data.time.lastFrame, 47);
            views::Viewport* viewport = window.viewport();
            test::waitForRender(viewport);
            const algo::Positions atStart = viewport->displayedShape();
            window.document()->setCurrentFrame(24);
            test::waitForRender(viewport);
            QVERIFY2((viewport->displayedShape() - atStart).cwiseAbs().maxCoeff() > 0.05f,
                "the trunk should have swung by frame 24");
        }
        // On an open project with the same vertex order: the base is replaced in one undo step and
        // the drawings stay.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        QVERIFY(!doc->data().animated());
        const std::size_t drawings = doc->data().drawings.size();
        QVERIFY(window.openFile(glb));
        QVERIFY(doc->data().animated());
        QCOMPARE(doc->data().drawings.size(), drawings);
        doc->undoStack()->undo();
        QVERIFY(!doc->data().animated());
    }

    void depthAnalysisWaitsForPlaybackToStop()
    {
        // The Depth tab analyses the picture after every change; while the timeline plays it
        // waits (its worker would take the cores playback needs), then analyses the frame shown.
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        views::Playback* playback = timeline(window)->playback();
        doc->animation().setSceneTime({24.0, 0, 11});
        window.findChild<QDockWidget*>(QStringLiteral("depthDock"))->raise();
        views::DepthAnalysisRunner* runner = window.depthPanel()->runner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->isActive(), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(runner->isCurrent() && !runner->isBusy(), 30000);
        QSignalSpy analysed(runner, &views::DepthAnalysisRunner::analysed);
        window.action(QStringLiteral("actionLoopPlayback"))->setChecked(false);
        playback->play();
        QVERIFY(runner->isHeld());
        QTRY_VERIFY_WITH_TIMEOUT(!playback->isPlaying(), 10000);
        QVERIFY(!runner->isHeld());
        QCOMPARE(analysed.count(), 0); // twelve frames played, none analysed
        QTRY_VERIFY_WITH_TIMEOUT(runner->isCurrent(), 30000);
        QCOMPARE(runner->result()->frame, 11);
        QCOMPARE(analysed.count(), 1);
    }

    void looksThroughTheShotCameraAtThePlayhead()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        views::Viewport* viewport = window.viewport();
        QAction* lookThrough = window.action(QStringLiteral("actionLookThroughShotCamera"));
        QVERIFY(!lookThrough->isChecked()); // the sample has no camera path
        doc->animation().makeTurntable(model::Turntable{}, aspectOf(viewport));
        lookThrough->setChecked(true);
        QVERIFY(viewport->isPreview());
        auto* sphere = window.findChild<views::ViewSpherePanel*>();
        QVERIFY(sphere);
        for (int f : {0, 7, 20, 47}) {
            doc->setCurrentFrame(f);
            const model::Camera wanted = model::cameraAtFrame(doc->data(), doc->data().look, f, aspectOf(viewport));
            const model::Camera shown = viewport->camera();
            QVERIFY2((shown.eye - wanted.eye).norm() < 1e-9, qPrintable(QString::number(f)));
            QVERIFY((shown.target - wanted.target).norm() < 1e-9);
            QVERIFY((shown.trueUp() - wanted.trueUp()).norm() < 1e-9);
            QVERIFY(std::abs(shown.fovYDegrees - wanted.fovYDegrees) < 1e-9);
            const Eigen::Vector3d direction = model::viewDirectionFromEye(doc->data(), wanted.eye, f);
            QVERIFY((sphere->viewDirection() - direction).norm() < 1e-9);
        }
        test::waitForRender(viewport);
        test::keepScreenshot(&window, "shot-camera");

        // A project with a path opens looking through it.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("turntable.celform"));
        QVERIFY(window.saveAs(path));
        lookThrough->setChecked(false);
        QVERIFY(window.openFile(path));
        QVERIFY(lookThrough->isChecked());
        doc->setCurrentFrame(11);
        QVERIFY((viewport->camera().eye - doc->data().look.cameraPath.at(11).eye).norm() < 1e-9);

        // Turning the view with the mouse leaves the shot camera.
        const QPoint c = viewport->rect().center();
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(40, 0));
        QVERIFY(!lookThrough->isChecked());
        const model::Camera turned = viewport->camera();
        doc->setCurrentFrame(12);
        QVERIFY(viewport->camera() == turned);
    }

    void keyCameraIsOneUndoStep()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        QAction* keyCamera = window.action(QStringLiteral("actionKeyCamera"));
        QVERIFY(keyCamera);
        QCOMPARE(keyCamera->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_K));
        doc->setCurrentFrame(5);
        keyCamera->trigger();
        QVERIFY(doc->data().look.cameraPath.hasKey(5));
        QVERIFY(doc->data().look.cameraPath.keys.front().camera.eye.isApprox(window.viewport()->camera().eye));
        QVERIFY(window.action(QStringLiteral("actionRemoveCameraKey"))->isEnabled());
        doc->undoStack()->undo();
        QVERIFY(doc->data().look.cameraPath.empty());
        QVERIFY(!window.action(QStringLiteral("actionRemoveCameraKey"))->isEnabled());
        doc->undoStack()->redo();
        QVERIFY(doc->data().look.cameraPath.hasKey(5));
        window.action(QStringLiteral("actionRemoveCameraKey"))->trigger();
        QVERIFY(doc->data().look.cameraPath.empty());
    }

    void observerShowsThePathAndTheCamera()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        views::Viewport* viewport = window.viewport();
        model::Camera camera = viewport->camera();
        for (int f : {0, 10, 20}) {
            camera.eye = Eigen::AngleAxisd(0.3 * f / 10.0, Eigen::Vector3d::UnitY()) * (camera.eye - camera.target)
                + camera.target;
            doc->animation().setCameraKey(f, camera);
        }
        window.action(QStringLiteral("actionObserverLayout"))->setChecked(true);
        QDockWidget* dock = window.findChild<QDockWidget*>(QStringLiteral("observerDock"));
        QTRY_VERIFY(dock->isVisible());
        auto* overlay = window.observer()->findChild<views::CameraPathOverlay*>();
        QVERIFY(overlay);
        vtkPolyData* path = overlay->pathPolyData();
        QCOMPARE(int(path->GetNumberOfPoints()), 3);
        QCOMPARE(int(path->GetLines()->GetNumberOfCells()), 1);
        double p[3];
        path->GetPoint(1, p);
        QVERIFY((Eigen::Vector3d(p[0], p[1], p[2]) - doc->data().look.cameraPath.keys[1].camera.eye).norm() < 1e-9);
        // The camera glyph sits at the main camera's eye and follows the playhead.
        window.action(QStringLiteral("actionLookThroughShotCamera"))->setChecked(true);
        doc->setCurrentFrame(10);
        overlay->cameraGlyph()->GetPoint(0, p);
        QVERIFY((Eigen::Vector3d(p[0], p[1], p[2]) - doc->data().look.cameraPath.at(10).eye).norm() < 1e-9);
        doc->setCurrentFrame(15);
        overlay->cameraGlyph()->GetPoint(0, p);
        QVERIFY((Eigen::Vector3d(p[0], p[1], p[2]) - doc->data().look.cameraPath.at(15).eye).norm() < 1e-9);
        test::waitForRender(window.observer());
        test::keepScreenshot(&window, "observer-layout");
        window.action(QStringLiteral("actionObserverLayout"))->setChecked(false);
        QVERIFY(!dock->isVisible());
    }

    // The showcase sample (two keys, a 48-frame turntable) plays at the look's full
    // quality through the shot camera. Reports the rate reached; asserts only a loose bound (a
    // loaded CI machine), the figure goes in the log.
    void playbackFrameRate()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        QVERIFY(window.openFile(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform")));
        model::Document* doc = window.document();
        views::Viewport* viewport = window.viewport();
        QCOMPARE(doc->data().look.cameraPath.keys.size(), std::size_t(48));
        QVERIFY(window.action(QStringLiteral("actionLookThroughShotCamera"))->isChecked());
        window.action(QStringLiteral("actionLoopPlayback"))->setChecked(false);
        views::Playback* playback = timeline(window)->playback();
        test::waitForRender(viewport);
        doc->animation().setSceneTime({24.0, 0, 47});
        doc->setCurrentFrame(0);
        test::waitForRender(viewport);
        // From frame 0 the clock calls for frames 1..47, one every 1/24 s; the player stops one
        // frame after the last. Frames drawn by then over frames called for, times 24, is the rate
        // achieved (a dropped frame is one the clock passed before the previous one was drawn).
        const int rendersBefore = viewport->renderCount();
        int rendersAtStop = -1;
        QElapsedTimer clock;
        const auto stopped = connect(playback, &views::Playback::playingChanged, this, [&](bool playing) {
            if (!playing)
                rendersAtStop = viewport->renderCount();
        });
        clock.start();
        playback->play();
        QTRY_VERIFY_WITH_TIMEOUT(!playback->isPlaying(), 60000);
        disconnect(stopped);
        const double seconds = clock.elapsed() / 1000.0;
        const int calledFor = 47;
        const int drawn = rendersAtStop - rendersBefore;
        const double achieved = 24.0 * drawn / calledFor;
        qInfo("playing frames 1-47 at 24 fps: %d drawn, %d dropped = %.1f fps (%.2f s)", drawn,
            std::max(0, calledFor - drawn), achieved, seconds);
        QVERIFY2(achieved >= 5.0, qPrintable(QString::number(achieved)));
        // What the viewport can draw: every frame of the turntable, one after the other, unpaced.
        clock.restart();
        double paintMs = 0.0, lineMs = 0.0;
        for (int f = 0; f < 48; ++f) {
            doc->setCurrentFrame(f);
            test::waitForRender(viewport);
            paintMs += viewport->lastFrameTimes().frame;
            lineMs += viewport->lastFrameTimes().lines;
        }
        qInfo("mean paint %.1f ms, of which lines %.1f ms, viewport %dx%d", paintMs / 48.0, lineMs / 48.0,
            viewport->width(), viewport->height());
        const double unpaced = 48.0 / (clock.elapsed() / 1000.0);
        qInfo("stepping 48 frames as fast as they draw: %.1f fps (last paint %.1f ms)", unpaced,
            viewport->lastFrameTimes().frame);
        QVERIFY2(unpaced >= 5.0, qPrintable(QString::number(unpaced)));
    }
};

QTEST_MAIN(TestAnimationUi)
#include "test_animation_ui.moc"
