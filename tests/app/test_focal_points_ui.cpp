// Focal points and the segment brush in the editor (issue 26, thesis 6.2), driven through the real
// window under Xvfb: Look > Focal Points > Paint Focal Points puts the patch tool in its importance
// mode; a drag over the sample's hind leg lowers those faces' importance in one undo step, the
// tint shows them, and undo gives every face importance 1 again. Look > Segment Brush splits a
// segment along a drag and merges two with two clicks.
#include "test_meshes.h"
#include "test_support.h"
#include "window_test_support.h"

#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/document/document.h"
#include "celform/model/render/render_job.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/viewport.h"

#include <QAction>
#include <QStandardPaths>
#include <QUndoStack>

#include <algorithm>
#include <numeric>

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

        const QPoint at = test::aimAtElephantHindLeg(vp, mesh);
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

    // The segment brush (Look > Segment Brush): a drag across the largest segment of the picture's
    // depth analysis splits it, two clicks merge two segments; each one undo step.
    void segmentBrushSplitsAndMerges()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        Viewport* vp = window.viewport();
        test::waitForRender(vp);
        // The picture the tool analyses: the viewport's camera at the widget's size.
        auto analyse = [doc, vp] {
            model::RenderJob job;
            job.camera = vp->camera();
            job.firstFrame = job.lastFrame = doc->currentFrame();
            job.size = vp->size();
            return model::analyseProject(doc->data(), QString(), job, {});
        };
        // A pixel of segment s, the one nearest its centroid.
        auto inside = [](const model::FrameAnalysis& a, int s) {
            const algo::SegmentLabels& l = a.analysis.segments;
            const Eigen::Vector2f c = a.analysis.stats[std::size_t(s)].centroid;
            QPoint best;
            float nearest = 1e30f;
            for (int y = 0; y < l.height; ++y)
                for (int x = 0; x < l.width; ++x)
                    if (l.labels[std::size_t(y) * std::size_t(l.width) + std::size_t(x)] == s) {
                        const float d = (Eigen::Vector2f(float(x) + 0.5f, float(y) + 0.5f) - c).squaredNorm();
                        if (d < nearest) {
                            nearest = d;
                            best = QPoint(x, y);
                        }
                    }
            return best;
        };
        const model::FrameAnalysis before = analyse();
        const std::size_t count = before.analysis.stats.size();
        QVERIFY(count >= 3);
        std::vector<int> bySize(count);
        std::iota(bySize.begin(), bySize.end(), 0);
        std::sort(bySize.begin(), bySize.end(), [&](int a, int b) {
            return before.analysis.stats[std::size_t(a)].pixels > before.analysis.stats[std::size_t(b)].pixels;
        });

        QAction* split = window.action(QStringLiteral("actionSplitSegment"));
        QVERIFY(split && split->isCheckable());
        split->trigger();
        QCOMPARE(vp->tool(), Viewport::Tool::Patch);
        QCOMPARE(vp->tool<views::PatchTool>().mode(), views::PatchTool::Mode::SplitSegment);
        const QPoint at = inside(before, bySize[0]);
        const int steps = doc->undoStack()->index();
        test::drag(vp, Qt::LeftButton, Qt::NoModifier, at - QPoint(6, 0), at + QPoint(6, 0), 4);
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Split Segment"));
        const std::size_t afterSplit = analyse().analysis.stats.size();
        qInfo("segment brush: %zu segments, %zu after splitting the largest", count, afterSplit);
        QVERIFY(afterSplit > count);
        doc->undoStack()->undo();
        QCOMPARE(analyse().analysis.segments.labels, before.analysis.segments.labels);

        QAction* merge = window.action(QStringLiteral("actionMergeSegments"));
        merge->trigger();
        QCOMPARE(vp->tool<views::PatchTool>().mode(), views::PatchTool::Mode::MergeSegments);
        QVERIFY(!split->isChecked());
        const QPoint a = inside(before, bySize[0]), b = inside(before, bySize[1]);
        QTest::mouseClick(vp, Qt::LeftButton, Qt::NoModifier, a);
        QCOMPARE(doc->undoStack()->index(), steps); // the first click only chooses
        QTest::mouseClick(vp, Qt::LeftButton, Qt::NoModifier, b);
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Merge Segments"));
        const model::FrameAnalysis merged = analyse();
        qInfo("segment brush: %zu segments after merging the two largest", merged.analysis.stats.size());
        QVERIFY(merged.analysis.stats.size() < count);
        doc->undoStack()->undo();
        QVERIFY(doc->data().segmentOverrides.empty());
    }
};

QTEST_MAIN(TestFocalPointsUi)
#include "test_focal_points_ui.moc"
