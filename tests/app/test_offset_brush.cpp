// The shading-offset brush in the editor, driven with real mouse events on the real
// viewport: Shift+O picks the tool, a drag over the model is one undo step and raises the offsets
// under the cursor, Ctrl+drag lowers them, the circle shows the radius, and undo restores the
// picture; the Edit menu holds the automatic offsets, smooth and clear.
#include "ui_test_support.h"
#include "window_test_support.h"

#include "editor/main_window.h"

#include "celform/model/document/document.h"
#include "celform/views/tools/brush_cursor.h"
#include "celform/views/tools/offset_brush_tool.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"

#include <QAction>
#include <QUndoStack>

using namespace celform;
using views::Viewport;

using test::showActive;

namespace {

/// The largest base-layer offset among the vertices within radius of a point.
float largestNear(const model::ProjectData& data, const Eigen::Vector3d& point, double radius)
{
    float best = 0.f;
    for (Eigen::Index v = 0; v < data.baseMesh->vertexCount(); ++v)
        if ((data.baseMesh->vertices.row(v).cast<double>().transpose() - point).norm() < radius
            && std::size_t(v) < data.shadingOffsets.size())
            best = std::max(best, std::abs(data.shadingOffsets[std::size_t(v)]));
    return best;
}

} // namespace

class TestOffsetBrush : public QObject {
    Q_OBJECT

private slots:
    void strokeIsOneStepAndPaintsUnderTheCursor()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(showActive(window));
        model::Document* doc = window.document();
        Viewport* viewport = window.viewport();
        QVERIFY(doc->data().shadingOffsets.empty());
        viewport->setFocus();
        QTest::keyClick(viewport, Qt::Key_O, Qt::ShiftModifier);
        QCOMPARE(viewport->tool(), Viewport::Tool::OffsetBrush);
        QVERIFY(window.action(QStringLiteral("actionOffsetBrush"))->isChecked());
        test::waitForRender(viewport);
        const QImage clean = viewport->renderedImage();

        const QPoint c = viewport->projectToWidget(viewport->modelCentre()).toPoint();
        QMouseEvent hover(QEvent::MouseMove, c, viewport->mapToGlobal(c), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &hover);
        QTRY_VERIFY(viewport->tool<views::OffsetBrushTool>().cursorCircle()->isVisible());
        const auto hit = viewport->pickSurface(c);
        QVERIFY(hit);

        const int steps = doc->undoStack()->count();
        viewport->tool<views::OffsetBrushTool>().setStrength(0.3);
        test::drag(viewport, Qt::LeftButton, Qt::NoModifier, c, c + QPoint(12, 4), 8);
        QCOMPARE(doc->undoStack()->count(), steps + 1); // one stroke, one step
        const float painted = largestNear(doc->data(), hit->second, viewport->tool<views::BrushTool>().size().radius());
        QVERIFY2(painted > 0.2f, qPrintable(QString::number(double(painted))));
        test::waitForRender(viewport);
        QVERIFY(viewport->renderedImage() != clean); // the picture shows it
        test::keepScreenshot(&window, "offset-brush-stroke");

        // Ctrl+drag subtracts: a second step, lower values.
        test::drag(viewport, Qt::LeftButton, Qt::ControlModifier, c, c + QPoint(12, 4), 8);
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        QVERIFY(
            largestNear(doc->data(), hit->second, viewport->tool<views::BrushTool>().size().radius() * 0.2) < painted);

        // Undo both: no offsets, the clean picture again.
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QVERIFY(doc->data().shadingOffsets.empty());
        test::waitForRender(viewport);
        QCOMPARE(viewport->renderedImage(), clean);

        // The menu's actions exist with tooltips.
        for (const char* name :
            {"actionAutoOffsets", "actionSmoothOffsets", "actionClearOffsets", "actionOffsetTargetKey"}) {
            QAction* a = window.action(QString::fromLatin1(name));
            QVERIFY2(a && !a->toolTip().isEmpty(), name);
        }
    }
};

QTEST_MAIN(TestOffsetBrush)
#include "test_offset_brush.moc"
