// The artist's day, second pass: the cameras a tool or a render works in, driven through the real
// window under Xvfb with the bundled sample. Every case failed on the editor before its fix.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/dialogs/render_dialog.h"
#include "editor/jobs/job_runner.h"
#include "editor/main_window.h"
#include "editor/review_window.h"

#include "celform/model/document/document.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>

using namespace celform;
using views::Viewport;
using Selection = views::ScenePanel::Selection;
using ItemKind = views::ScenePanel::ItemKind;

namespace {

/// Whether two cameras look the same way from the same place (to a millionth).
bool sameView(const model::Camera& a, const model::Camera& b)
{
    return (a.eye - b.eye).norm() < 1e-6 && (a.target - b.target).norm() < 1e-6 && (a.up - b.up).norm() < 1e-6;
}

/// The window with the sample, active so that typed keys reach its shortcuts.
bool openActive(app::MainWindow& window)
{
    if (!test::showSample(window, QSize(1400, 900)))
        return false;
    window.activateWindow();
    QApplication::setActiveWindow(&window);
    QApplication::processEvents();
    return QApplication::activeWindow() == &window;
}

/// A key seen from the right of the framed view, selected in the Scene dock.
model::ObjectId addSideKey(app::MainWindow& window)
{
    model::Camera camera = window.viewport()->camera();
    const Eigen::AngleAxisd turn(0.6, Eigen::Vector3d::UnitY());
    camera.eye = camera.target + turn * (camera.eye - camera.target);
    const model::ObjectId key = window.document()->keys().createKey(QStringLiteral("Side"), camera);
    window.scenePanel()->select(Selection{ItemKind::Key, key});
    return key;
}

/// Selects the side drawing and starts aligning it; its id, or 0 when the mode did not start.
model::ObjectId startAligning(app::MainWindow& window)
{
    const model::Drawing* drawing = window.document()->data().drawingByName(QStringLiteral("tuxpaint_elephant"));
    if (!drawing)
        return 0;
    const model::ObjectId id = drawing->id;
    window.scenePanel()->select(Selection{ItemKind::Drawing, id});
    window.propertiesPanel()->alignButton()->click();
    return window.viewport()->tool() == Viewport::Tool::Align ? id : 0;
}

/// Moves the pointer over the viewport at a widget point, no button held.
void hoverAt(Viewport* viewport, QPoint at)
{
    QTest::mouseMove(viewport, at);
    QMouseEvent hover(QEvent::MouseMove, at, viewport->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(viewport, &hover);
}

/// Sets a sequence dialog to frames 0 and 1 into output (a #### pattern) at size.
void setTwoFrames(app::RenderDialog* dialog, const QString& output, QSize size, bool openWhenDone)
{
    dialog->findChild<QLineEdit*>(QStringLiteral("renderOutput"))->setText(output);
    dialog->findChild<QSpinBox*>(QStringLiteral("renderWidth"))->setValue(size.width());
    dialog->findChild<QSpinBox*>(QStringLiteral("renderHeight"))->setValue(size.height());
    dialog->findChild<QSpinBox*>(QStringLiteral("renderFirstFrame"))->setValue(0);
    dialog->findChild<QSpinBox*>(QStringLiteral("renderLastFrame"))->setValue(1);
    dialog->findChild<QCheckBox*>(QStringLiteral("renderOpenWhenDone"))->setChecked(openWhenDone);
}

/// Runs the render the dialog describes and waits for its end.
bool renderAndWait(app::MainWindow& window, app::RenderDialog* dialog)
{
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
    auto* runner = window.findChild<app::JobRunner*>();
    if (!runner)
        return false;
    QSignalSpy finished(runner, &app::JobRunner::finished);
    return finished.wait(120000) && finished.at(0).at(0).toBool();
}

} // namespace

class TestArtistCameras : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Item 1: with a camera path, Render Sequence and Render Image offer the shot camera first,
    // and a sequence follows the path frame by frame as `celform render` does.
    void renderFollowsTheShotCamera()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        model::Document* doc = window.document();
        // The remembered choice was the current view: the shot camera wins once there is a path.
        QSettings().setValue(QStringLiteral("render/camera"), QStringLiteral("view"));
        model::Turntable turntable;
        turntable.frames = 4; // a quarter turn a frame
        doc->animation().makeTurntable(turntable, 4.0 / 3.0);
        QVERIFY(!doc->data().look.cameraPath.empty());

