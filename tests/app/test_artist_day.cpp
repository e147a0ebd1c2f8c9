// The artist's day in the editor: each trap a new user fell into, driven through the
// real window under Xvfb with the bundled sample. Every case failed on the editor before the fix.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"
#include "editor/review_window.h"

#include "celform/model/document/document.h"
#include "celform/views/viewport/axis_gizmo.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/overlays/drawing_overlay.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/viewport/viewport_display.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTreeWidget>
#include <QUndoStack>

using namespace celform;
using test::clickSceneItem;
using views::Viewport;

namespace {

/// The sample in an active window: key presses reach the window's shortcuts as typed ones do.
bool showActive(app::MainWindow& window, const QSize& size = QSize(1400, 900))
{
    if (!test::showSample(window, size))
        return false;
    // Xvfb has no window manager to activate it: do what one would (window shortcuts need it).
    window.activateWindow();
    QApplication::setActiveWindow(&window);
    QApplication::processEvents();
    return QApplication::activeWindow() == &window;
}

model::ObjectId drawingId(const app::MainWindow& window, const char* name)
{
    const model::Drawing* d = window.document()->data().drawingByName(QString::fromLatin1(name));
    return d ? d->id : 0;
}

/// Aligns the selected drawing by an orbit drag in Align mode and ends the mode (Esc).
void alignByDrag(app::MainWindow& window)
{
    Viewport* viewport = window.viewport();
    window.propertiesPanel()->alignButton()->click();
    QCOMPARE(viewport->tool(), Viewport::Tool::Align);
    const QPoint c = viewport->rect().center();
    test::drag(viewport, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(30, 5));
    QTest::keyClick(viewport, Qt::Key_Escape);
    QCOMPARE(viewport->tool(), Viewport::Tool::Navigate);
}

/// A key from the side drawing: selected, aligned by a drag, Create Key from Drawing.
void makeKey(app::MainWindow& window)
{
    QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
    alignByDrag(window);
    if (QTest::currentTestFailed())
        return;
    QVERIFY(window.propertiesPanel()->createKeyButton()->isEnabled());
    window.propertiesPanel()->createKeyButton()->click();
    QCOMPARE(int(window.document()->data().keys.size()), 1);
}

} // namespace

