// Issue 24, "Done when": the two-key task on the plain sample, scripted through the real window as
// an artist does it, on a 1366x768 screen with a window manager (ctest runs this through
// tests/app/with-window-manager.sh, which starts openbox on an Xvfb server of that size).
//
// For the model sheet's side and front drawings: select the drawing in the Scene tree, start from
// the nearest preset view, Align to Drawing with a nudge of the mouse, Fit Camera to Drawing
// (Ctrl+Shift+F), Create Key from Drawing, one brush stroke on the key; then the view-dependent
// preview. At every step the whole window, its status bar and the Timeline's Play button are on
// the screen; a screenshot of each step is kept (CELFORM_SCREENSHOT_DIR) to be looked at.
#include "test_support.h"
#include "window_test_support.h"

#include "editor/jobs/job_runner.h"
#include "editor/main_window.h"
#include "celform/model/document/document.h"
#include "celform/views/panels/fit_group.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QScrollArea>
#include <QElapsedTimer>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>

using namespace celform;
using views::Viewport;

namespace {

constexpr int kJobTimeoutMs = 120000;

/// Whether a widget lies wholly on the screen's available area (what a window manager leaves).
bool onScreen(const QWidget* widget)
{
    const QRect available = widget->screen()->availableGeometry();
    // Wholly shown: not scrolled out of its panel nor hidden under another widget.
    return widget->isVisible() && available.contains(QRect(widget->mapToGlobal(QPoint(0, 0)), widget->size()))
        && widget->visibleRegion().boundingRect() == widget->rect();
}

QString where(const QWidget* widget)
{
    const QRect global(widget->mapToGlobal(QPoint(0, 0)), widget->size());
    const QRect seen = widget->visibleRegion().boundingRect();
    return QStringLiteral("%1: %2x%3 at %4,%5, visible %6, %7x%8 of it shown")
        .arg(widget->objectName())
        .arg(global.width())
        .arg(global.height())
        .arg(global.x())
        .arg(global.y())
        .arg(widget->isVisible())
        .arg(seen.width())
        .arg(seen.height());
}

/// The geometry of the window and its screen, for messages.
QString describe(const app::MainWindow& window)
{
    const QRect frame = window.frameGeometry(), available = window.screen()->availableGeometry();
    return QStringLiteral("frame %1x%2 at %3,%4 on a screen of %5x%6 available at %7,%8")
        .arg(frame.width())
        .arg(frame.height())
        .arg(frame.x())
        .arg(frame.y())
        .arg(available.width())
        .arg(available.height())
        .arg(available.x())
        .arg(available.y());
}

/// Presses a fit's shortcut in the viewport and waits for its job to end (the runner deletes itself).
bool runFit(app::MainWindow& window, QKeySequence keys, const char* runner)
{
    QTest::keySequence(window.viewport(), keys);
    QElapsedTimer clock;
    clock.start();
    while (!window.findChild<app::JobRunner*>(QString::fromLatin1(runner)) && clock.elapsed() < 2000)
        QTest::qWait(10);
    while (window.findChild<app::JobRunner*>(QString::fromLatin1(runner)) && clock.elapsed() < kJobTimeoutMs)
        QTest::qWait(20);
    QTest::qWait(50);
    return !window.findChild<app::JobRunner*>(QString::fromLatin1(runner));
}

} // namespace

class TestTwoKeyRun : public QObject {
    Q_OBJECT