        window.action(QStringLiteral("actionRenderImage"))->trigger();
        auto* still = window.findChild<app::RenderDialog*>(QStringLiteral("renderImageDialog"));
        QVERIFY(still);
        auto* stillCamera = still->findChild<QComboBox*>(QStringLiteral("renderCamera"));
        QCOMPARE(stillCamera->currentData().toString(), QStringLiteral("shot"));
        QVERIFY(!still->job().camera && !still->job().view); // the path at the frame
        still->reject();
        delete still;

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString project = dir.filePath(QStringLiteral("turntable.celform"));
        doc->saveAs(project);
        window.action(QStringLiteral("actionRenderSequence"))->trigger();
        auto* dialog = window.findChild<app::RenderDialog*>(QStringLiteral("renderSequenceDialog"));
        QVERIFY(dialog);
        auto* camera = dialog->findChild<QComboBox*>(QStringLiteral("renderCamera"));
        QCOMPARE(camera->itemData(0).toString(), QStringLiteral("shot"));
        QCOMPARE(camera->currentData().toString(), QStringLiteral("shot"));
        setTwoFrames(dialog, dir.filePath(QStringLiteral("gui_####.png")), QSize(160, 120), false);
        QVERIFY2(dialog->problem().isEmpty(), qPrintable(dialog->problem()));
        QVERIFY(renderAndWait(window, dialog));

