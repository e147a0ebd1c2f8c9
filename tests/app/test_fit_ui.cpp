// Fit to Drawing in the editor, driven through the real window under Xvfb: a drawing of the
// elephant made from a known camera (its silhouette as black ink on white paper), a rough
// alignment by hand, then Fit Camera to Drawing, Fit Shape to Drawing and one brush stroke, each
// one undo step; the Properties panel's live figures follow. Bad drawings (blank paper, all ink,
// a figure cut by the frame) say why by name and change nothing. The outline settings of a
// drawing are undoable edits, a spin box drag one step.
#include "fit_model_sheet.h"
#include "test_support.h"
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/jobs/job_runner.h"
#include "editor/main_window.h"

#include "celform/model/document/document.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/panels/fit_group.h"
#include "celform/views/panels/outline_settings_box.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QImage>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>

#include <Eigen/Geometry>

using namespace celform;
using views::Viewport;

namespace {

constexpr int kDrawingSize = 512;
constexpr int kJobTimeoutMs = 120000;

/// A grey image as a PNG in dir; its path.
QString writePng(const QTemporaryDir& dir, const QString& name, const algo::DrawingImage& image)
{
    QImage out(image.width, image.height, QImage::Format_Grayscale8);
    for (int y = 0; y < image.height; ++y)
        std::memcpy(
            out.scanLine(y), image.pixels.data() + std::size_t(y) * std::size_t(image.width), std::size_t(image.width));
    const QString path = dir.filePath(name + QStringLiteral(".png"));
    return out.save(path) ? path : QString();
}

algo::DrawingImage plain(int size, std::uint8_t grey)
{
    algo::DrawingImage image;
    image.width = image.height = size;
    image.channels = 1;
    image.pixels.assign(std::size_t(size) * std::size_t(size), grey);
    return image;
}

model::Camera documentCamera(const algo::RasterCamera& r)
{
    model::Camera c;
    c.eye = r.eye;
    c.target = r.target;
    c.up = r.up;
    c.fovYDegrees = r.fovYDegrees;
    c.orthoHeight = r.orthoHeight;
    c.projection = r.orthographic ? model::Projection::Orthographic : model::Projection::Perspective;
    return c;
}

/// Shows the window and starts a project on the mesh; false when either fails.
bool showWithMesh(app::MainWindow& window, const QString& meshPath)
{
    window.resize(1400, 900);
    window.show();
    return QTest::qWaitForWindowExposed(&window) && window.openFile(meshPath);
}

/// Triggers a fit action and waits for its job to end (the runner deletes itself).
bool runFit(app::MainWindow& window, const char* action, const char* runner)
{
    QAction* a = window.action(QString::fromLatin1(action));
    if (!a || !a->isEnabled())
        return false;
    a->trigger();
    QElapsedTimer clock;
    clock.start();
    while (window.findChild<app::JobRunner*>(QString::fromLatin1(runner)) && clock.elapsed() < kJobTimeoutMs)
        QTest::qWait(20);
    QTest::qWait(50); // the deferred deletion and the panel's coalesced measurement
    return !window.findChild<app::JobRunner*>(QString::fromLatin1(runner));
}

} // namespace

