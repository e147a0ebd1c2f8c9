// Direct manipulation of a highlight layer in the viewport (Highlights dock, "Edit in Viewport"):
// a drag on an icosphere keys a translation at the current frame in the drag's direction, as one
// undo step; painting a layer's patch with the Patch tool.
#include "celform/model/document/document.h"
#include "celform/views/panels/highlight_panel.h"
#include "celform/views/viewport/viewport.h"
#include "celform/views/tools/brush_size.h"
#include "celform/views/tools/brush_tool.h"
#include "celform/views/tools/highlight_tool.h"
#include "celform/views/tools/patch_tool.h"
#include "celform/views/viewport/viewport_display.h"

#include "test_meshes.h"

#include <QApplication>
#include <QMouseEvent>
#include <QPushButton>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest/QtTest>

#include <memory>

using celform::algo::HighlightOperationType;
using celform::model::Document;
using celform::views::HighlightPanel;
using celform::views::Viewport;

/// What the editor window does: the dock's targets go to the viewport's tools.
void connectTargets(HighlightPanel& panel, Viewport& view)
{
    QObject::connect(&panel, &HighlightPanel::highlightTargetChosen, &view,
        [&view](celform::model::ObjectId layer) { view.tool<celform::views::HighlightTool>().setTarget(layer); });
    QObject::connect(&panel, &HighlightPanel::patchTargetChosen, &view,
        [&view](const QString& faceSet) { view.tool<celform::views::PatchTool>().setTarget(faceSet); });
}

class TestHighlightDrag : public QObject {
    Q_OBJECT

    void drag(Viewport* view, QPoint from, QPoint to, Qt::KeyboardModifiers mods = Qt::NoModifier)
    {
        QMouseEvent press(
            QEvent::MouseButtonPress, from, view->mapToGlobal(from), Qt::LeftButton, Qt::LeftButton, mods);
        QApplication::sendEvent(view, &press);
        for (int i = 1; i <= 10; ++i) {
            const QPoint p = from + (to - from) * i / 10;
            QMouseEvent move(QEvent::MouseMove, p, view->mapToGlobal(p), Qt::NoButton, Qt::LeftButton, mods);
            QApplication::sendEvent(view, &move);
        }
        QMouseEvent release(QEvent::MouseButtonRelease, to, view->mapToGlobal(to), Qt::LeftButton, Qt::NoButton, mods);
        QApplication::sendEvent(view, &release);
    }