        QProcess cli;
        cli.start(QStringLiteral(CELFORM_EXECUTABLE),
            {QStringLiteral("render"), project, QStringLiteral("--frames"), QStringLiteral("0-1"),
                QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--out"),
                dir.filePath(QStringLiteral("cli_####.png"))});
        QVERIFY(cli.waitForFinished(120000));
        QCOMPARE(cli.exitCode(), 0);
        QImage gui[2], fromCli[2];
        for (int f = 0; f < 2; ++f) {
            const QString number = QStringLiteral("%1.png").arg(f, 4, 10, QLatin1Char('0'));
            gui[f] = QImage(dir.filePath(QStringLiteral("gui_") + number)).convertToFormat(QImage::Format_RGBA8888);
            fromCli[f] = QImage(dir.filePath(QStringLiteral("cli_") + number)).convertToFormat(QImage::Format_RGBA8888);
            QVERIFY(!gui[f].isNull() && !fromCli[f].isNull());
            QCOMPARE(gui[f], fromCli[f]);
        }
        QVERIFY2(gui[0] != gui[1], "both frames show the same angle");
    }

    // Item 14: "Open the folder when done" without a file manager says where the frames are.
    void openWhenDoneWithoutAFileManagerShowsThePath()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1200, 800)));
        QTemporaryDir dir, emptyPath;
        QVERIFY(dir.isValid() && emptyPath.isValid());
        // No program to open a folder with, whatever the machine has installed.
        const QByteArray path = qgetenv("PATH");
        qputenv("PATH", QFile::encodeName(emptyPath.path()));
        window.action(QStringLiteral("actionRenderSequence"))->trigger();
        auto* dialog = window.findChild<app::RenderDialog*>(QStringLiteral("renderSequenceDialog"));
        QVERIFY(dialog);
        setTwoFrames(dialog, dir.filePath(QStringLiteral("f_####.png")), QSize(64, 48), true);
        const bool rendered = renderAndWait(window, dialog);
        qputenv("PATH", path);
        QVERIFY(rendered);
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("renderNotOpenedBox"));
        QVERIFY2(box, "the failed open was silent");
        QTRY_VERIFY(box->isVisible());
        QCOMPARE(box->informativeText(), QDir::toNativeSeparators(dir.path()));
        box->accept();
    }

    // Item 3: an undo of an alignment step moves the view at once, the mode still on.
    void undoWhileAligningMovesTheView()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(openActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        const model::ObjectId id = startAligning(window);
        QVERIFY(id);

        const QPoint c = viewport->rect().center();
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(30, 5));
        const model::Camera afterOrbit = doc->data().drawing(id)->camera;
        QVERIFY(doc->data().drawing(id)->aligned);
        // Scroll and pan: one more step.
        for (int i = 0; i < 3; ++i) {
            QWheelEvent wheel(c, viewport->mapToGlobal(c), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                Qt::NoScrollPhase, false);
            QApplication::sendEvent(viewport, &wheel);
            QApplication::processEvents();
        }
        QTest::qWait(600); // the pause that ends the burst
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier | Qt::ShiftModifier, c, c + QPoint(25, -15));
        QVERIFY(!sameView(viewport->camera(), afterOrbit));
        const int steps = doc->undoStack()->index();

        QTest::keyClick(viewport, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(doc->undoStack()->index(), steps - 1);
        QTest::keyClick(viewport, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(doc->undoStack()->index(), steps - 2);
        QCOMPARE(viewport->tool(), Viewport::Tool::Align);
        QVERIFY(sameView(doc->data().drawing(id)->camera, afterOrbit));
        QVERIFY2(sameView(viewport->camera(), afterOrbit), "the view kept the undone camera");
        QCOMPARE(doc->undoStack()->index(), steps - 2); // following the undo stored nothing
        // Redo moves it back as well.
        QTest::keyClick(viewport, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(sameView(viewport->camera(), doc->data().drawing(id)->camera));
        QVERIFY(!sameView(viewport->camera(), afterOrbit));
    }

    // Item 4: while brushing, F, [ and ] and Esc are the brush's wherever the focus is, and Frame
    // All moves neither the key's view nor, while aligning, the drawing's camera.
    void toolKeysWinWhereverTheFocusIs()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(openActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        const model::ObjectId key = addSideKey(window);
        window.propertiesPanel()->editKeyButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Brush);
        const model::Camera keyCamera = doc->data().key(key)->camera;
        QVERIFY(sameView(viewport->camera(), keyCamera));
        test::waitForRender(viewport);
        hoverAt(viewport, viewport->projectToWidget(viewport->modelCentre()).toPoint());
        auto& brush = viewport->tool<views::BrushTool>();
        QTRY_VERIFY(brush.cursorCircle()->isVisible()); // the brush knows its size on screen there

        QTreeWidget* tree = window.scenePanel()->tree();
        tree->setFocus();
        QTRY_VERIFY(tree->hasFocus());
        QTest::keyClick(tree, Qt::Key_F);
        QVERIFY2(brush.isResizing(), qPrintable(window.statusBar()->currentMessage()));
        QVERIFY(sameView(viewport->camera(), keyCamera));
        QTest::keyClick(tree, Qt::Key_Escape); // cancels the resize, the brush stays on
        QVERIFY(!brush.isResizing());
        QCOMPARE(viewport->tool(), Viewport::Tool::Brush);
        const double radius = brush.size().current();
        QTest::keyClick(tree, Qt::Key_BracketRight);
        QVERIFY2(brush.size().current() > 1.1 * radius, "] did not reach the brush");

        // View > Frame All, from the menu or anywhere: the view stays the key's.
        window.action(QStringLiteral("actionFrameAll"))->trigger();
        QVERIFY(sameView(viewport->camera(), keyCamera));
        QVERIFY(sameView(doc->data().key(key)->camera, keyCamera));
        // Nor do the preset views: Home, the numpad and View > Top, wherever the focus is.
        QTest::keyClick(tree, Qt::Key_Home);
        QTest::keyClick(tree, Qt::Key_7, Qt::KeypadModifier);
        QTest::keyClick(viewport, Qt::Key_Home);
        window.action(QStringLiteral("actionViewTop"))->trigger();
        QVERIFY(sameView(viewport->camera(), keyCamera));
        QVERIFY(sameView(doc->data().key(key)->camera, keyCamera));
        QVERIFY2(window.statusBar()->currentMessage().contains(QStringLiteral("leave the tool")),
            qPrintable(window.statusBar()->currentMessage()));
        QTest::keyClick(viewport, Qt::Key_Escape);
        QCOMPARE(viewport->tool(), Viewport::Tool::Navigate);

        // Aligning: Frame All stores nothing and keeps the drawing's view.
        const model::ObjectId id = startAligning(window);
        QVERIFY(id);
        const model::Camera aligned = viewport->camera();
        const model::Drawing before = *doc->data().drawing(id);
        const int steps = doc->undoStack()->index();
        window.action(QStringLiteral("actionFrameAll"))->trigger();
        tree->setFocus();
        QTest::keyClick(tree, Qt::Key_F);
        QVERIFY(sameView(viewport->camera(), aligned));
        QCOMPARE(doc->undoStack()->index(), steps);
        QVERIFY(*doc->data().drawing(id) == before);
    }

    // Item 13: in the review, the arrow to a key's camera shows the key's shape, not the base.
    void reviewShowsTheKeyAtItsCamera()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(openActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        addSideKey(window);
        window.propertiesPanel()->editKeyButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Brush);
        test::waitForRender(viewport);
        const QPoint c = viewport->projectToWidget(viewport->modelCentre()).toPoint();
        test::drag(viewport, Qt::LeftButton, Qt::NoModifier, c, c + QPoint(40, -30));
        const algo::Positions keyShape = viewport->displayedShape();
        QVERIFY((keyShape - doc->data().baseMesh->vertices).cwiseAbs().maxCoeff() > 1e-3);
        window.propertiesPanel()->editKeyButton()->click(); // back to the base model
        QCOMPARE(viewport->displayedKey(), model::ObjectId(0));
        QVERIFY(!viewport->isPreview());

        window.action(QStringLiteral("actionStereoReview"))->trigger();
        auto* review = window.findChild<app::ReviewWindow*>();
        QVERIFY(review);
        Viewport* shown = review->viewport();
        QTest::keyClick(shown, Qt::Key_Right);
        QCOMPARE(review->keyIndex(), 0);
        QVERIFY(shown->isPreview());
        const algo::Positions reviewed = shown->displayedShape();
        QCOMPARE(reviewed.rows(), keyShape.rows());
        QVERIFY2((reviewed - keyShape).cwiseAbs().maxCoeff() < 1e-4, "the review shows the base at the key");
        // P still turns the preview off, and the arrows then keep it off.
        QTest::keyClick(shown, Qt::Key_P);
        QVERIFY(!shown->isPreview());
        QTest::keyClick(shown, Qt::Key_Left);
        QVERIFY(!shown->isPreview());
        review->close();
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestArtistCameras test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_artist_cameras.moc"