class TestFitUi : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
    }

    void roughAlignFitCameraFitShapeBrush()
    {
        CELFORM_REQUIRE_SHARED(meshPath, QStringLiteral("meshes/cgal_elephant.off"));
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showWithMesh(window, meshPath));
        model::Document* doc = window.document();
        Viewport* vp = window.viewport();
        views::PropertiesPanel* props = window.propertiesPanel();
        const algo::TriMesh& mesh = *doc->data().baseMesh;

        // The drawing: the elephant, a little pulled (a trunk drawn longer), seen from a known camera.
        const test::ModelSheet sheet
            = test::makeModelSheet(mesh, Eigen::Vector3d(0.45, 0.25, 1.0).normalized(), kDrawingSize, 0.04);
        const QString png = writePng(
            m_dir, QStringLiteral("elephant_sheet"), test::silhouetteDrawing(sheet.pulled, mesh.faces, sheet.camera));
        QVERIFY(window.openFile(png));
        const model::ObjectId drawing = doc->data().drawings.back().id;
        QCOMPARE(window.scenePanel()->selection().id, drawing);

        // 1. Rough alignment by hand: the true camera turned 6° about the vertical.
        const model::Camera truth = documentCamera(sheet.camera);
        model::Camera rough = truth;
        const Eigen::AngleAxisd turn(6.0 * M_PI / 180.0, Eigen::Vector3d::UnitY());
        rough.eye = truth.target + turn * (truth.eye - truth.target);
        rough.fovYDegrees = 32.0;
        props->alignButton()->click();
        QCOMPARE(vp->tool(), Viewport::Tool::Align);
        vp->setCamera(rough);
        vp->setTool(Viewport::Tool::Navigate);
        QVERIFY(doc->data().drawing(drawing)->aligned);
        const model::Camera roughStored = doc->data().drawing(drawing)->camera;
        props->createKeyButton()->click();
        QCOMPARE(int(doc->data().keys.size()), 1);
        const model::ObjectId key = doc->data().keys.front().id;
        QCOMPARE(window.scenePanel()->selection().id, key);
        const auto before = test::fitFigures(window);
        QVERIFY(before && before->valid);
        qInfo("rough alignment: silhouette IoU %.3f, chamfer %.2f px (measured in %.2f ms)", before->iou,
            before->chamferPx, props->fitGroup()->measureMilliseconds());
        QVERIFY(before->iou < 0.95);

        // 2. Fit Camera to Drawing: the drawing's camera and the key's, one step; the view
        // looks through the fitted camera.
        QUndoStack* stack = doc->undoStack();
        const int start = stack->count();
        // Cancel leaves everything as it was.
        const model::ProjectData beforeFit = doc->data();
        window.action(QStringLiteral("actionFitCamera"))->trigger();
        auto* running = window.findChild<app::JobRunner*>(QStringLiteral("fitCameraRunner"));
        QVERIFY(running && running->isRunning());
        QVERIFY(!window.action(QStringLiteral("actionFitCamera"))->isEnabled()); // one fit at a time
        running->cancel();
        QTRY_VERIFY_WITH_TIMEOUT(!window.findChild<app::JobRunner*>(QStringLiteral("fitCameraRunner")), kJobTimeoutMs);
        QCOMPARE(stack->count(), start);
        QVERIFY(doc->data() == beforeFit);
        QTRY_VERIFY(window.action(QStringLiteral("actionFitCamera"))->isEnabled());

        QVERIFY(runFit(window, "actionFitCamera", "fitCameraRunner"));
        QCOMPARE(stack->count(), start + 1);
        QCOMPARE(stack->text(start), QStringLiteral("Fit Camera to Drawing"));
        const model::Camera fitted = doc->data().drawing(drawing)->camera;
        QVERIFY(doc->data().key(key)->camera == fitted);
        QVERIFY((vp->camera().eye - fitted.eye).norm() < 1e-6 * (fitted.eye - fitted.target).norm());
        QCOMPARE(vp->drawingOverlay().drawing(), drawing);
        const auto afterCamera = test::fitFigures(window);
        QVERIFY(afterCamera && afterCamera->iou > before->iou);
        qInfo("after Fit Camera: silhouette IoU %.3f, chamfer %.2f px", afterCamera->iou, afterCamera->chamferPx);

        // 3. Fit Shape to Drawing: the key's deformation at the drawing's frame, one step.
        QVERIFY(runFit(window, "actionFitShape", "fitShapeRunner"));
        QCOMPARE(stack->count(), start + 2);
        QCOMPARE(stack->text(start + 1), QStringLiteral("Fit Shape to Drawing"));
        QVERIFY(!doc->data().key(key)->offsetsByFrame.empty());
        const auto afterShape = test::fitFigures(window);
        QVERIFY(afterShape);
        qInfo("after Fit Shape: silhouette IoU %.3f, chamfer %.2f px (measured in %.2f ms)", afterShape->iou,
            afterShape->chamferPx, props->fitGroup()->measureMilliseconds());
        QVERIFY2(afterShape->iou >= 0.95, qPrintable(QString::number(afterShape->iou)));
        QVERIFY(props->fitGroup()->figuresText().contains(QStringLiteral("IoU")));

        // 4. The brush refines it: one stroke, one step.
        props->editKeyButton()->click();
        QCOMPARE(vp->tool(), Viewport::Tool::Brush);
        test::waitForRender(vp);
        const QPoint c = vp->rect().center();
        QVERIFY2(vp->pickVertex(c) >= 0, "nothing under the viewport centre");
        test::drag(vp, Qt::LeftButton, Qt::NoModifier, c, c + QPoint(6, -4), 4);
        QCOMPARE(stack->count(), start + 3);
        QVERIFY(stack->text(start + 2).startsWith(QStringLiteral("Brush")));

        // The outline the fits aimed at, over the fitted key (a picture to look at).
        window.action(QStringLiteral("actionDrawingOutline"))->trigger();
        QVERIFY(vp->drawingOverlay().outline());
        QVERIFY(vp->drawingOverlay().outlineProblem().isEmpty());
        test::waitForRender(vp);
        test::keepScreenshot(&window, "fit-to-drawing");
        vp->setTool(Viewport::Tool::Navigate);
        window.scenePanel()->select({views::ScenePanel::ItemKind::Drawing, drawing});
        QVERIFY(props->outlineSettings()->isVisible());
        QVERIFY(props->outlineSettings()->statusText().contains(QStringLiteral("Outline found")));
        // The settings are below the drawing's rows: scroll them into the picture.
        for (QWidget* w = props->outlineSettings(); w; w = w->parentWidget())
            if (auto* scroll = qobject_cast<QScrollArea*>(w)) {
                QApplication::processEvents(); // the box's place, now that it shows
                scroll->verticalScrollBar()->setValue(
                    props->outlineSettings()->mapTo(scroll->widget(), QPoint(0, 0)).y() - 150);
                break;
            }
        test::waitForRender(vp);
        test::keepScreenshot(&window, "fit-to-drawing-outline-settings");

        // Undo walks back through the three steps to the rough alignment.
        for (int i = 0; i < 3; ++i)
            window.action(QStringLiteral("actionUndo"))->trigger();
        QVERIFY(doc->data().drawing(drawing)->camera == roughStored);
        QVERIFY(doc->data().key(key)->camera == roughStored);
        QVERIFY(doc->data().keyShape(*doc->data().key(key), 0) == doc->data().baseMesh->vertices);
    }

    void badDrawingsSayWhyAndChangeNothing()
    {
        CELFORM_REQUIRE_SHARED(meshPath, QStringLiteral("meshes/cgal_elephant.off"));
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showWithMesh(window, meshPath));
        model::Document* doc = window.document();
        const algo::TriMesh& mesh = *doc->data().baseMesh;

        // A figure cut by the frame: the elephant seen from too close.
        algo::RasterCamera close = test::sheetCamera(mesh, Eigen::Vector3d(0, 0, 1), 256);
        close.fovYDegrees = 12.0;
        const struct {
            QString name;
            algo::DrawingImage image;
        } cases[] = {{QStringLiteral("blank_paper"), plain(256, 255)}, {QStringLiteral("all_ink"), plain(256, 0)},
            {QStringLiteral("cut_by_the_frame"), test::silhouetteDrawing(mesh.vertices, mesh.faces, close)}};
        for (const auto& bad : cases) {
            QVERIFY(window.openFile(writePng(m_dir, bad.name, bad.image)));
            const model::ObjectId id = doc->data().drawings.back().id;
            QCOMPARE(window.scenePanel()->selection().id, id);
            const model::ProjectData data = doc->data();
            const int count = doc->undoStack()->count();
            window.statusBar()->clearMessage();
            // Fit Camera works on a drawing alone; Fit Shape needs a key linked to it.
            QVERIFY(window.action(QStringLiteral("actionFitCamera"))->isEnabled());
            QVERIFY(!window.action(QStringLiteral("actionFitShape"))->isEnabled());
            QVERIFY(runFit(window, "actionFitCamera", "fitCameraRunner"));
            const QString message = window.statusBar()->currentMessage();
            qInfo("%s: %s", qPrintable(bad.name), qPrintable(message));
            QVERIFY2(message.contains(bad.name), qPrintable(message));
            QCOMPARE(doc->undoStack()->count(), count);
            QVERIFY(doc->data() == data);
            // The Properties panel says the same under the drawing's outline settings.
            QCOMPARE(window.propertiesPanel()->outlineSettings()->statusText(), message);
        }

        // Fit Shape with a key linked to a bad drawing: the same, nothing changes.
        const model::ObjectId blank = doc->data().drawingByName(QStringLiteral("blank_paper"))->id;
        const model::ObjectId key
            = doc->keys().createKey(QStringLiteral("Key"), documentCamera(close), std::vector<model::ObjectId>{blank});
        window.scenePanel()->select({views::ScenePanel::ItemKind::Key, key});
        QVERIFY(window.action(QStringLiteral("actionFitShape"))->isEnabled());
        const int count = doc->undoStack()->count();
        const model::ProjectData data = doc->data();
        QVERIFY(runFit(window, "actionFitShape", "fitShapeRunner"));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("blank_paper")));
        QCOMPARE(doc->undoStack()->count(), count);
        QVERIFY(doc->data() == data);
        QTRY_VERIFY(window.propertiesPanel()->fitGroup()->figuresText().contains(QStringLiteral("blank_paper")));
    }

    void liveFiguresOfAMegapixelDrawing()
    {
        CELFORM_REQUIRE_SHARED(meshPath, QStringLiteral("meshes/cgal_elephant.off"));
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showWithMesh(window, meshPath));
        model::Document* doc = window.document();
        const algo::TriMesh& mesh = *doc->data().baseMesh;
        const algo::RasterCamera camera = test::sheetCamera(mesh, Eigen::Vector3d(0.3, 0.2, 1.0).normalized(), 1024);
        QVERIFY(window.openFile(
            writePng(m_dir, QStringLiteral("large"), test::silhouetteDrawing(mesh.vertices, mesh.faces, camera))));
        const model::ObjectId drawing = doc->data().drawings.back().id;
        const model::ObjectId key = doc->keys().createKey(
            QStringLiteral("Key"), documentCamera(camera), std::vector<model::ObjectId>{drawing});
        window.scenePanel()->select({views::ScenePanel::ItemKind::Key, key});
        const auto first = test::fitFigures(window);
        QVERIFY(first && first->valid);
        QVERIFY2(first->iou > 0.99, qPrintable(QString::number(first->iou)));
        // Again after an edit of the key (the outline is kept, the scratch too): the live cost.
        model::Camera moved = documentCamera(camera);
        moved.fovYDegrees += 1.0;
        double fastest = 1e9;
        for (int i = 0; i < 3; ++i) {
            moved.fovYDegrees += 0.2;
            doc->keys().setKeyCamera(key, moved);
            QVERIFY(test::fitFigures(window));
            fastest = std::min(fastest, window.propertiesPanel()->fitGroup()->measureMilliseconds());
        }
        qInfo("1024 px drawing: the live figures take %.2f ms", fastest);
        QVERIFY2(fastest < 100.0, qPrintable(QString::number(fastest)));
    }

    void outlineSettingsAreUndoableEdits()
    {
        CELFORM_REQUIRE_SHARED(meshPath, QStringLiteral("meshes/cgal_elephant.off"));
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showWithMesh(window, meshPath));
        model::Document* doc = window.document();
        const algo::TriMesh& mesh = *doc->data().baseMesh;
        const algo::RasterCamera camera = test::sheetCamera(mesh, Eigen::Vector3d(0, 0, 1), 256);
        QVERIFY(window.openFile(
            writePng(m_dir, QStringLiteral("front"), test::silhouetteDrawing(mesh.vertices, mesh.faces, camera))));
        const model::ObjectId id = doc->data().drawings.back().id;
        views::OutlineSettingsBox* box = window.propertiesPanel()->outlineSettings();
        QVERIFY(box->isVisible());
        QVERIFY(box->automaticBox()->isChecked());
        QVERIFY(!box->thresholdBox()->isEnabled());
        QVERIFY(box->statusText().contains(QStringLiteral("Outline found")));
        QUndoStack* stack = doc->undoStack();
        const int start = stack->count();

        box->innerLinesBox()->click();
        QCOMPARE(stack->count(), start + 1);
        QVERIFY(doc->data().drawing(id)->outline.innerLines);
        box->automaticBox()->click();
        QCOMPARE(stack->count(), start + 2);
        QVERIFY(doc->data().drawing(id)->outline.threshold >= 0.0);
        QVERIFY(box->thresholdBox()->isEnabled());
        // A held arrow key on the closing radius is one step however many values it passes.
        box->closingBox()->setFocus();
        test::holdKey(box->closingBox(), Qt::Key_Up, 5);
        QCOMPARE(stack->count(), start + 3);
        QVERIFY(doc->data().drawing(id)->outline.closingRadius >= model::DrawingOutline{}.closingRadius + 5.0);
        QVERIFY(stack->text(start + 2).contains(QStringLiteral("Outline")));
        // The viewport's outline mode reads the same settings.
        window.action(QStringLiteral("actionDrawingOutline"))->trigger();
        QVERIFY(window.viewport()->drawingOverlay().outline());
        QVERIFY2(window.viewport()->drawingOverlay().outlineProblem().isEmpty(),
            qPrintable(window.viewport()->drawingOverlay().outlineProblem()));
        for (int i = 0; i < 3; ++i)
            window.action(QStringLiteral("actionUndo"))->trigger();
        QVERIFY(doc->data().drawing(id)->outline == model::DrawingOutline{});
        QVERIFY(box->automaticBox()->isChecked());
    }

private:
    QTemporaryDir m_dir;
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    app.setApplicationName(QStringLiteral("CelformTest"));
    TestFitUi test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_fit_ui.moc"
