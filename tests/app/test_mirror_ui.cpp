// Issue 24, item 5: the brush's mirror on the sample elephant, driven through the real window under
// Xvfb. The elephant faces +x and is roughly (not vertex-exactly) symmetric across z: the mirror
// choice marks the detected Z plane, and a stroke on one hind leg moves the other one too. A plane
// with no twin under the brush says so in the status bar.
#include "test_meshes.h"
#include "test_support.h"
#include "window_test_support.h"

#include "celform/model/document/document.h"
#include "celform/views/panels/highlight_panel.h"
#include "celform/views/panels/properties_panel.h"
#include "celform/views/panels/scene_panel.h"
#include "celform/views/viewport/viewport.h"

#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QPushButton>
#include <QToolButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QUndoStack>

using namespace celform;
using views::Viewport;

class TestMirrorUi : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void mirrorStrokeOnTheSampleMovesTheOtherSide()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        Viewport* vp = window.viewport();
        views::PropertiesPanel* props = window.propertiesPanel();
        QVERIFY(doc->hasMesh());
        const algo::TriMesh& mesh = *doc->data().baseMesh;
        // The sample predates the saved plane: it opens with the one detected on its model.
        QCOMPARE(doc->data().mirrorPlane, model::MirrorPlane::Z);
        auto* mirror = props->findChild<QComboBox*>(QStringLiteral("brushMirror"));
        QVERIFY(mirror);
        QCOMPARE(mirror->count(), 4);
        QVERIFY2(mirror->itemText(3).contains(QStringLiteral("detected")), qPrintable(mirror->itemText(3)));
        QCOMPARE(mirror->currentIndex(), 0); // off until the artist asks

        // A key seen from the +z side, where the picked hind leg is; edit it.
        const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
        model::Camera side;
        side.target = box.center();
        side.eye = box.center() + Eigen::Vector3d(0.0, 0.1, 2.5) * box.diagonal().norm();
        side.up = Eigen::Vector3d::UnitY();
        const model::ObjectId key = doc->keys().createKey(QStringLiteral("side"), side);
        window.scenePanel()->select({views::ScenePanel::ItemKind::Key, key});
        props->editKeyButton()->click();
        QCOMPARE(vp->tool(), Viewport::Tool::Brush);
        vp->setCamera(side);
        test::waitForRender(vp);
        const std::uint32_t leg = test::elephantHindLegVertex(mesh);
        const Eigen::Vector3d legPoint = doc->data().keyShape(*doc->data().key(key), 0).row(leg).cast<double>();
        const QPoint at = vp->projectToWidget(legPoint).toPoint();
        QVERIFY2(vp->rect().contains(at) && vp->pickVertex(at) >= 0, "the hind leg is not under the cursor");

        // A stroke moves the vertices whose key shape changed; count them on each side of the plane.
        const double centreZ = box.center().z();
        auto strokeMoves = [&](std::size_t& near, std::size_t& far) {
            const algo::Positions before = doc->data().keyShape(*doc->data().key(key), 0);
            test::drag(vp, Qt::LeftButton, Qt::NoModifier, at, at + QPoint(0, -12), 4);
            const algo::Positions after = doc->data().keyShape(*doc->data().key(key), 0);
            near = far = 0;
            for (Eigen::Index v = 0; v < after.rows(); ++v)
                if (after.row(v) != before.row(v))
                    (mesh.vertices(v, 2) > centreZ ? near : far) += 1;
        };
        std::size_t near = 0, far = 0;
        strokeMoves(near, far);
        qInfo("no mirror: %zu vertices moved on the leg's side, %zu on the other", near, far);
        QVERIFY(near > 0);
        QCOMPARE(far, std::size_t(0));

        // The Z plane (the detected one): the other hind leg moves as well.
        mirror->setCurrentIndex(3);
        QCOMPARE(doc->data().mirrorPlane, model::MirrorPlane::Z);
        strokeMoves(near, far);
        qInfo("Z mirror: %zu vertices moved on the leg's side, %zu on the other", near, far);
        QVERIFY(far > near / 2);
        test::keepScreenshot(&window, "mirror-z");

        // The Y plane has no twin under a foot (the reflection floats above the back): the status
        // bar says so, one undo step sets the plane.
        const int steps = doc->undoStack()->count();
        mirror->setCurrentIndex(2);
        QCOMPARE(doc->data().mirrorPlane, model::MirrorPlane::Y);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        window.statusBar()->clearMessage();
        strokeMoves(near, far);
        qInfo("Y mirror: %zu vertices moved on the leg's side, %zu on the other; status “%s”", near, far,
            qPrintable(window.statusBar()->currentMessage()));
        const auto& twins = mesh.mirrorTwins(1);
        if (twins[leg] < 0)
            QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("no twin")));
        // Off: the brush stops mirroring, the project keeps its plane.
        mirror->setCurrentIndex(0);
        QCOMPARE(doc->data().mirrorPlane, model::MirrorPlane::Y);
    }

    // Patch painting mirrors the same way: the Highlights dock's Mirror button by Paint, one dab on
    // a hind leg paints the other hind leg's faces too, in the same undo step.
    void patchPaintingMirrors()
    {
        app::MainWindow window(app::MainWindow::Mode::Batch);
        QVERIFY(test::showSample(window));
        model::Document* doc = window.document();
        Viewport* vp = window.viewport();
        QCOMPARE(doc->data().mirrorPlane, model::MirrorPlane::Z);
        const algo::TriMesh& mesh = *doc->data().baseMesh;
        auto* panel = window.findChild<views::HighlightPanel*>();
        QVERIFY(panel);
        test::raiseDockOf(panel);
        auto* presets = panel->findChild<QToolButton*>(QStringLiteral("addHighlightPreset"));
        QVERIFY(presets && presets->menu() && !presets->menu()->actions().isEmpty());
        presets->menu()->actions().front()->trigger(); // a layer on a new patch
        auto* mirrorButton = panel->findChild<QToolButton*>(QStringLiteral("highlightPatchMirror"));
        QVERIFY(mirrorButton);
        QVERIFY(!mirrorButton->toolTip().isEmpty());
        mirrorButton->click();
        QVERIFY(mirrorButton->isChecked());
        auto* paint = panel->findChild<QToolButton*>(QStringLiteral("highlightPaintPatch"));
        paint->click();
        QCOMPARE(vp->tool(), Viewport::Tool::Patch);

        const QPoint at = test::aimAtElephantHindLeg(vp, mesh);
        QVERIFY2(vp->rect().contains(at) && vp->pickVertex(at) >= 0, "the hind leg is not under the cursor");
        const int steps = doc->undoStack()->index();
        test::drag(vp, Qt::LeftButton, Qt::NoModifier, at, at + QPoint(0, -6), 2);
        QCOMPARE(doc->undoStack()->index(), steps + 1);
        const QString patch = doc->data().look.highlights.front().patch;
        const algo::FaceSet* set = doc->data().faceSet(patch);
        QVERIFY(set);
        std::size_t near = 0, far = 0;
        const double centreZ = algo::boundingBox(mesh.vertices).center().z();
        for (const std::int32_t f : set->faces)
            (mesh.vertices(mesh.faces(f, 0), 2) > centreZ ? near : far) += 1;
        qInfo("patch mirror: %zu faces on the leg's side, %zu on the other", near, far);
        QVERIFY(near > 0);
        QVERIFY(far >= near / 2);
        test::keepScreenshot(&window, "mirror-patch");
    }
};

QTEST_MAIN(TestMirrorUi)
#include "test_mirror_ui.moc"
