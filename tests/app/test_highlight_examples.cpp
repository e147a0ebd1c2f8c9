// The paper's two worked highlight examples made on the bundled sample in the editor alone, as an
// artist would under Xvfb (Anjyo & Hiramitsu 2003, Figures 5 and 6): paint the elephant's ear as
// the patch (nearly flat, like the car's window), add the Window preset (rotation, directional
// scaling, split), key it at frames 0 and 30 by dragging it in the viewport, add the Crescent
// preset (a layer minus a hidden, shifted copy), key the cut, save, and render the 30 frames with
// `celform render`.
#include "test_support.h"
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"

#include "celform/model/render/render_output.h"
#include "celform/views/panels/highlight_panel.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"

#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QToolButton>

using namespace celform;

using test::drag;
using test::keepScreenshot;
using test::waitForRender;

namespace {

/// The ear of the sample elephant (model units), facing the default camera.
const Eigen::Vector3d kEarCentre(0.14, -0.07, 0.22);

struct Coverage {
    int area = 0;
    double cx = 0.0, cy = 0.0;
};

Coverage coverage(const std::vector<float>& mask, int width)
{
    Coverage c;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i] > 0.5f) {
            ++c.area;
            c.cx += double(int(i) % width);
            c.cy += double(int(i) / width);
        }
    if (c.area > 0) {
        c.cx /= c.area;
        c.cy /= c.area;
    }
    return c;
}

QAction* presetAction(views::HighlightPanel* panel, int index)
{
    auto* button = panel->findChild<QToolButton*>(QStringLiteral("addHighlightPreset"));
    return button && button->menu() ? button->menu()->actions().value(index) : nullptr;
}

} // namespace

