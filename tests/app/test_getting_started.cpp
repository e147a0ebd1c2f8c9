// Help > Getting Started and its pictures. The test walks the guide's steps in the real editor and
// writes each screenshot into docs/images (so the guide never shows an editor that is gone), then
// checks that the guide names exactly those pictures and that the Help menu opens it with them.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"

#include "celform/model/document/document.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/overlays/drawing_overlay.h"

#include <QAction>
#include <QDialog>
#include <QDir>
#include <QFile>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QUndoStack>

using namespace celform;
using views::Viewport;

class TestGettingStarted : public QObject {
    Q_OBJECT

    const QString m_docs = QStringLiteral(CELFORM_SOURCE_DIR "/docs");

    bool shoot(app::MainWindow& window, const QString& name)
    {
        window.viewport()->update();
        test::waitForRender(window.viewport());
        return window.saveScreenshot(m_docs + QStringLiteral("/images/") + name);
    }

    bool clickSceneItem(app::MainWindow& window, const QString& name)
    {
        QTreeWidget* tree = window.scenePanel()->tree();
        const auto items = tree->findItems(name, Qt::MatchExactly | Qt::MatchRecursive);
        if (items.isEmpty())
            return false;
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, tree->visualItemRect(items.front()).center());
        return true;
    }

private slots:
    void screenshotsOfEachStep()
    {
        QStringList made;
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window, QSize(1280, 800)));
        Viewport* viewport = window.viewport();
        QVERIFY(shoot(window, QStringLiteral("getting-started-1-open.png")));
        made << QStringLiteral("getting-started-1-open.png");

        // Step 2: the model-sheet drawing of the side, the right view, a little orbit, the outline.
        QVERIFY(clickSceneItem(window, QStringLiteral("elephant-sheet-side")));
        window.propertiesPanel()->alignButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Align);
        window.action(QStringLiteral("actionViewFront"))->trigger();
        const QPoint c = viewport->rect().center();
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(-12, 4));
        window.action(QStringLiteral("actionDrawingOutline"))->trigger();
        QVERIFY(viewport->drawingOverlay().outline());
        QVERIFY(shoot(window, QStringLiteral("getting-started-2-align.png")));
        made << QStringLiteral("getting-started-2-align.png");
        window.action(QStringLiteral("actionNavigate"))->trigger();

        // Step 3: a key, then Fit Camera and Fit Shape, each one undo step.
        QPushButton* createKey = window.propertiesPanel()->createKeyButton();
        QVERIFY(createKey->isEnabled());
        createKey->click();
        QUndoStack* undo = window.document()->undoStack();
        const int beforeFits = undo->index();
        QAction* fitCamera = window.action(QStringLiteral("actionFitCamera"));
        QAction* fitShape = window.action(QStringLiteral("actionFitShape"));
        QTRY_VERIFY(fitCamera->isEnabled());
        fitCamera->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(undo->index(), beforeFits + 1, 60000);
        QTRY_VERIFY(fitShape->isEnabled());
        fitShape->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(undo->index(), beforeFits + 2, 60000);
        QCOMPARE(undo->text(beforeFits), QStringLiteral("Fit Camera to Drawing"));
        QCOMPARE(undo->text(beforeFits + 1), QStringLiteral("Fit Shape to Drawing"));
        window.action(QStringLiteral("actionDrawingOutline"))->trigger();
        window.propertiesPanel()->editKeyButton()->click();
        QCOMPARE(viewport->tool(), Viewport::Tool::Brush);
        window.action(QStringLiteral("actionDrawingOutline"))->trigger();
        QVERIFY(viewport->drawingOverlay().outline());
        QVERIFY(shoot(window, QStringLiteral("getting-started-3-fit.png")));
        made << QStringLiteral("getting-started-3-fit.png");
        window.action(QStringLiteral("actionDrawingOutline"))->trigger();

        // Step 4: the brush touches up, the circle under the cursor.
        test::waitForRender(viewport);
        const QPoint centre = viewport->projectToWidget(viewport->modelCentre()).toPoint();
        QPoint nose = centre;
        for (int dx = 0; dx < 200 && !viewport->pickSurface(nose); dx += 5)
            nose = centre + QPoint(-dx, dx / 2);
        QVERIFY(viewport->pickSurface(nose));
        const int steps = undo->index();
        test::drag(viewport, Qt::LeftButton, Qt::NoModifier, nose, nose + QPoint(-6, 3));
        QCOMPARE(undo->index(), steps + 1);
        QMouseEvent hover(QEvent::MouseMove, nose, viewport->mapToGlobal(nose), Qt::NoButton, Qt::NoButton, {});
        QApplication::sendEvent(viewport, &hover);
        QTest::qWait(60);
        QVERIFY(shoot(window, QStringLiteral("getting-started-4-brush.png")));
        made << QStringLiteral("getting-started-4-brush.png");

        // Step 5: the preview from an orbited view.
        window.action(QStringLiteral("actionNavigate"))->trigger();
        window.action(QStringLiteral("actionPreview"))->trigger();
        test::drag(viewport, Qt::LeftButton, Qt::AltModifier, c, c + QPoint(-60, 10));
        QVERIFY(viewport->isPreview());
        QVERIFY(shoot(window, QStringLiteral("getting-started-5-preview.png")));
        made << QStringLiteral("getting-started-5-preview.png");

        // The guide shows exactly these pictures.
        QFile guide(m_docs + QStringLiteral("/getting-started.md"));
        QVERIFY(guide.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString text = QString::fromUtf8(guide.readAll());
        QStringList named;
        const QRegularExpression image(QStringLiteral(R"(!\[[^\]]*\]\(images/([^)]+)\))"));
        for (auto it = image.globalMatch(text); it.hasNext();)
            named << it.next().captured(1);
        QCOMPARE(named, made);
        for (const QString& name : made) {
            const QImage shot(m_docs + QStringLiteral("/images/") + name);
            QCOMPARE(shot.size(), window.size() * window.devicePixelRatio());
        }
    }

    void helpMenuOpensTheGuide()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QAction* open = window.action(QStringLiteral("actionGettingStarted"));
        QVERIFY(open);
        open->trigger();
        auto* dialog = window.findChild<QDialog*>(QStringLiteral("gettingStarted"));
        QVERIFY(dialog && dialog->isVisible());
        auto* browser = dialog->findChild<QTextBrowser*>();
        QVERIFY(browser);
        QVERIFY(browser->toPlainText().contains(QStringLiteral("Getting started with Celform")));
        const QVariant picture = browser->document()->resource(
            QTextDocument::ImageResource, QUrl(QStringLiteral("images/getting-started-2-align.png")));
        QVERIFY(picture.isValid());
        // An artist's guide: pictures no wider than the text, no build or test instructions.
        const QImage shown = picture.value<QImage>();
        QVERIFY(!shown.isNull());
        QVERIFY2(shown.width() <= browser->viewport()->width(),
            qPrintable(QStringLiteral("%1 > %2").arg(shown.width()).arg(browser->viewport()->width())));
        QTRY_COMPARE(browser->horizontalScrollBar()->maximum(), 0);
        for (const char* developers : {"scripts/", "test suite", "test_getting_started", "build/release", "cmake"})
            QVERIFY2(!browser->toPlainText().contains(QLatin1String(developers)), developers);
        dialog->close();
    }
};

QTEST_MAIN(TestGettingStarted)
#include "test_getting_started.moc"