    /// A unit icosphere with one highlight layer "spot" keyed at the given frames, shown in the
    /// viewport from +Z (5.5 units away, 30 degree field of view) and drawn once.
    void showSphereWithLayer(Document& doc, Viewport& view, const std::vector<double>& keyFrames)
    {
        celform::model::ProjectData data;
        data.baseMesh = celform::test::icosphere(4);
        celform::model::HighlightTrack track;
        track.name = QStringLiteral("spot");
        for (const double frame : keyFrames)
            track.setKey(frame, celform::algo::HighlightLayer{});
        data.look.highlights.push_back(track);
        doc.reset(std::move(data));
        view.display().setLightGizmoVisible(false);
        view.resize(400, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QTRY_VERIFY(view.renderCount() > 0);
        celform::model::Camera camera;
        camera.eye = Eigen::Vector3d(0.0, 0.0, 5.5);
        camera.target = Eigen::Vector3d::Zero();
        camera.up = Eigen::Vector3d::UnitY();
        camera.fovYDegrees = 30.0;
        view.setCamera(camera);
        const int drawn = view.renderCount();
        view.update();
        QTRY_VERIFY(view.renderCount() > drawn);
    }

private slots:
    void dragTranslatesTheSelectedLayer()
    {
        Document doc;
        Viewport view(&doc);
        showSphereWithLayer(doc, view, {0.0, 10.0});
        if (QTest::currentTestFailed())
            return;

        HighlightPanel panel(&doc);
        connectTargets(panel, view);
        panel.setViewport(&view);
        panel.selectLayer(0);
        panel.setCurrentFrame(10);
        auto* edit = panel.findChild<QPushButton*>(QStringLiteral("highlightEditInViewport"));
        QVERIFY(edit && edit->isEnabled());
        edit->click();
        QCOMPARE(view.tool(), Viewport::Tool::Highlight);

        const auto before = doc.data().look;
        const int steps = doc.undoStack()->index();
        // At the front of the sphere the guide (y) gives du = up on screen, dv = n x du = left.
        const QPoint centre = view.projectToWidget(Eigen::Vector3d(0.0, 0.0, 1.0)).toPoint();
        drag(&view, centre, centre + QPoint(40, -30));
        const auto& t = doc.data().look.highlights.front();
        QCOMPARE(t.keys.size(), std::size_t(2));
        for (const auto& k : t.keys) // the operation was added to every key
            QVERIFY(!k.layer.shape.operations.empty()
                && k.layer.shape.operations.front().type == HighlightOperationType::Translation);
        const auto op = t.layerAt(10).shape.operations.front();
        QVERIFY2(op.a > 0.05f && op.b < -0.05f, qPrintable(QStringLiteral("alpha %1 beta %2").arg(op.a).arg(op.b)));
        QCOMPARE(t.layerAt(0).shape.operations.front().a, 0.0f); // only the current frame's key moved
        QCOMPARE(doc.undoStack()->index(), steps + 1); // one drag, one undo step

        // Shift+drag rotates, as another step.
        drag(&view, centre, centre + QPoint(30, 0), Qt::ShiftModifier);
        QCOMPARE(doc.undoStack()->index(), steps + 2);
        QVERIFY(doc.data().look.highlights.front().layerAt(10).shape.operations.size() == 2);

        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(doc.data().look == before);

        edit->click();
        QCOMPARE(view.tool(), Viewport::Tool::Navigate);
    }

    /// Centroid and count of the pure-green pixels (the layer's colour in the test below).
    static std::pair<QPointF, int> greenSpot(Viewport& view)
    {
        const QImage image = view.renderedImage();
        const double dpr = view.devicePixelRatioF();
        double sx = 0.0, sy = 0.0;
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor p = image.pixelColor(x, y);
                if (p.green() > 200 && p.red() < 80 && p.blue() < 80) {
                    sx += x;
                    sy += y;
                    ++n;
                }
            }
        return {n ? QPointF(sx / n / dpr, sy / n / dpr) : QPointF(), n};
    }

    // The grabbed point of the highlight stays under the cursor, for small and
    // large drags alike (a 15 px drag used to make it vanish, a 60 px one to leave the model).
    void dragKeepsTheHighlightUnderTheCursor()
    {
        Document doc;
        Viewport view(&doc);
        showSphereWithLayer(doc, view, {0.0});
        if (QTest::currentTestFailed())
            return;
        celform::algo::HighlightLayer green;
        green.color = {0.0f, 1.0f, 0.0f};
        doc.highlights().setHighlightKey(doc.data().look.highlights.front().id, 0, green);
        HighlightPanel panel(&doc);
        connectTargets(panel, view);
        panel.setViewport(&view);
        panel.selectLayer(0);
        panel.findChild<QPushButton*>(QStringLiteral("highlightEditInViewport"))->click();
        QCOMPARE(view.tool(), Viewport::Tool::Highlight);

        auto render = [&view] {
            const int drawn = view.renderCount();
            view.update();
            QTRY_VERIFY(view.renderCount() > drawn);
        };
        render();
        const auto [start, count] = greenSpot(view);
        QVERIFY2(count > 20, qPrintable(QString::number(count)));
        const int steps = doc.undoStack()->index();
        for (const QPoint shift : {QPoint(15, 0), QPoint(-20, 60)}) {
            const auto [from, n] = greenSpot(view);
            QVERIFY(n > 20);
            drag(&view, from.toPoint(), from.toPoint() + shift);
            render();
            const auto [to, m] = greenSpot(view);
            QVERIFY2(m > 20,
                qPrintable(
                    QStringLiteral("the highlight vanished after a drag of (%1, %2)").arg(shift.x()).arg(shift.y())));
            const QPointF expected = from + QPointF(shift);
            QVERIFY2(QLineF(to, expected).length() < 0.25 * std::hypot(shift.x(), shift.y()) + 3.0,
                qPrintable(QStringLiteral("centre at (%1, %2), cursor at (%3, %4)")
                               .arg(to.x())
                               .arg(to.y())
                               .arg(expected.x())
                               .arg(expected.y())));
        }
        QCOMPARE(doc.undoStack()->index(), steps + 2); // one step per drag
    }