class TestArtistDay : public QObject {
    Q_OBJECT

private slots:
    // Bug 1: selecting another drawing while aligning changed nothing but marked it aligned.
    void selectingAnotherDrawingWhileAligningChangesNothing()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        const model::ObjectId tux = drawingId(window, "tuxpaint_elephant");
        const model::ObjectId contour = drawingId(window, "openclipart_contour_elephant");
        QVERIFY(tux && contour);
        const model::Drawing contourBefore = *doc->data().drawing(contour);

        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        QCOMPARE(viewport->drawingOverlay().drawing(), tux);
        window.propertiesPanel()->alignButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Align);
        auto* banner = viewport->findChild<QLabel*>(QStringLiteral("alignBanner"));
        QVERIFY(banner && banner->isVisible());
        QVERIFY(banner->text().contains(QStringLiteral("tuxpaint_elephant")));
        QVERIFY(banner->text().contains(QStringLiteral("Esc")));
        const int steps = doc->undoStack()->index();

        QVERIFY(clickSceneItem(window, QStringLiteral("openclipart_contour_elephant")));
        QCOMPARE(viewport->drawingOverlay().drawing(), contour);
        test::waitForRender(viewport);
        QCOMPARE(doc->undoStack()->index(), steps); // no "Align Drawing" step
        QVERIFY(*doc->data().drawing(contour) == contourBefore);
        QCOMPARE(viewport->tool(), Viewport::Tool::Navigate); // the mode ended with its drawing
        QVERIFY(!banner->isVisible());
        QCOMPARE(window.propertiesPanel()->createKeyButton()->isEnabled(), contourBefore.aligned);

        // Esc ends the mode, the status of which was shown in the banner.
        window.propertiesPanel()->alignButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Align);
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_Escape);
        QCOMPARE(viewport->tool(), Viewport::Tool::Navigate);
        QVERIFY(!banner->isVisible());
        QCOMPARE(doc->undoStack()->index(), steps); // aligning without moving stores nothing
    }

    // Bug 8: a run of wheel ticks while aligning is one step, as a drag is.
    void wheelBurstWhileAligningIsOneStep()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        window.propertiesPanel()->alignButton()->click();
        const int steps = doc->undoStack()->index();
        const QPoint c = viewport->rect().center();
        for (int i = 0; i < 5; ++i) {
            QWheelEvent wheel(c, viewport->mapToGlobal(c), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                Qt::NoScrollPhase, false);
            QApplication::sendEvent(viewport, &wheel);
            QApplication::processEvents(); // ticks well inside the 400 ms pause, even on a busy machine
        }
        QTest::qWait(600); // the pause that ends the burst
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        QVERIFY(doc->data().drawingByName(QStringLiteral("tuxpaint_elephant"))->aligned);
        // A drag is a second step.
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(20, 0));
        QCOMPARE(doc->undoStack()->index(), steps + 2);
    }

    // Bug 2: after Create Key from Drawing, 5 toggles the projection and Ctrl+Z undoes, whatever
    // the focus.
    void viewportShortcutsWorkAfterCreatingAKey()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        alignByDrag(window);
        if (QTest::currentTestFailed())
            return;
        QPushButton* createKey = window.propertiesPanel()->createKeyButton();
        QVERIFY(createKey->isEnabled());
        const double sharpness = doc->data().blend.sharpness;
        QTest::mouseClick(createKey, Qt::LeftButton);
        QCOMPARE(int(doc->data().keys.size()), 1);

        QWidget* focus = QApplication::focusWidget();
        QVERIFY2(!qobject_cast<QAbstractSpinBox*>(focus),
            qPrintable(QStringLiteral("focus on %1").arg(focus ? focus->objectName() : QStringLiteral("nothing"))));
        const model::Projection projection = viewport->projection();
        QTest::keyClick(focus ? focus : viewport, Qt::Key_5);
        QVERIFY(viewport->projection() != projection);
        QCOMPARE(doc->data().blend.sharpness, sharpness);

        // Ctrl+Z from a spin box that has focus undoes the document, not the box's text.
        QAbstractSpinBox* spin = nullptr;
        for (auto* s : window.propertiesPanel()->findChildren<QAbstractSpinBox*>())
            if (s->isVisible())
                spin = s;
        QVERIFY(spin);
        spin->setFocus();
        QTRY_VERIFY(spin->hasFocus());
        const int steps = doc->undoStack()->index();
        QTest::keyClick(spin, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(doc->undoStack()->index(), steps - 1);
        QVERIFY(doc->data().keys.empty());
        QTest::keyClick(spin, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(doc->undoStack()->index(), steps);
        QCOMPARE(int(doc->data().keys.size()), 1);
    }

    // Bug 3: every shortcut of the README's table is the shortcut of its action (Save As has one).
    void readmeShortcutTableMatchesTheActions()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QFile readme(QStringLiteral(CELFORM_SOURCE_DIR "/README.md"));
        QVERIFY(readme.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString text = QString::fromUtf8(readme.readAll());
        const int start = text.indexOf(QStringLiteral("| action | mouse / key |"));
        QVERIFY(start >= 0);
        // Rows whose keys are window actions: row label -> the action of each " / " part.
        const QHash<QString, QStringList> actions{
            {QStringLiteral("frame all / front view"), {"actionFrameAll", "actionViewFront"}},
            {QStringLiteral("axis views with the mouse"), {}},
            {QStringLiteral("back / right / left / top / bottom view"),
                {"actionViewBack", "actionViewRight", "actionViewLeft", "actionViewTop", "actionViewBottom"}},
            {QStringLiteral("perspective ↔ orthographic"), {"actionOrthographic"}},
            {QStringLiteral("undo / redo"), {"actionUndo", "actionRedo"}},
            {QStringLiteral("new from mesh / open / save / save as"),
                {"actionNewFromMesh", "actionOpen", "actionSave", "actionSaveAs"}},
            {QStringLiteral("import mesh / import drawing"), {"actionImportMesh", "actionImportDrawing"}},
            {QStringLiteral("preview the view-dependent shape"), {"actionPreview"}},
            {QStringLiteral("new key from the current view"), {"actionCreateKeyFromView"}},
            {QStringLiteral("fit the camera / the key's shape to the drawing (Edit ▸ Fit to Drawing)"),
                {"actionFitCamera", "actionFitShape"}},
            {QStringLiteral("leave a tool"), {"actionNavigate"}},
            {QStringLiteral("paint shading offsets (tool)"), {"actionOffsetBrush"}},
            {QStringLiteral("cartoon look on/off"), {"actionShowLook"}},
            {QStringLiteral("drawing outline only (aligning)"), {"actionDrawingOutline"}},
            {QStringLiteral("show / hide the selected drawing (the eye in the Scene panel)"), {"actionToggleDrawing"}},
            {QStringLiteral("stereo preview in the viewport on/off"), {"actionStereoToggle"}},
            {QStringLiteral("next depth overlay (none, segments, curvature, depth error)"), {"actionDepthOverlayNext"}},
            {QStringLiteral("optimise the light for stereo (Look menu, Depth tab)"), {"actionOptimiseLight"}},
            {QStringLiteral("set the render camera / look through it"),
                {"actionSetRenderCamera", "actionViewRenderCamera"}},
            {QStringLiteral("stereo review (full screen)"), {"actionStereoReview"}},
            {QStringLiteral("render image / render sequence"), {"actionRenderImage", "actionRenderSequence"}},
            {QStringLiteral("play / pause (viewports, Timeline)"), {"actionPlayPause"}},
            {QStringLiteral("previous / next frame"), {"actionPreviousFrame", "actionNextFrame"}},
            {QStringLiteral("first / last frame of the range"), {"actionFirstFrame", "actionLastFrame"}},
            {QStringLiteral("previous / next key of any kind"), {"actionPreviousKeyFrame", "actionNextKeyFrame"}},
            {QStringLiteral("key the shot camera at the current frame"), {"actionKeyCamera"}},
            {QStringLiteral("export (glTF, PC2, OBJ sequence)"), {"actionExport"}},
            {QStringLiteral("keyboard shortcuts (searchable) / preferences"),
                {"actionKeyboardShortcuts", "actionPreferences"}},
        };
        int checked = 0;
        QStringList unknown;
        const QStringList lines = text.mid(start).split(QLatin1Char('\n'));
        for (int i = 2; i < lines.size() && lines[i].startsWith(QLatin1Char('|')); ++i) {
            const QStringList cells = lines[i].split(QLatin1Char('|'));
            QVERIFY(cells.size() >= 4);
            const QString label = cells[1].trimmed();
            QString keys = cells[2].trimmed();
            if (!actions.contains(label)) {
                // Mouse gestures and viewport keys (brush, roll, F-resize) are not window actions.
                if (!keys.contains(QStringLiteral("drag")) && !label.startsWith(QStringLiteral("brush"))
                    && !label.contains(QStringLiteral("scene tree")))
                    unknown << label;
                continue;
            }
            if (actions.value(label).isEmpty())
                continue; // documented, but not a key of an action (the gizmo)
            keys = keys.section(QLatin1Char(';'), 0, 0);
            const QStringList parts = keys.split(QStringLiteral(" / "));
            const QStringList names = actions.value(label);
            QCOMPARE(parts.size(), names.size());
            for (int k = 0; k < parts.size(); ++k) {
                QAction* action = window.action(names[k]);
                QVERIFY2(action, qPrintable(names[k]));
                // "Ctrl+Shift+Z (Ctrl+Y)": every spelling must be one of the action's shortcuts.
                QString part = parts[k];
                part.replace(QLatin1Char('('), QLatin1Char(',')).remove(QLatin1Char(')'));
                // A comma after "+" is the key itself (Ctrl+,), not a separator.
                for (QString key : part.split(QRegularExpression(QStringLiteral("(?<!\\+),")), Qt::SkipEmptyParts)) {
                    key = key.trimmed();
                    const QKeySequence documented = QKeySequence::fromString(key, QKeySequence::PortableText);
                    QVERIFY2(!documented.isEmpty(), qPrintable(key));
                    QVERIFY2(action->shortcuts().contains(documented),
                        qPrintable(
                            QStringLiteral("%1: README says %2, the action has %3")
                                .arg(names[k], key,
                                    QKeySequence::listToString(action->shortcuts(), QKeySequence::PortableText))));
                    ++checked;
                }
            }
        }
        QVERIFY2(unknown.isEmpty(), qPrintable(QStringLiteral("rows without an action: ") + unknown.join(", ")));
        QVERIFY(checked >= 20);
        QCOMPARE(
            window.action(QStringLiteral("actionSaveAs"))->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    }

    // Bug 4: with every dock open and a drawing selected, the window fits a 1366x768 screen.
    void everyDockFitsASmallScreen()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window, QSize(1300, 700)));
        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        const QList<QDockWidget*> docks = window.findChildren<QDockWidget*>();
        QVERIFY(docks.size() >= 5);
        for (QDockWidget* dock : docks) {
            dock->toggleViewAction()->setChecked(true);
            dock->show();
            dock->raise();
            QApplication::processEvents();
            const QSize minimum = window.minimumSizeHint().expandedTo(window.minimumSize());
            QVERIFY2(minimum.width() <= 1366 && minimum.height() <= 768 - 40,
                qPrintable(QStringLiteral("with %1 open: %2x%3")
                               .arg(dock->objectName())
                               .arg(minimum.width())
                               .arg(minimum.height())));
        }
        // And the window really is that small when asked.
        window.resize(1366, 728);
        QApplication::processEvents();
        QVERIFY2(window.height() <= 728, qPrintable(QString::number(window.height())));
        test::keepScreenshot(&window, "artist-day-small-screen");
    }

    // Bug 5: P after looking through a key toggles the shape, never the camera or the zoom.
    void previewKeepsTheCamera()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        makeKey(window);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(int(doc->data().keys.size()), 1);
        window.propertiesPanel()->editKeyButton()->click(); // looks through the key with its drawing
        test::waitForRender(viewport);
        const Eigen::Vector3d probe = viewport->modelCentre() + Eigen::Vector3d(0.3, 0.2, 0.1);
        const QPointF before = viewport->projectToWidget(probe);
        const model::Camera camera = viewport->camera();

        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_P);
        QVERIFY(viewport->isPreview());
        test::waitForRender(viewport);
        const QPointF after = viewport->projectToWidget(probe);
        QVERIFY2(QLineF(before, after).length() < 0.5,
            qPrintable(
                QStringLiteral("(%1, %2) -> (%3, %4)").arg(before.x()).arg(before.y()).arg(after.x()).arg(after.y())));
        QVERIFY((viewport->camera().eye - camera.eye).norm() < 1e-9);
        QCOMPARE(viewport->camera().fovYDegrees, camera.fovYDegrees);
        QTest::keyClick(viewport, Qt::Key_P);
        QVERIFY(!viewport->isPreview());
        QVERIFY(QLineF(before, viewport->projectToWidget(probe)).length() < 0.5);
    }

    // Bug 6: Stereo Review shows what the editor shows (the preview's blend at the same camera).
    void reviewShowsTheEditorsShape()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        makeKey(window);
        if (QTest::currentTestFailed())
            return;
        window.propertiesPanel()->editKeyButton()->click();
        // Deform the key so the preview differs from the base model.
        test::waitForRender(viewport);
        const QPoint c = viewport->projectToWidget(viewport->modelCentre()).toPoint();
        test::drag(viewport, Qt::LeftButton, Qt::NoModifier, c, c + QPoint(40, -30));
        QVERIFY(doc->undoStack()->index() > 0);
        window.action(QStringLiteral("actionPreview"))->trigger();
        QVERIFY(viewport->isPreview());
        const algo::Positions shown = viewport->displayedShape();
        QVERIFY((shown - doc->data().baseMesh->vertices).cwiseAbs().maxCoeff() > 1e-3);

        window.action(QStringLiteral("actionStereoReview"))->trigger();
        auto* review = window.findChild<app::ReviewWindow*>();
        QVERIFY(review);
        QVERIFY(review->viewport()->isPreview());
        QVERIFY((review->viewport()->camera().eye - viewport->camera().eye).norm() < 1e-6);
        const algo::Positions reviewed = review->viewport()->displayedShape();
        QCOMPARE(reviewed.rows(), shown.rows());
        QVERIFY((reviewed - shown).cwiseAbs().maxCoeff() < 1e-5);
        // Bug 8: an idle review shows its last frame's time, not "0.0 fps".
        QTest::qWait(1200);
        QVERIFY2(!review->statusText().contains(QStringLiteral("0.0 fps")), qPrintable(review->statusText()));
        review->close();
    }

    // Bug 8: a white-on-transparent drawing's thumbnail shows in the Scene tree (drawn on a checker).
    void thumbnailsShowLightDrawings()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        QTreeWidget* tree = window.scenePanel()->tree();
        const auto items = tree->findItems(QStringLiteral("tuxpaint_elephant"), Qt::MatchExactly | Qt::MatchRecursive);
        QVERIFY(!items.isEmpty());
        const QImage icon = items.front()->icon(0).pixmap(32, 32).toImage().convertToFormat(QImage::Format_ARGB32);
        QVERIFY(!icon.isNull());
        // On a plain white tree the drawing's white would vanish: count the pixels that are not.
        int visible = 0;
        for (int y = 0; y < icon.height(); ++y)
            for (int x = 0; x < icon.width(); ++x) {
                const QColor p = icon.pixelColor(x, y);
                visible += p.alpha() > 200 && p.lightness() < 225;
            }
        QVERIFY2(visible > icon.width() * icon.height() / 8,
            qPrintable(QStringLiteral("%1 of %2x%3, first %4")
                           .arg(visible)
                           .arg(icon.width())
                           .arg(icon.height())
                           .arg(icon.pixel(5, 5), 8, 16)));
    }

    // Bug 8: the brush's red selection shows during the stroke only (not after it, nor after undo);
    // the circle under the cursor shows the radius and F resizes it.
    void brushFeedbackDuringTheStrokeOnly()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        makeKey(window);
        if (QTest::currentTestFailed())
            return;
        window.propertiesPanel()->editKeyButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Brush);
        test::waitForRender(viewport);
        const QImage clean = viewport->renderedImage();

        // Hovering shows the circle with the radius in pixels at the surface under the cursor.
        const QPoint c = viewport->projectToWidget(viewport->modelCentre()).toPoint();
        QTest::mouseMove(viewport, c);
        QMouseEvent hover(QEvent::MouseMove, c, viewport->mapToGlobal(c), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &hover);
        const views::BrushCursor* circle = viewport->tool<views::BrushTool>().cursorCircle();
        QTRY_VERIFY(circle->isVisible());
        const auto hit = viewport->pickSurface(c);
        QVERIFY(hit);
        const double expected
            = viewport->tool<views::BrushTool>().size().radius() / viewport->worldUnitsPerPixel(hit->second);
        QVERIFY2(std::abs(circle->radiusPixels() - expected) < 0.5,
            qPrintable(QStringLiteral("%1 vs %2").arg(circle->radiusPixels()).arg(expected)));
        test::keepScreenshot(&window, "artist-day-brush-circle");

        // F, a move away from the centre, a click: the new radius is the distance from the centre.
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_F);
        QVERIFY(viewport->tool<views::BrushTool>().isResizing());
        const double radiusBefore = viewport->tool<views::BrushTool>().size().radius();
        const QPoint out = c + QPoint(int(expected) + 40, 0);
        QMouseEvent away(
            QEvent::MouseMove, out, viewport->mapToGlobal(out), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &away);
        QVERIFY(viewport->tool<views::BrushTool>().size().radius() > radiusBefore * 1.2);
        QTest::mouseClick(viewport, Qt::LeftButton, {}, out);
        QVERIFY(!viewport->tool<views::BrushTool>().isResizing());
        const int steps = doc->undoStack()->index();
        QCOMPARE(doc->undoStack()->index(), steps); // resizing is not an edit

        {
            QMouseEvent press(
                QEvent::MouseButtonPress, c, viewport->mapToGlobal(c), Qt::LeftButton, Qt::LeftButton, {});
            QApplication::sendEvent(viewport, &press);
            const QPoint to = c + QPoint(30, 0);
            QMouseEvent move(QEvent::MouseMove, to, viewport->mapToGlobal(to), Qt::NoButton, Qt::LeftButton, {});
            QApplication::sendEvent(viewport, &move);
            test::waitForRender(viewport);
            const QImage during = viewport->renderedImage();
            QMouseEvent release(
                QEvent::MouseButtonRelease, to, viewport->mapToGlobal(to), Qt::LeftButton, Qt::NoButton, {});
            QApplication::sendEvent(viewport, &release);
            int red = 0;
            for (int y = 0; y < during.height(); y += 2)
                for (int x = 0; x < during.width(); x += 2) {
                    const QColor p = during.pixelColor(x, y);
                    red += p.red() > 150 && p.green() < 110 && p.blue() < 110;
                }
            QVERIFY2(red > 20, qPrintable(QString::number(red)));
        }
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        doc->undoStack()->undo();
        test::waitForRender(viewport);
        // After the stroke and its undo the model shows its look again, not the red selection.
        const QImage after = viewport->renderedImage();
        QCOMPARE(after.size(), clean.size());
        auto redPixels = [](const QImage& image) {
            int red = 0;
            for (int y = 0; y < image.height(); y += 2)
                for (int x = 0; x < image.width(); x += 2) {
                    const QColor p = image.pixelColor(x, y);
                    if (p.red() > 180 && p.green() < 90 && p.blue() < 90)
                        ++red;
                }
            return red;
        };
        // During a stroke the selection is red; after it and its undo the picture is as before.
        QCOMPARE(redPixels(after), redPixels(clean));
        int differing = 0;
        for (int y = 0; y < after.height(); y += 2)
            for (int x = 0; x < after.width(); x += 2)
                differing += after.pixel(x, y) != clean.pixel(x, y);
        QVERIFY2(differing < after.width() * after.height() / 4 / 1000, qPrintable(QString::number(differing)));
    }

    // View presets and the axis gizmo (Blender's numpad 1/3/7 and its corner gizmo).
    void viewPresetsAndTheAxisGizmo()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        Viewport* viewport = window.viewport();
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_3, Qt::KeypadModifier);
        QVERIFY((viewport->camera().forward() + Eigen::Vector3d::UnitX()).norm() < 1e-6); // from +X
        QTest::keyClick(viewport, Qt::Key_7, Qt::KeypadModifier | Qt::ControlModifier);
        QVERIFY((viewport->camera().forward() - Eigen::Vector3d::UnitY()).norm() < 1e-6); // from below

        auto* gizmo = viewport->findChild<views::AxisGizmo*>();
        QVERIFY(gizmo && gizmo->isVisible());
        window.action(QStringLiteral("actionViewFront"))->trigger();
        // From the front, +X points right and +Y up in the gizmo; click +Y: the top view.
        const auto ends = gizmo->axisEnds();
        QVERIFY(ends[0].x() > gizmo->width() / 2.0 + 10);
        QVERIFY(ends[2].y() < gizmo->height() / 2.0 - 10);
        QTest::mouseClick(gizmo, Qt::LeftButton, {}, ends[2].toPoint());
        QVERIFY((viewport->camera().forward() + Eigen::Vector3d::UnitY()).norm() < 1e-6);
        // -Z sits behind the centre from the front; from the top it is up on screen: the back view.
        const auto top = gizmo->axisEnds();
        QTest::mouseClick(gizmo, Qt::LeftButton, {}, top[5].toPoint());
        QVERIFY((viewport->camera().forward() - Eigen::Vector3d::UnitZ()).norm() < 1e-6);
    }

    // Stereo in the main viewport, from the View menu and Ctrl+3.
    void stereoToggleInTheViewport()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        Viewport* viewport = window.viewport();
        QCOMPARE(viewport->display().stereo(), algo::StereoOutput::Off);
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(viewport->display().stereo(), algo::StereoOutput::Anaglyph);
        QVERIFY(window.action(QStringLiteral("actionStereoAnaglyph"))->isChecked());
        test::waitForRender(viewport);
        // Anaglyph: red and cyan fringes where the eyes disagree.
        const QImage image = viewport->renderedImage();
        int fringes = 0;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2) {
                const QColor p = image.pixelColor(x, y);
                if (std::abs(p.green() - p.blue()) < 20 && std::abs(p.red() - p.green()) > 60)
                    ++fringes;
            }
        QVERIFY(fringes > 50);
        window.action(QStringLiteral("actionStereoSideBySide"))->trigger();
        QCOMPARE(viewport->display().stereo(), algo::StereoOutput::SideBySide);
        QTest::keyClick(viewport, Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(viewport->display().stereo(), algo::StereoOutput::Off);
        QVERIFY(window.action(QStringLiteral("actionStereoOff"))->isChecked());
        QTest::keyClick(viewport, Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(viewport->display().stereo(), algo::StereoOutput::SideBySide); // the last mode comes back
    }

    // Empty states: the viewport says what to do next.
    void emptyStatesSayWhatToDoNext()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        window.resize(1200, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QApplication::setActiveWindow(&window);
        auto* hint = window.viewport()->findChild<QLabel*>(QStringLiteral("firstStepsHint"));
        QVERIFY(hint && hint->isVisible());
        QVERIFY(hint->text().contains(QStringLiteral("New from Mesh")));
        QVERIFY(window.openFile(test::sampleProject()));
        QVERIFY(hint->isVisible());
        QVERIFY(hint->text().contains(QStringLiteral("Align to Drawing")));
        makeKey(window);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(!hint->isVisible());
        window.document()->undoStack()->undo();
        QVERIFY(hint->isVisible());
    }

    // Aligning: O shows the drawing's outline only; Ctrl snaps the roll to 15 degrees.
    void outlineAndRollSnapping()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        Viewport* viewport = window.viewport();
        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        window.propertiesPanel()->alignButton()->click();
        test::waitForRender(viewport);
        const QImage full = viewport->renderedImage();
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_O);
        QVERIFY(viewport->drawingOverlay().outline());
        test::waitForRender(viewport);
        const QImage outline = viewport->renderedImage();
        int magenta = 0;
        for (int y = 0; y < outline.height(); y += 2)
            for (int x = 0; x < outline.width(); x += 2) {
                const QColor p = outline.pixelColor(x, y);
                if (p.red() > 200 && p.green() < 60 && p.blue() > 120)
                    ++magenta;
            }
        QVERIFY2(magenta > 100, qPrintable(QString::number(magenta)));
        QVERIFY(outline != full);
        test::keepScreenshot(&window, "artist-day-aligning-outline");
        QTest::keyClick(viewport, Qt::Key_O);
        QVERIFY(!viewport->drawingOverlay().outline());

        const Eigen::Vector3d upBefore = viewport->camera().trueUp();
        const QPoint c = viewport->rect().center();
        // 0.4 degrees per pixel: 50 px is 20 degrees, snapped to 15.
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier | Qt::ShiftModifier | Qt::ControlModifier, c,
            c + QPoint(50, 0), 25);
        const double angle = std::acos(std::clamp(upBefore.dot(viewport->camera().trueUp()), -1.0, 1.0)) * 180.0 / M_PI;
        QVERIFY2(std::abs(angle - 15.0) < 1e-6, qPrintable(QString::number(angle)));
    }

    // Issue 24, item 16: the hint follows the first key's steps (select, align, create).
    void hintFollowsTheFirstKeysSteps()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        auto* hint = window.viewport()->findChild<QLabel*>(QStringLiteral("firstStepsHint"));
        QVERIFY(hint && hint->isVisible());
        const QString unselected = hint->text();
        QVERIFY(unselected.contains(QStringLiteral("Select a drawing")));
        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        QVERIFY(hint->isVisible());
        const QString selected = hint->text();
        QVERIFY2(!selected.contains(QStringLiteral("Select a drawing")), qPrintable(selected));
        QVERIFY(selected.contains(QStringLiteral("Align to Drawing")));
        // Item 18: under a desktop that takes Alt + drag, the hint says how to navigate without Alt.
        {
            const QByteArray saved = qgetenv("XDG_CURRENT_DESKTOP");
            qputenv("XDG_CURRENT_DESKTOP", "KDE");
            QVERIFY(clickSceneItem(window, QStringLiteral("openclipart_contour_elephant")));
            QVERIFY2(hint->text().contains(QStringLiteral("Blender navigation")), qPrintable(hint->text()));
            qunsetenv("XDG_CURRENT_DESKTOP");
            QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
            QVERIFY(!hint->text().contains(QStringLiteral("Blender navigation")));
            if (!saved.isNull())
                qputenv("XDG_CURRENT_DESKTOP", saved);
        }
        alignByDrag(window);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(hint->isVisible());
        const QString aligned = hint->text();
        QVERIFY2(aligned != selected && !aligned.contains(QStringLiteral("press Align")), qPrintable(aligned));
        QVERIFY(aligned.contains(QStringLiteral("Create Key from Drawing")));
        // Selecting the base model goes back to the first step's words.
        window.scenePanel()->select({views::ScenePanel::ItemKind::BaseModel, 0});
        QCOMPARE(hint->text(), unselected);
    }

    // Issue 24, item 11: after Create Key from Drawing the panel shows Edit Key with the Brush,
    // which the status bar points at, though the artist had scrolled down to Create Key.
    void editKeyButtonInViewAfterCreatingAKey()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window, QSize(1366, 700)));
        QVERIFY(clickSceneItem(window, QStringLiteral("tuxpaint_elephant")));
        alignByDrag(window);
        if (QTest::currentTestFailed())
            return;
        views::PropertiesPanel* panel = window.propertiesPanel();
        auto* scroll = panel->findChild<QScrollArea*>();
        QVERIFY(scroll);
        QApplication::processEvents();
        scroll->verticalScrollBar()->setValue(
            panel->createKeyButton()->mapTo(scroll->widget(), QPoint(0, 0)).y() - scroll->viewport()->height() / 2);
        QApplication::processEvents();
        QVERIFY2(scroll->verticalScrollBar()->value() > 0, "the panel does not scroll at this size");
        // Top to bottom within the viewport (the panel scrolls vertically only).
        auto inView = [scroll](const QWidget* w) {
            const int top = w->mapTo(scroll->viewport(), QPoint(0, 0)).y();
            return w->isVisible() && top >= 0 && top + w->height() <= scroll->viewport()->height();
        };
        const QRect createRect(
            panel->createKeyButton()->mapTo(scroll->viewport(), QPoint(0, 0)), panel->createKeyButton()->size());
        QVERIFY2(inView(panel->createKeyButton()),
            qPrintable(QStringLiteral("Create Key at %1,%2 %3x%4 in a %5x%6 view")
                           .arg(createRect.x())
                           .arg(createRect.y())
                           .arg(createRect.width())
                           .arg(createRect.height())
                           .arg(scroll->viewport()->width())
                           .arg(scroll->viewport()->height())));
        QTest::mouseClick(panel->createKeyButton(), Qt::LeftButton);
        QCOMPARE(int(window.document()->data().keys.size()), 1);
        QTRY_VERIFY_WITH_TIMEOUT(inView(panel->editKeyButton()), 2000);
        QCOMPARE(scroll->horizontalScrollBar()->value(), 0); // the panel's left edge stays
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("Edit Key with the Brush")));
    }
};

QTEST_MAIN(TestArtistDay)
#include "test_artist_day.moc"
