// The editor as a user drives it, under Xvfb: opening the sample project, orbiting in the viewport,
// the unsaved-changes marker, undo, deleting from the scene, dropping files, autosave and recovery,
// and the --screenshot option.
#include "test_support.h"
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/jobs/job_runner.h"
#include "editor/main_window.h"
#include "editor/recovery_manager.h"

#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"
#include "celform/views/panels/look_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QApplication>
#include <QMimeData>
#include <QProcess>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeWidget>

using namespace celform;

namespace {

/// Share of pixels that differ clearly from the top-left corner's colour (the background).
double coverage(const QImage& image)
{
    if (image.isNull())
        return 0;
    const QImage img = image.convertToFormat(QImage::Format_RGB32);
    const QRgb bg = img.pixel(2, 2);
    qint64 differing = 0;
    for (int y = 0; y < img.height(); y += 2)
        for (int x = 0; x < img.width(); x += 2) {
            const QRgb p = img.pixel(x, y);
            if (std::abs(qRed(p) - qRed(bg)) + std::abs(qGreen(p) - qGreen(bg)) + std::abs(qBlue(p) - qBlue(bg)) > 60)
                ++differing;
        }
    return double(differing) / (double(img.width() / 2) * double(img.height() / 2));
}

QImage renderNow(views::Viewport* vp)
{
    test::waitForRender(vp);
    return vp->renderedImage();
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY2(QFileInfo::exists(test::sampleProject()), "the bundled sample project is missing");
    }

    void opensSampleAndOrbits()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QVERIFY(window.document()->hasMesh());
        QVERIFY(!window.document()->data().drawings.empty());
        QVERIFY(window.windowTitle().startsWith(QStringLiteral("elephant-plain.celform")));

        auto* vp = window.viewport();
        const QImage first = renderNow(vp);
        QVERIFY2(coverage(first) > 0.05, "the viewport shows no model");

        QSignalSpy cameraSpy(vp, &views::Viewport::cameraChanged);
        const model::Camera before = vp->camera();
        const QPoint c = vp->rect().center();
        test::drag(vp, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(150, 40));
        QVERIFY(cameraSpy.count() > 0);
        const model::Camera after = vp->camera();
        QVERIFY((after.eye - before.eye).norm() > 1e-3);
        // Orbit keeps the distance to the pivot.
        QVERIFY(std::abs((after.eye - vp->pivot()).norm() - (before.eye - vp->pivot()).norm())
            < 1e-6 * (1 + (before.eye - vp->pivot()).norm()));
        const QImage orbited = renderNow(vp);
        QVERIFY2(coverage(orbited) > 0.05, "the viewport went blank after orbiting");
        QVERIFY(orbited != first);