    void paintPatchFromTheDock()
    {
        Document doc;
        Viewport view(&doc);
        showSphereWithLayer(doc, view, {0.0});
        if (QTest::currentTestFailed())
            return;
        view.tool<celform::views::BrushTool>().size().setRadius(0.15);

        HighlightPanel panel(&doc);
        connectTargets(panel, view);
        panel.setViewport(&view);
        panel.selectLayer(0);
        auto* paint = panel.findChild<QToolButton*>(QStringLiteral("highlightPaintPatch"));
        QVERIFY(paint && paint->isEnabled());
        const int steps = doc.undoStack()->index();
        paint->click();
        // A layer on all faces gets a patch of its own first (one undo step), then painting starts.
        QCOMPARE(view.tool(), Viewport::Tool::Patch);
        QCOMPARE(doc.undoStack()->index(), steps + 1);
        const QString patch = doc.data().look.highlights.front().patch;
        QCOMPARE(patch, QStringLiteral("spot patch"));
        QCOMPARE(view.tool<celform::views::PatchTool>().target(), patch);
        QVERIFY(doc.data().faceSet(patch) && doc.data().faceSet(patch)->faces.empty());

        // One drag across the front: faces under the brush, all on the visible side, one step.
        const QPoint left = view.projectToWidget(Eigen::Vector3d(-0.5, 0.0, 0.85)).toPoint();
        const QPoint right = view.projectToWidget(Eigen::Vector3d(0.5, 0.0, 0.85)).toPoint();
        drag(&view, left, right);
        QCOMPARE(doc.undoStack()->index(), steps + 2);
        const auto painted = doc.data().faceSet(patch)->faces;
        QVERIFY2(painted.size() > 20, qPrintable(QString::number(painted.size())));
        const auto& mesh = *doc.data().baseMesh;
        for (const auto f : painted) {
            const Eigen::Vector3f c = (mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1))
                                          + mesh.vertices.row(mesh.faces(f, 2)))
                                          .transpose()
                / 3.f;
            QVERIFY(c.z() > 0.5f && std::abs(c.y()) < 0.35f);
        }
        // The patch is tinted while painting.
        const QImage shot = view.renderedImage();
        const QColor tint = shot.pixelColor(view.projectToWidget(Eigen::Vector3d(0.0, 0.0, 1.0)).toPoint());
        QVERIFY2(tint.red() > tint.blue() + 40, qPrintable(tint.name()));

        // Ctrl+drag over the middle removes faces, as another step; undo gives the drag back.
        const QPoint top = view.projectToWidget(Eigen::Vector3d(0.0, 0.3, 0.95)).toPoint();
        const QPoint bottom = view.projectToWidget(Eigen::Vector3d(0.0, -0.3, 0.95)).toPoint();
        drag(&view, top, bottom, Qt::ControlModifier);
        QCOMPARE(doc.undoStack()->index(), steps + 3);
        QVERIFY(doc.data().faceSet(patch)->faces.size() < painted.size());
        doc.undoStack()->undo();
        QCOMPARE(doc.data().faceSet(patch)->faces, painted);

        paint->click();
        QCOMPARE(view.tool(), Viewport::Tool::Navigate);
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::defaultFormat());
    QApplication app(argc, argv);
    TestHighlightDrag test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_highlight_drag.moc"
