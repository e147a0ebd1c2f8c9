// Focal points in the editor (issue 26, thesis 6.2), driven through the real window under Xvfb:
// Look > Focal Points > Paint Focal Points puts the patch tool in its importance mode; a drag over
// the sample's hind leg lowers those faces' importance in one undo step, the tint shows them, and
// undo gives every face importance 1 again.
#include "test_meshes.h"
#include "test_support.h"
#include "window_test_support.h"

#include "celform/model/document/document.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QStandardPaths>
#include <QUndoStack>

using namespace celform;
using views::Viewport;

class TestFocalPointsUi : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void paintingFocalPointsIsOneUndoStep()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        Viewport* vp = window.viewport();
        const algo::TriMesh& mesh = *doc->data().baseMesh;
        QVERIFY(doc->data().faceImportance.empty());
        QAction* paint = window.action(QStringLiteral("actionPaintFocalPoints"));
        QVERIFY(paint && paint->isCheckable());
        QVERIFY(!paint->toolTip().isEmpty());
        paint->trigger();
        QCOMPARE(vp->tool(), Viewport::Tool::Patch);
        views::PatchTool& tool = vp->tool<views::PatchTool>();
        QCOMPARE(tool.mode(), views::PatchTool::Mode::Importance);
        tool.setImportance(0.f);
        tool.setStrength(0.5f);

        const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
        model::Camera side;
        side.target = box.center();
        side.eye = box.center() + Eigen::Vector3d(0.0, 0.1, 2.5) * box.diagonal().norm();
        side.up = Eigen::Vector3d::UnitY();
        vp->setCamera(side);
        test::waitForRender(vp);
        const std::uint32_t leg = test::elephantHindLegVertex(mesh);
        const QPoint at = vp->projectToWidget(mesh.vertices.row(leg).transpose().cast<double>()).toPoint();
        QVERIFY2(vp->rect().contains(at) && vp->pickVertex(at) >= 0, "the hind leg is not under the cursor");
        const int steps = doc->undoStack()->index();
        test::drag(vp, Qt::LeftButton, Qt::NoModifier, at, at + QPoint(0, -8), 3);
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Paint Focal Points"));
        const std::vector<float>& importance = doc->data().faceImportance;
        QCOMPARE(importance.size(), std::size_t(mesh.faceCount()));
        std::size_t half = 0, other = 0;
        for (const float v : importance)
            (v == 0.5f ? half : other) += 1;
        qInfo("focal points: %zu faces at 0.5 after one drag, %zu at 1", half, other);
        QVERIFY(half > 0);
        QCOMPARE(half + other, importance.size()); // once per stroke: no face went further
        test::waitForRender(vp);
        test::keepScreenshot(&window, "focal-points");

        // Choosing the patch again (the Highlights dock's Paint) leaves the importance mode.
        paint->trigger();
        QCOMPARE(vp->tool(), Viewport::Tool::Navigate);
        doc->undoStack()->undo();
        QVERIFY(doc->data().faceImportance.empty());
    }
};

QTEST_MAIN(TestFocalPointsUi)
#include "test_focal_points_ui.moc"