    /// The window, its status bar and the Play button are all on the screen.
    void checkOnScreen(app::MainWindow& window, const char* step)
    {
        const QRect available = window.screen()->availableGeometry();
        QVERIFY2(available.contains(window.frameGeometry()),
            qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(step), describe(window))));
        QVERIFY2(onScreen(window.statusBar()), step);
        auto* play = window.findChild<QToolButton*>(QStringLiteral("timelinePlay"));
        QVERIFY2(play && onScreen(play), step);
    }

    /// One key from a drawing of the model sheet: selected, a preset view, aligned by a nudge and
    /// Fit Camera, the key made and brushed once.
    void makeKey(app::MainWindow& window, const QString& drawing, int presetKey, const char* name)
    {
        model::Document* doc = window.document();
        Viewport* vp = window.viewport();
        views::PropertiesPanel* props = window.propertiesPanel();
        QVERIFY2(test::clickSceneItem(window, drawing), qPrintable(drawing));
        const model::ObjectId id = window.scenePanel()->selection().id;
        QVERIFY(doc->data().drawing(id));
        QTest::keyClick(vp, Qt::Key(presetKey), Qt::KeypadModifier);
        test::waitForRender(vp);
        test::keepScreenshot(&window, qPrintable(QStringLiteral("two-keys-%1-1-selected").arg(QLatin1String(name))));

        // Align to Drawing, a small orbit by hand (the artist's rough alignment), then Fit Camera.
        props->alignButton()->click();
        QCOMPARE(vp->tool(), Viewport::Tool::Align);
        const QPoint c = vp->rect().center();
        test::drag(vp, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(12, 4));
        QVERIFY(doc->data().drawing(id)->aligned);
        QVERIFY(runFit(window, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F), "fitCameraRunner"));
        test::waitForRender(vp);
        test::keepScreenshot(&window, qPrintable(QStringLiteral("two-keys-%1-2-aligned").arg(QLatin1String(name))));
        QTest::keyClick(vp, Qt::Key_Escape);
        QCOMPARE(vp->tool(), Viewport::Tool::Navigate);
        // The fit is the last step: back in the mode and out again stores nothing more.
        QVERIFY2(doc->undoStack()->text(doc->undoStack()->index() - 1) == QStringLiteral("Fit Camera to Drawing"),
            qPrintable(doc->undoStack()->text(doc->undoStack()->index() - 1) + QStringLiteral("; ")
                + window.statusBar()->currentMessage()));
        checkOnScreen(window, "aligned");

        // Create Key from Drawing; its figures show how well the model meets the drawing.
        const std::size_t keys = doc->data().keys.size();
        QVERIFY(props->createKeyButton()->isEnabled());
        props->createKeyButton()->click();
        QCOMPARE(doc->data().keys.size(), keys + 1);
        const auto fit = test::fitFigures(window);
        QVERIFY(fit && fit->valid);
        qInfo("%s: silhouette IoU %.3f, chamfer %.2f px after Fit Camera", name, fit->iou, fit->chamferPx);
        QVERIFY2(fit->iou > 0.85, qPrintable(QString::number(fit->iou)));

        // Edit Key with the Brush: one stroke, one undo step, on the model's middle.
        test::keepScreenshot(&window, qPrintable(QStringLiteral("two-keys-%1-3-key").arg(QLatin1String(name))));
        // The panel's rows fit its dock: nothing is cut at the right edge (it never scrolls sideways).
        auto* scroll = props->findChild<QScrollArea*>();
        QVERIFY(scroll);
        QVERIFY2(scroll->widget()->width() <= scroll->viewport()->width(),
            qPrintable(QStringLiteral("the Properties need %1 px, the dock shows %2")
                           .arg(scroll->widget()->width())
                           .arg(scroll->viewport()->width())));
        QVERIFY2(onScreen(props->editKeyButton()), qPrintable(where(props->editKeyButton())));
        props->editKeyButton()->click();
        QCOMPARE(vp->tool(), Viewport::Tool::Brush);
        test::waitForRender(vp);
        const QPoint middle = vp->projectToWidget(vp->modelCentre()).toPoint();
        QPoint at = middle;
        for (int dy = 0; dy < 200 && vp->pickVertex(at) < 0; dy += 5)
            at = middle + QPoint(0, dy);
        QVERIFY2(vp->pickVertex(at) >= 0, "nothing to brush near the model's centre");
        const int steps = doc->undoStack()->index();
        test::drag(vp, Qt::LeftButton, Qt::NoModifier, at, at + QPoint(5, -4), 3);
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        test::waitForRender(vp);
        test::keepScreenshot(&window, qPrintable(QStringLiteral("two-keys-%1-4-brushed").arg(QLatin1String(name))));
        QTest::keyClick(vp, Qt::Key_Escape);
        QCOMPARE(vp->tool(), Viewport::Tool::Navigate);
        checkOnScreen(window, "brushed");
    }

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void twoKeysOnASmallScreen()
    {
        {
            QSettings settings; // a first launch: no saved geometry
            settings.remove(QStringLiteral("window/geometry"));
            settings.remove(QStringLiteral("window/state"));
        }
        app::MainWindow window(app::MainWindow::Mode::Interactive);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.activateWindow();
        QTRY_VERIFY(QApplication::activeWindow() == &window);
        qInfo("%s", qPrintable(describe(window)));
        QVERIFY(window.openFile(test::sampleProject()));
        test::waitForRender(window.viewport());
        checkOnScreen(window, "opened");
        test::keepScreenshot(&window, "two-keys-0-opened");

        makeKey(window, QStringLiteral("elephant-sheet-side"), Qt::Key_1, "side");
        if (QTest::currentTestFailed())
            return;
        makeKey(window, QStringLiteral("elephant-sheet-front"), Qt::Key_3, "front");
        if (QTest::currentTestFailed())
            return;

        // The view-dependent preview: P, then an orbit between the keys changes the shape.
        Viewport* vp = window.viewport();
        QTest::keyClick(vp, Qt::Key_P);
        QVERIFY(vp->isPreview());
        QTest::keyClick(vp, Qt::Key_1, Qt::KeypadModifier);
        test::waitForRender(vp);
        const algo::Positions atSide = vp->displayedShape();
        const QPoint c = vp->rect().center();
        test::drag(vp, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(-120, 0));
        test::waitForRender(vp);
        QVERIFY((vp->displayedShape() - atSide).cwiseAbs().maxCoeff() > 1e-5);
        test::keepScreenshot(&window, "two-keys-5-preview");
        checkOnScreen(window, "preview");
        QCOMPARE(int(window.document()->data().keys.size()), 2);
    }
};

QTEST_MAIN(TestTwoKeyRun)
#include "test_two_key_run.moc"