        // Plain middle-button drag orbits too.
        test::drag(vp, Qt::MiddleButton, Qt::NoModifier, c, c + QPoint(-80, 0));
        QVERIFY((vp->camera().eye - after.eye).norm() > 1e-3);
        QVERIFY(coverage(renderNow(vp)) > 0.05);
    }

    // The first launch (no saved geometry) fits the screen, whatever its size: ctest also runs this
    // under 1366x768, 1600x900 and 1920x1080 screens (tests/app/CMakeLists.txt).
    void firstWindowFitsTheScreen()
    {
        {
            QSettings settings;
            settings.remove(QStringLiteral("window/geometry"));
            settings.remove(QStringLiteral("window/state"));
        }
        app::MainWindow window(app::MainWindow::Mode::Interactive);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QApplication::processEvents();
        const QRect available = window.screen()->availableGeometry();
        const QString sizes = QStringLiteral("window %1x%2 at %3,%4 (frame %5x%6), screen %7x%8")
                                  .arg(window.width())
                                  .arg(window.height())
                                  .arg(window.x())
                                  .arg(window.y())
                                  .arg(window.frameGeometry().width())
                                  .arg(window.frameGeometry().height())
                                  .arg(available.width())
                                  .arg(available.height());
        QVERIFY2(available.contains(window.frameGeometry()), qPrintable(sizes));
        // What fell off a 1366x768 screen: the status bar and the bottom of the window.
        const QRect statusBar(window.statusBar()->mapToGlobal(QPoint(0, 0)), window.statusBar()->size());
        QVERIFY2(available.contains(statusBar), qPrintable(sizes));
    }

    void titleMarksUnsavedChangesAndUndo()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        window.show();
        QVERIFY(window.openFile(test::sampleProject()));
        QVERIFY(!window.isWindowModified());
        const auto id = window.document()->data().drawings.front().id;
        window.document()->drawings().renameDrawing(id, QStringLiteral("side view"));
        QVERIFY(window.isWindowModified());
        window.action(QStringLiteral("actionUndo"))->trigger();
        QVERIFY(!window.isWindowModified());
        QCOMPARE(window.document()->data().drawings.front().name, QStringLiteral("tuxpaint_elephant"));
    }

    void deleteInSceneRemovesDrawing()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(test::sampleProject()));
        const std::size_t count = window.document()->data().drawings.size();
        const auto id = window.document()->data().drawings.front().id;
        window.scenePanel()->select({views::ScenePanel::ItemKind::Drawing, id});
        QAction* del = window.action(QStringLiteral("actionDelete"));
        QVERIFY(del);
        QCOMPARE(del->shortcut(), QKeySequence(QKeySequence::Delete));
        // Triggered directly: key shortcuts need an active window, which a shared Xvfb without a
        // window manager does not guarantee while other UI tests run.
        del->trigger();
        QCOMPARE(window.document()->data().drawings.size(), count - 1);
        QVERIFY(!window.document()->data().drawing(id));
        window.action(QStringLiteral("actionUndo"))->trigger();
        QCOMPARE(window.document()->data().drawings.size(), count);
        QVERIFY(window.document()->data().drawing(id));
    }

    void dropMeshAndImage()
    {
        CELFORM_REQUIRE_SHARED(mesh, QStringLiteral("meshes/npm_bunny.off"));
        CELFORM_REQUIRE_SHARED(image, QStringLiteral("drawings/openclipart_cartoon_cat_gerald_g._01.svg"));
        app::MainWindow window(app::MainWindow::Mode::Batch);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        for (const QString& path : {mesh, image}) {
            QMimeData mime;
            mime.setUrls({QUrl::fromLocalFile(path)});
            QDragEnterEvent enter(QPoint(300, 300), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(&window, &enter);
            QVERIFY(enter.isAccepted());
            QDropEvent drop(QPointF(300, 300), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(&window, &drop);
        }
        QTRY_VERIFY(window.document()->hasMesh());
        QTRY_COMPARE(window.document()->data().drawings.size(), std::size_t(1));
        QCOMPARE(window.document()->data().baseMesh->vertexCount(), Eigen::Index(1839));
    }

    // Properties > Import Deformation reads the mesh as a job of the window's JobRunner, as every
    // import, then makes it the key's deformation in one undo step.
    void keyDeformationImportIsAJob()
    {
        QTemporaryDir dir;
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(window.openFile(test::sampleProject()));
        model::Document& doc = *window.document();
        const model::ObjectId id = doc.keys().createKey(QStringLiteral("imported"), window.viewport()->camera());
        algo::TriMesh shape = *doc.data().baseMesh;
        shape.vertices = doc.data().keyShape(*doc.data().key(id), 0);
        shape.vertices(0, 1) += 0.25f;
        const QString path = dir.filePath(QStringLiteral("deformed.obj"));
        model::exportMesh(shape, path);
        bool ranAsJob = false;
        QTimer::singleShot(0, &window, [&] { ranAsJob = window.findChild<app::JobRunner*>() != nullptr; });
        const int steps = doc.undoStack()->count();
        QVERIFY(window.importKeyDeformation(id, path));
        QVERIFY(ranAsJob);
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        QVERIFY((doc.data().keyShape(*doc.data().key(id), 0).row(0) - shape.vertices.row(0)).norm() < 1e-4f);
        // A mesh with other vertices is refused: an error, nothing changed.
        const model::ProjectData before = doc.data();
        algo::TriMesh small;
        small.vertices = shape.vertices.topRows(3);
        small.faces.resize(1, 3);
        small.faces << 0, 1, 2;
        const QString bad = dir.filePath(QStringLiteral("small.obj"));
        model::exportMesh(small, bad);
        QVERIFY(!window.importKeyDeformation(id, bad));
        QVERIFY(doc.data() == before);
    }

    // Issue 26, fixes 2 and 3: Import Deformation imports at the playhead's frame, into a new
    // keyed frame of the key or replacing the one stored there, one undo step each.
    void keyDeformationImportsAtThePlayhead()
    {
        QTemporaryDir dir;
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(window.openFile(test::sampleProject()));
        model::Document& doc = *window.document();
        const model::ObjectId id = doc.keys().createKey(QStringLiteral("imported"), window.viewport()->camera());
        doc.setCurrentFrame(12);
        algo::TriMesh shape = *doc.data().baseMesh;
        shape.vertices = doc.data().keyShape(*doc.data().key(id), 12);
        shape.vertices(0, 1) += 0.25f;
        const QString path = dir.filePath(QStringLiteral("deformed.obj"));
        model::exportMesh(shape, path);
        const int steps = doc.undoStack()->count();
        QVERIFY(window.importKeyDeformation(id, path));
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        QCOMPARE(doc.data().key(id)->offsetsByFrame.count(12), std::size_t(1));
        QVERIFY((doc.data().keyShape(*doc.data().key(id), 12).row(0) - shape.vertices.row(0)).norm() < 1e-4f);
        // Frame 0 keeps the key's copy of the base.
        QVERIFY(
            (doc.data().keyShape(*doc.data().key(id), 0).row(0) - doc.data().baseMesh->vertices.row(0)).norm() < 1e-6f);
        // Again at the same frame: the stored deformation is replaced, one more step.
        shape.vertices(0, 1) -= 0.5f;
        model::exportMesh(shape, path);
        QVERIFY(window.importKeyDeformation(id, path));
        QCOMPARE(doc.undoStack()->count(), steps + 2);
        QVERIFY((doc.data().keyShape(*doc.data().key(id), 12).row(0) - shape.vertices.row(0)).norm() < 1e-4f);
    }

    void badFileLeavesDocumentAlone()
    {
        QTemporaryDir dir;
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(window.openFile(test::sampleProject()));
        const model::ProjectData before = window.document()->data();
        const QString bad = dir.filePath(QStringLiteral("bad.celform"));
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("garbage");
        f.close();
        QVERIFY(!window.openFile(bad));
        QVERIFY(window.document()->data() == before);
    }

    // A crash inside Assimp (a glTF nested 30,000 nodes deep overflows its stack) took the
    // editor and its unsaved edits along. Assimp runs in a child process now: the import fails.
    void crashingImporterLeavesDocumentAlone()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(window.openFile(test::sampleProject()));
        window.document()->drawings().renameDrawing(
            window.document()->data().drawings.front().id, QStringLiteral("unsaved"));
        const model::ProjectData before = window.document()->data();
        QVERIFY(!window.openFile(
            test::testDataPath(QStringLiteral("fuzz-regressions/mesh/gltf-30000-nested-nodes-stack-overflow.gltf"))));
        QVERIFY(window.document()->data() == before);
        QVERIFY(window.document()->isModified());
    }

    void autosaveAndRecovery()
    {
        QTemporaryDir dir;
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(window.openFile(test::sampleProject()));
        auto* recovery = window.recovery();
        window.document()->drawings().renameDrawing(
            window.document()->data().drawings.front().id, QStringLiteral("edited"));
        QVERIFY(recovery->autosaveNow());
        QVERIFY(QFileInfo::exists(recovery->ownRecoveryFile()));
        QCOMPARE(model::loadProject(recovery->ownRecoveryFile()).drawings.front().name, QStringLiteral("edited"));
        // The autosave is a copy: the document still points at its own file and is still unsaved.
        QVERIFY(window.document()->isModified());
        QVERIFY(window.document()->filePath().endsWith(QStringLiteral("elephant-plain.celform")));

        // A session that crashed left a recovery file and a lock whose process is gone.
        const QString orphanBase
            = QFileInfo(recovery->ownRecoveryFile()).absolutePath() + QStringLiteral("/session-999999-1");
        QVERIFY(QFile::copy(recovery->ownRecoveryFile(), orphanBase + QStringLiteral(".celform")));
        QFile lock(orphanBase + QStringLiteral(".lock"));
        QVERIFY(lock.open(QIODevice::WriteOnly));
        lock.write(QByteArray("999999\n") + QCoreApplication::applicationName().toUtf8() + "\n"
            + QSysInfo::machineHostName().toUtf8() + "\n");
        lock.close();
        const auto orphans = recovery->orphans();
        QCOMPARE(orphans.size(), std::size_t(1));
        QCOMPARE(orphans.front().recoveryFile, orphanBase + QStringLiteral(".celform"));
        // Our own live session is never offered.
        for (const auto& o : orphans)
            QVERIFY(o.recoveryFile != recovery->ownRecoveryFile());
        app::RecoveryManager::discard(orphans.front());
        QVERIFY(recovery->orphans().empty());

        // Saving makes the recovery copy unnecessary.
        const QString saved = dir.filePath(QStringLiteral("saved.celform"));
        QVERIFY(window.saveAs(saved));
        QVERIFY(!QFileInfo::exists(recovery->ownRecoveryFile()));
        QVERIFY(!window.isWindowModified());
    }

    void lookPanelEditsAreUndoable()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        auto* dock = window.findChild<QDockWidget*>(QStringLiteral("lookDock"));
        QVERIFY(dock);
        dock->raise();
        auto* panel = window.findChild<views::LookPanel*>();
        QVERIFY(panel);
        QComboBox* style = panel->styleBox();
        const int gooch = style->findData(int(model::ShadingStyle::Gooch));
        style->setCurrentIndex(gooch);
        emit style->activated(gooch);
        QCOMPARE(window.document()->data().look.style, model::ShadingStyle::Gooch);
        test::waitForRender(window.viewport());
        test::keepScreenshot(&window, "look-panel");
        window.action(QStringLiteral("actionUndo"))->trigger();
        QCOMPARE(window.document()->data().look.style, model::ShadingStyle::Toon);
        QCOMPARE(style->currentData().toInt(), int(model::ShadingStyle::Toon)); // the panel follows undo
    }

    void renderCameraFromTheView()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1000, 700)));
        views::Viewport* vp = window.viewport();
        QVERIFY(!window.document()->data().look.renderCamera);
        window.action(QStringLiteral("actionSetRenderCamera"))->trigger();
        const model::Camera shot = vp->camera();
        QVERIFY(window.document()->data().look.renderCamera == shot);
        // Somewhere else, then back through the render camera.
        model::Camera elsewhere = shot;
        elsewhere.eye = shot.target + (shot.eye - shot.target).norm() * Eigen::Vector3d(1, 0, 0);
        vp->setCamera(elsewhere);
        window.action(QStringLiteral("actionViewRenderCamera"))->trigger();
        QVERIFY((vp->camera().eye - shot.eye).norm() < 1e-9 && (vp->camera().target - shot.target).norm() < 1e-9);
        window.action(QStringLiteral("actionUndo"))->trigger();
        QVERIFY(!window.document()->data().look.renderCamera);
    }

    void screenshotOption()
    {
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("shot.png"));
        QProcess p;
        p.start(QStringLiteral(CELFORM_EXECUTABLE), {test::sampleProject(), QStringLiteral("--screenshot"), png});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QImage shot(png);
        QVERIFY(!shot.isNull());
        QVERIFY(shot.width() >= 800);
        QVERIFY(coverage(shot) > 0.05);
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    app.setApplicationName(QStringLiteral("CelformTest"));
    TestMainWindow test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_main_window.moc"