class TestHighlightExamples : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void windowAndCrescentOnTheSample()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        views::Viewport* vp = window.viewport();
        auto* panel = window.findChild<views::HighlightPanel*>();
        QVERIFY(panel);
        // Bring the Highlights tab forward, as an artist would.
        test::raiseDockOf(panel);
        waitForRender(vp);

        // 1. The Window preset, then its patch painted on the ear with one dab of the brush.
        QAction* windowPreset = presetAction(panel, 0);
        QVERIFY(windowPreset);
        windowPreset->trigger();
        QCOMPARE(doc->data().look.highlights.size(), std::size_t(1));
        auto* paint = panel->findChild<QToolButton*>(QStringLiteral("highlightPaintPatch"));
        paint->click();
        QCOMPARE(vp->tool(), views::Viewport::Tool::Patch);
        vp->tool<views::BrushTool>().size().setRadius(0.12);
        const QPoint ear = vp->projectToWidget(kEarCentre).toPoint();
        drag(vp, Qt::LeftButton, Qt::NoModifier, ear, ear, 1);
        const QString patch = doc->data().look.highlights.front().patch;
        const algo::FaceSet* set = doc->data().faceSet(patch);
        QVERIFY(set && set->faces.size() > 100);
        waitForRender(vp);
        keepScreenshot(&window, "highlight-1-patch");
        paint->click();
        QCOMPARE(vp->tool(), views::Viewport::Tool::Navigate);

        // 2. Keys at 0 and 30: at 30 the streak is dragged across the ear ("Edit in Viewport").
        auto* editInViewport = panel->findChild<QPushButton*>(QStringLiteral("highlightEditInViewport"));
        panel->setCurrentFrame(30);
        editInViewport->click();
        QCOMPARE(vp->tool(), views::Viewport::Tool::Highlight);
        drag(vp, Qt::LeftButton, Qt::NoModifier, ear, ear + QPoint(-25, 20));
        editInViewport->click();
        const model::HighlightTrack window30 = doc->data().look.highlights.front();
        QCOMPARE(window30.keys.size(), std::size_t(2));
        QCOMPARE(window30.keys.back().frame, 30.0);

        // 3. The Crescent preset on the same patch; its cut moves between 0 and 30.
        QAction* crescentPreset = presetAction(panel, 1);
        QVERIFY(crescentPreset);
        crescentPreset->trigger();
        const auto& tracks = doc->data().look.highlights;
        QCOMPARE(tracks.size(), std::size_t(3));
        QCOMPARE(tracks[1].patch, patch);
        QVERIFY(!tracks[1].visible);
        QCOMPARE(tracks[2].combineWith.size(), std::size_t(1));
        QCOMPARE(panel->selectedLayer(), 2);
        panel->selectLayer(1);
        panel->setCurrentFrame(0);
        // The rows of the previously selected layer are deleted later: let them go before looking.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        auto* cutAlpha = panel->findChild<QDoubleSpinBox*>(QStringLiteral("highlightOperation0a"));
        QVERIFY(cutAlpha);
        cutAlpha->setValue(0.05); // keys the cut at 0 (the preset's key is at frame 30)
        QCOMPARE(tracks[1].keys.front().frame, 0.0);
        QCOMPARE(tracks[1].keys.front().layer.shape.operations[0].a, 0.05f);
        QCOMPARE(doc->undoStack()->text(doc->undoStack()->index() - 1), QStringLiteral("Change Highlight Operation"));
        panel->setCurrentFrame(30);
        cutAlpha->setValue(-0.05);
        QCOMPARE(doc->data().look.highlights[1].keys.size(), std::size_t(2));
        panel->setCurrentFrame(15);
        QCOMPARE(doc->currentFrame(), 15); // one playhead: the viewport shows the document at it
        waitForRender(vp);
        keepScreenshot(&window, "highlight-2-frame15");

        // 4. The offline renderer at 0, 15 and 30: highlights on the ear, moving with the keys.
        const model::Camera camera = vp->camera();
        algo::RenderCache cache;
        // The viewport's aspect, so that widget positions scale to the render's pixels.
        const int height = int(std::lround(480.0 * vp->height() / vp->width()));
        auto masks = [&](int frame) {
            return model::renderShape(doc->data(), doc->data().look, doc->data().baseMesh->vertices, frame, camera, 480,
                height, algo::StereoOutput::Off, cache)
                .highlights;
        };
        const std::vector<float> mask0 = masks(0), mask15 = masks(15), mask30 = masks(30);
        const Coverage at0 = coverage(mask0, 480), at15 = coverage(mask15, 480), at30 = coverage(mask30, 480);
        QVERIFY2(at0.area > 30 && at15.area > 30 && at30.area > 30,
            qPrintable(QStringLiteral("%1 %2 %3").arg(at0.area).arg(at15.area).arg(at30.area)));
        int changed = 0;
        for (std::size_t i = 0; i < mask0.size(); ++i)
            changed += (mask0[i] > 0.5f) != (mask30[i] > 0.5f);
        QVERIFY2(changed > at0.area / 4, qPrintable(QStringLiteral("%1 of %2").arg(changed).arg(at0.area)));
        // On the ear: the highlights' centre lies within the ear's projection.
        const QPointF earOnScreen = vp->projectToWidget(kEarCentre);
        const double scale = 480.0 / vp->width();
        QVERIFY2(std::hypot(at15.cx - earOnScreen.x() * scale, at15.cy - earOnScreen.y() * scale) < 0.2 * 480,
            qPrintable(QStringLiteral("%1,%2").arg(at15.cx).arg(at15.cy)));

        // 5. Saved, then rendered frame by frame from the command line.
        QTemporaryDir dir;
        const QString project = dir.filePath(QStringLiteral("examples.celform"));
        doc->saveAs(project);
        if (const QString keep = qEnvironmentVariable("CELFORM_SCREENSHOT_DIR"); !keep.isEmpty())
            QFile::copy(project, keep + QStringLiteral("/highlight-examples.celform"));
        QProcess render;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        render.setProcessEnvironment(env);
        render.start(QStringLiteral(CELFORM_EXECUTABLE),
            {QStringLiteral("render"), project, QStringLiteral("--frames"), QStringLiteral("0-29"),
                QStringLiteral("--size"), QStringLiteral("320x180"), QStringLiteral("--out"),
                dir.filePath(QStringLiteral("frame_####.png"))});
        QVERIFY(render.waitForFinished(120000));
        QVERIFY2(render.exitCode() == 0, render.readAllStandardError().constData());
        for (int f = 0; f < 30; ++f)
            QVERIFY(!QImage(dir.filePath(QStringLiteral("frame_%1.png").arg(f, 4, 10, QLatin1Char('0')))).isNull());
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    QApplication app(argc, argv);
    app.setApplicationName(QStringLiteral("CelformTest"));
    TestHighlightExamples test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_highlight_examples.moc"
