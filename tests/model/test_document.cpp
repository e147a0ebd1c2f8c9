// Document commands: every edit applies, undoes to the exact previous data, and redoes.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/document/face_set_command.h"

#include <QSignalSpy>
#include <QTemporaryDir>

#include <numeric>

using namespace celform;
using namespace celform::model;

namespace {

std::shared_ptr<const algo::TriMesh> tetrahedron(float scale = 1.f)
{
    auto mesh = std::make_shared<algo::TriMesh>();
    mesh->vertices.resize(4, 3);
    mesh->vertices << 0, 0, 0, scale, 0, 0, 0, scale, 0, 0, 0, scale;
    mesh->faces.resize(4, 3);
    mesh->faces << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
    return mesh;
}

Drawing smallDrawing(const QString& name)
{
    Drawing d;
    d.name = name;
    d.imageFormat = QStringLiteral("png");
    d.imageData = QByteArray("not decoded in this test");
    d.image = QImage(8, 4, QImage::Format_RGBA8888);
    d.image.fill(Qt::red);
    return d;
}

KeyViewpoint keyWithOffsets(const QString& name, const Eigen::Vector3d& direction = Eigen::Vector3d(1, 0, 0))
{
    KeyViewpoint k;
    k.name = name;
    k.direction = direction;
    k.camera.eye = Eigen::Vector3d(5, 0, 0);
    k.offsetsByFrame[0] = SparseOffsets{{1, 3}, {Eigen::Vector3f(0.1f, 0, 0), Eigen::Vector3f(0, 0.2f, 0)}};
    return k;
}

} // namespace

class TestDocument : public QObject {
    Q_OBJECT

private:
    Document m_doc;

    void startFresh()
    {
        ProjectData data;
        data.baseMesh = tetrahedron();
        data.baseMeshName = QStringLiteral("tet.off");
        m_doc.reset(std::move(data));
    }

    /// Applies an edit, checks it changed the data, undoes, checks the data is back exactly,
    /// redoes, checks the edited data is back exactly.
    template <typename Edit> ProjectData applyUndoRedo(Edit edit)
    {
        const ProjectData before = m_doc.data();
        const int count = m_doc.undoStack()->count();
        edit();
        const ProjectData after = m_doc.data();
        [&] { QVERIFY2(!(after == before), "the edit changed nothing"); }();
        [&] { QCOMPARE(m_doc.undoStack()->count(), count + 1); }();
        m_doc.undoStack()->undo();
        [&] { QVERIFY2(m_doc.data() == before, "undo did not restore the data"); }();
        m_doc.undoStack()->redo();
        [&] { QVERIFY2(m_doc.data() == after, "redo did not restore the edit"); }();
        return after;
    }

private slots:
    void init() { startFresh(); }

    void resetIsClean()
    {
        QVERIFY(!m_doc.isModified());
        QCOMPARE(m_doc.undoStack()->count(), 0);
    }

    void addDrawing()
    {
        QSignalSpy spy(&m_doc, &Document::changed);
        ObjectId id = 0;
        const ProjectData after
            = applyUndoRedo([&] { id = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("side"))); });
        QCOMPARE(after.drawings.size(), std::size_t(1));
        QCOMPARE(after.drawings.front().id, id);
        QVERIFY(after.nextId > id);
        QVERIFY(spy.count() >= 3);
        QVERIFY(m_doc.isModified());
    }

    void drawingNamesAreUnique()
    {
        m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("side")));
        const ObjectId second = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("side")));
        QCOMPARE(m_doc.data().drawing(second)->name, QStringLiteral("side 2"));
    }

    void removeDrawingUnlinksKeys()
    {
        const ObjectId d = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("front")));
        KeyViewpoint key = keyWithOffsets(QStringLiteral("front key"));
        key.drawingIds = {d};
        const ObjectId k = m_doc.keys().addKey(key);
        const ProjectData after = applyUndoRedo([&] { m_doc.drawings().removeDrawing(d); });
        QVERIFY(after.drawings.empty());
        QVERIFY(after.key(k)->drawingIds.empty());
    }

    void renameDrawing()
    {
        const ObjectId d = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("a")));
        const ProjectData after
            = applyUndoRedo([&] { m_doc.drawings().renameDrawing(d, QStringLiteral("three-quarter")); });
        QCOMPARE(after.drawing(d)->name, QStringLiteral("three-quarter"));
        // An empty name is refused and pushes nothing.
        const int count = m_doc.undoStack()->count();
        m_doc.drawings().renameDrawing(d, QStringLiteral("   "));
        QCOMPARE(m_doc.undoStack()->count(), count);
    }

    void opacityDragIsOneUndoStep()
    {
        const ObjectId d = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("a")));
        const double start = m_doc.data().drawing(d)->opacity;
        const int count = m_doc.undoStack()->count();
        Gesture g1 = m_doc.beginGesture(); // a slider's press
        for (int i = 1; i <= 10; ++i)
            m_doc.drawings().setDrawingOpacity(d, i / 10.0, g1);
        g1.end(); // its release
        QCOMPARE(m_doc.undoStack()->count(), count + 1);
        QCOMPARE(m_doc.data().drawing(d)->opacity, 1.0);
        m_doc.undoStack()->undo();
        QCOMPARE(m_doc.data().drawing(d)->opacity, start);
    }

    void drawingCamera()
    {
        const ObjectId d = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("a")));
        Camera c;
        c.eye = Eigen::Vector3d(0, 0, 10);
        c.projection = Projection::Orthographic;
        const ProjectData after = applyUndoRedo([&] { m_doc.drawings().setDrawingCamera(d, c); });
        QVERIFY(after.drawing(d)->aligned);
        QVERIFY(after.drawing(d)->camera == c);
        // A degenerate camera is refused.
        Camera bad = c;
        bad.target = bad.eye;
        const int count = m_doc.undoStack()->count();
        m_doc.drawings().setDrawingCamera(d, bad);
        QCOMPARE(m_doc.undoStack()->count(), count);
    }

    void keys()
    {
        ObjectId k = 0;
        ProjectData after = applyUndoRedo([&] { k = m_doc.keys().addKey(keyWithOffsets(QStringLiteral("side"))); });
        QCOMPARE(after.keys.size(), std::size_t(1));
        after = applyUndoRedo([&] { m_doc.keys().renameKey(k, QStringLiteral("left side")); });
        QCOMPARE(after.key(k)->name, QStringLiteral("left side"));
        after = applyUndoRedo([&] { m_doc.keys().setKeyEnabled(k, false); });
        QVERIFY(!after.key(k)->enabled);
        after = applyUndoRedo([&] { m_doc.keys().removeKey(k); });
        QVERIFY(after.keys.empty());
    }

    void removeThenUndoKeepsOrder()
    {
        const ObjectId a = m_doc.keys().addKey(keyWithOffsets(QStringLiteral("a"), {1, 0, 0}));
        const ObjectId b = m_doc.keys().addKey(keyWithOffsets(QStringLiteral("b"), {0, 1, 0}));
        const ObjectId c = m_doc.keys().addKey(keyWithOffsets(QStringLiteral("c"), {0, 0, 1}));
        m_doc.keys().removeKey(b);
        m_doc.undoStack()->undo();
        QCOMPARE(m_doc.data().keys.at(0).id, a);
        QCOMPARE(m_doc.data().keys.at(1).id, b);
        QCOMPARE(m_doc.data().keys.at(2).id, c);
    }

    void blendAndLook()
    {
        BlendSettings blend;
        blend.sharpness = 2.5;
        blend.unspecified = UnspecifiedMode::Cosine2;
        applyUndoRedo([&] { m_doc.look().setSharpness(2.5); });
        ProjectData after = applyUndoRedo([&] { m_doc.look().setUnspecifiedMode(UnspecifiedMode::Cosine2); });
        QVERIFY(after.blend == blend);
        Look look;
        look.style = ShadingStyle::Gooch;
        look.light.type = LightType::Point;
        after = applyUndoRedo([&] { m_doc.look().setLook(look); });
        QVERIFY(after.look == look);
    }

    void replaceBaseMesh()
    {
        const ProjectData after
            = applyUndoRedo([&] { m_doc.setBaseMesh(tetrahedron(2.f), QStringLiteral("big.off")); });
        QCOMPARE(after.baseMeshName, QStringLiteral("big.off"));
        QCOMPARE(after.baseMesh->vertices(1, 0), 2.f);
    }

    void replaceBaseMeshRefusesMismatchedKeys()
    {
        m_doc.keys().addKey(keyWithOffsets(QStringLiteral("k"))); // uses vertex 3
        auto small = std::make_shared<algo::TriMesh>();
        small->vertices.resize(3, 3);
        small->vertices.setZero();
        small->vertices(1, 0) = 1;
        small->vertices(2, 1) = 1;
        small->faces.resize(1, 3);
        small->faces << 0, 1, 2;
        const ProjectData before = m_doc.data();
        QVERIFY_THROWS_EXCEPTION(IoError, m_doc.setBaseMesh(small, QStringLiteral("tri.obj")));
        QVERIFY(m_doc.data() == before);
    }

    void faceSetsAreUndoable()
    {
        QSignalSpy changed(&m_doc, &Document::changed);
        ProjectData after = applyUndoRedo([&] {
            m_doc.faceSets().setFaceSet(QStringLiteral("p"), {3, 1, 1}, QStringLiteral("t"));
        });
        QCOMPARE(after.faceSets.size(), std::size_t(1));
        QCOMPARE(after.faceSets[0].faces, (std::vector<std::int32_t>{1, 3})); // sorted, repeats dropped
        QVERIFY(changed.count() >= 3);
        // A paint drag: several steps with one stroke id are one undo step.
        const int count = m_doc.undoStack()->count();
        Gesture g2 = m_doc.beginGesture();
        m_doc.faceSets().setFaceSet(QStringLiteral("p"), {0, 1, 3}, QStringLiteral("paint"), g2);
        m_doc.faceSets().setFaceSet(QStringLiteral("p"), {0, 1, 2, 3}, QStringLiteral("paint"), g2);
        g2.end();
        QCOMPARE(m_doc.undoStack()->count(), count + 1);
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces.size(), std::size_t(4));
        m_doc.undoStack()->undo();
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces, (std::vector<std::int32_t>{1, 3}));
        // Painting dabs: the drag's step holds the net change; a drag that takes back what it
        // added leaves no step, and a drag that adds and takes undoes to the set as it was.
        const int paintStart = m_doc.undoStack()->index();
        FaceSetStroke s3 = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("p"));
        m_doc.faceSets().applyFaceSetStroke(s3, {0, 2}, false);
        m_doc.faceSets().applyFaceSetStroke(s3, {0, 2}, true);
        m_doc.faceSets().endFaceSetStroke(s3);
        QCOMPARE(m_doc.undoStack()->index(), paintStart);
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces, (std::vector<std::int32_t>{1, 3}));
        FaceSetStroke s4 = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("p"));
        m_doc.faceSets().applyFaceSetStroke(s4, {0, 2}, false);
        m_doc.faceSets().applyFaceSetStroke(s4, {1, 2}, true);
        m_doc.faceSets().endFaceSetStroke(s4);
        QCOMPARE(m_doc.undoStack()->index(), paintStart + 1);
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces, (std::vector<std::int32_t>{0, 3}));
        m_doc.undoStack()->undo();
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces, (std::vector<std::int32_t>{1, 3}));
        m_doc.undoStack()->redo();
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces, (std::vector<std::int32_t>{0, 3}));
        m_doc.undoStack()->undo();
        // Bad input is refused with the data unchanged.
        const ProjectData before = m_doc.data();
        QVERIFY_THROWS_EXCEPTION(
            EditRefused, m_doc.faceSets().setFaceSet(QStringLiteral("p"), {4}, QStringLiteral("t")));
        QVERIFY_THROWS_EXCEPTION(
            EditRefused, m_doc.faceSets().setFaceSet(QStringLiteral(" "), {0}, QStringLiteral("t")));
        QVERIFY(m_doc.data() == before);
    }

    // A patch drag of several dabs is one undo step, and its command stores only the faces the
    // drag added and took, not the set.
    void faceSetStrokeIsOneSparseStep()
    {
        ProjectData data;
        data.baseMesh = test::icosphere(3); // 1280 faces
        m_doc.reset(std::move(data));
        std::vector<std::int32_t> start(600);
        std::iota(start.begin(), start.end(), 0);
        m_doc.faceSets().setFaceSet(QStringLiteral("p"), start, QStringLiteral("t"));
        const ProjectData before = m_doc.data();
        const int index = m_doc.undoStack()->index();
        FaceSetStroke stroke = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("p"));
        QVERIFY(stroke.active());
        std::size_t changed = 0;
        for (int dab = 0; dab < 6; ++dab) { // overlapping dabs, half on faces the set holds
            std::vector<std::int32_t> faces;
            for (int f = 590 + 5 * dab; f < 600 + 5 * dab; ++f)
                faces.push_back(f);
            changed += m_doc.faceSets().applyFaceSetStroke(stroke, faces, false);
        }
        changed += m_doc.faceSets().applyFaceSetStroke(stroke, {0, 1, 700}, true); // 700: not in it
        m_doc.faceSets().endFaceSetStroke(stroke);
        QVERIFY(!stroke.active());
        QCOMPARE(changed, std::size_t(25 + 2));
        QCOMPARE(m_doc.undoStack()->index(), index + 1);
        const auto* command = dynamic_cast<const FaceSetCommand*>(m_doc.undoStack()->command(index));
        QVERIFY(command);
        std::vector<std::int32_t> added(25); // 600 .. 624
        std::iota(added.begin(), added.end(), 600);
        QCOMPARE(command->change().added, added);
        QCOMPARE(command->change().removed, (std::vector<std::int32_t>{0, 1}));
        QVERIFY(!command->change().created);
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("p"))->faces.size(), std::size_t(600 + 25 - 2));
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data() == before);
        // A dab after the end is a step of its own no longer: the stroke is closed.
        QCOMPARE(m_doc.faceSets().applyFaceSetStroke(stroke, {900}, false), std::size_t(0));
        QCOMPARE(m_doc.undoStack()->index(), index);
        // A stroke on a missing set makes it in the same step; an empty name is refused.
        FaceSetStroke fresh = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("new"));
        m_doc.faceSets().applyFaceSetStroke(fresh, {5, 3}, false);
        m_doc.faceSets().applyFaceSetStroke(fresh, {4}, false);
        m_doc.faceSets().endFaceSetStroke(fresh);
        QCOMPARE(m_doc.undoStack()->index(), index + 1);
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("new"))->faces, (std::vector<std::int32_t>{3, 4, 5}));
        m_doc.undoStack()->undo();
        QVERIFY(!m_doc.data().faceSet(QStringLiteral("new")));
        QVERIFY_THROWS_EXCEPTION(EditRefused, (void)m_doc.faceSets().beginFaceSetStroke(QStringLiteral(" ")));
        FaceSetStroke bad = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("p"));
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.faceSets().applyFaceSetStroke(bad, {1280}, false));
        QCOMPARE(m_doc.undoStack()->index(), index);
    }

    // Issue 24, item 5: patch painting mirrors as the brushes do. A dab's faces bring the faces
    // whose centroids lie nearest their reflections; on a half model there are none, and the
    // stroke says so.
    void faceSetStrokeMirrors()
    {
        ProjectData data;
        data.baseMesh = test::icosphere(2); // symmetric across x = 0 through its centre
        m_doc.reset(std::move(data));
        const algo::TriMesh& mesh = *m_doc.data().baseMesh;
        auto centroid = [&](std::int32_t f) {
            return Eigen::Vector3d((mesh.vertices.row(mesh.faces(f, 0)) + mesh.vertices.row(mesh.faces(f, 1))
                                       + mesh.vertices.row(mesh.faces(f, 2)))
                                       .transpose()
                                       .cast<double>()
                / 3.0);
        };
        std::vector<std::int32_t> dab;
        for (std::int32_t f = 0; f < mesh.faceCount() && dab.size() < 5; ++f)
            if (centroid(f).x() > 0.3)
                dab.push_back(f);
        QCOMPARE(int(dab.size()), 5);
        const int index = m_doc.undoStack()->index();
        FaceSetStroke stroke = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("m"), MirrorPlane::X);
        QCOMPARE(m_doc.faceSets().applyFaceSetStroke(stroke, dab, false), std::size_t(10));
        QVERIFY(!stroke.twinMissing);
        m_doc.faceSets().endFaceSetStroke(stroke);
        QCOMPARE(m_doc.undoStack()->index(), index + 1);
        const auto& faces = m_doc.data().faceSet(QStringLiteral("m"))->faces;
        for (const std::int32_t f : dab) {
            const Eigen::Vector3d twin = centroid(f).cwiseProduct(Eigen::Vector3d(-1.0, 1.0, 1.0));
            QVERIFY(std::any_of(
                faces.begin(), faces.end(), [&](std::int32_t g) { return (centroid(g) - twin).norm() < 1e-6; }));
        }
        // Ctrl+drag takes the twins out as well.
        FaceSetStroke erase = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("m"), MirrorPlane::X);
        m_doc.faceSets().applyFaceSetStroke(erase, dab, true);
        m_doc.faceSets().endFaceSetStroke(erase);
        QVERIFY(m_doc.data().faceSet(QStringLiteral("m"))->faces.empty());

        // Half a sphere (x >= 0 only): nothing within reach of the reflection.
        algo::TriMesh half = *test::icosphere(2);
        std::vector<Eigen::Vector3i> kept;
        for (Eigen::Index f = 0; f < half.faceCount(); ++f) {
            bool right = true;
            for (int k = 0; k < 3; ++k)
                right = right && half.vertices(half.faces(f, k), 0) >= -1e-6f;
            if (right)
                kept.push_back(half.faces.row(f).transpose());
        }
        half.faces.resize(Eigen::Index(kept.size()), 3);
        for (std::size_t i = 0; i < kept.size(); ++i)
            half.faces.row(Eigen::Index(i)) = kept[i].transpose();
        ProjectData halfData;
        halfData.baseMesh = std::make_shared<algo::TriMesh>(half);
        m_doc.reset(std::move(halfData));
        const algo::TriMesh& h = *m_doc.data().baseMesh;
        std::int32_t far = 0;
        for (std::int32_t f = 0; f < h.faceCount(); ++f)
            if (h.vertices(h.faces(f, 0), 0) > h.vertices(h.faces(far, 0), 0))
                far = f;
        FaceSetStroke lonely = m_doc.faceSets().beginFaceSetStroke(QStringLiteral("m"), MirrorPlane::X);
        m_doc.faceSets().applyFaceSetStroke(lonely, {far}, false);
        m_doc.faceSets().endFaceSetStroke(lonely);
        QVERIFY(lonely.twinMissing);
        QCOMPARE(m_doc.data().faceSet(QStringLiteral("m"))->faces, std::vector<std::int32_t>{far});
    }

    // A highlight drag (moves, a rotation, a scaling) is one undo step; moves are offsets from
    // the press, so the last one decides where the highlight ends.
    void highlightDragIsOneStep()
    {
        HighlightTrack track;
        track.name = QStringLiteral("spot");
        track.setKey(0, algo::HighlightLayer{});
        track.setKey(10, algo::HighlightLayer{});
        const ObjectId id = m_doc.highlights().addHighlightLayers({track}, QStringLiteral("Add")).front();
        const ProjectData before = m_doc.data();
        const int index = m_doc.undoStack()->index();
        using M = HighlightMotion;
        HighlightDrag drag = m_doc.highlights().beginHighlightDrag(id, 10);
        m_doc.highlights().applyHighlightDrag(drag, {M::Move, 0.1, 0.2});
        m_doc.highlights().applyHighlightDrag(drag, {M::Move, 0.3, -0.1});
        m_doc.highlights().applyHighlightDrag(drag, {M::Rotate, 30.0, 0.0});
        m_doc.highlights().applyHighlightDrag(drag, {M::Scale, 0.25, 0.0});
        m_doc.highlights().applyHighlightDrag(drag, {M::Scale, 2.0, 0.0}); // kept at 1
        m_doc.highlights().applyHighlightDrag(drag, {M::Move, 0.4, 0.1});
        m_doc.highlights().endHighlightDrag(drag);
        QCOMPARE(m_doc.undoStack()->index(), index + 1);
        const HighlightTrack& t = *m_doc.data().highlight(id);
        const Eigen::Vector2d moved = t.translationAt(10);
        QVERIFY2((moved - Eigen::Vector2d(0.4, 0.1)).norm() < 1e-5,
            qPrintable(QStringLiteral("%1, %2").arg(moved.x()).arg(moved.y())));
        QCOMPARE(t.translationAt(0), Eigen::Vector2d(Eigen::Vector2d::Zero())); // only frame 10's key
        for (const auto& k : t.keys) // every key has the operations, so that they interpolate
            QCOMPARE(k.layer.shape.operations.size(), std::size_t(3));
        const auto& ops = t.layerAt(10).shape.operations;
        QCOMPARE(ops.back().type, algo::HighlightOperationType::DirectionalScaling);
        QCOMPARE(ops.back().a, 1.0f);
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data() == before);
        // A second drag is a second step; a missing layer is refused.
        HighlightDrag again = m_doc.highlights().beginHighlightDrag(id, 0);
        m_doc.highlights().applyHighlightDrag(again, {M::Rotate, 5.0, 0.0});
        m_doc.highlights().endHighlightDrag(again);
        m_doc.highlights().applyHighlightDrag(again, {M::Rotate, 5.0, 0.0}); // ended: nothing
        QCOMPARE(m_doc.undoStack()->index(), index + 1);
        QCOMPARE(m_doc.data().highlight(id)->layerAt(0).shape.operations.front().a, 5.0f);
        QVERIFY_THROWS_EXCEPTION(EditRefused, (void)m_doc.highlights().beginHighlightDrag(987654, 0));
    }

    void renameAndRemoveFaceSetFollowLayers()
    {
        m_doc.faceSets().setFaceSet(QStringLiteral("ear"), {0, 1}, QStringLiteral("t"));
        HighlightTrack track;
        track.name = QStringLiteral("shine");
        track.patch = QStringLiteral("ear");
        track.setKey(0, algo::HighlightLayer{});
        m_doc.highlights().addHighlightLayers({track}, QStringLiteral("Add"));

        ProjectData after
            = applyUndoRedo([&] { m_doc.faceSets().renameFaceSet(QStringLiteral("ear"), QStringLiteral("left ear")); });
        QVERIFY(after.faceSet(QStringLiteral("left ear")) && !after.faceSet(QStringLiteral("ear")));
        QCOMPARE(after.look.highlights[0].patch, QStringLiteral("left ear"));
        m_doc.faceSets().setFaceSet(QStringLiteral("other"), {2}, QStringLiteral("t"));
        QVERIFY_THROWS_EXCEPTION(
            EditRefused, m_doc.faceSets().renameFaceSet(QStringLiteral("left ear"), QStringLiteral("other")));

        after = applyUndoRedo([&] { m_doc.faceSets().removeFaceSet(QStringLiteral("left ear")); });
        QVERIFY(!after.faceSet(QStringLiteral("left ear")));
        QVERIFY(after.look.highlights[0].patch.isEmpty()); // back to all faces
        QCOMPARE(m_doc.faceSets().uniqueFaceSetName(QStringLiteral("other")), QStringLiteral("other 2"));
    }

    void replacingTheMeshDropsPatchesOfOtherFaces()
    {
        m_doc.faceSets().setFaceSet(QStringLiteral("p"), {0}, QStringLiteral("t"));
        // Same face count: the patches stay.
        m_doc.setBaseMesh(tetrahedron(2.f), QStringLiteral("big.off"));
        QVERIFY(m_doc.data().faceSet(QStringLiteral("p")));
        auto pyramid = std::make_shared<algo::TriMesh>(*tetrahedron());
        pyramid->faces.conservativeResize(3, 3);
        const ProjectData after = applyUndoRedo([&] { m_doc.setBaseMesh(pyramid, QStringLiteral("three.off")); });
        QVERIFY(after.faceSets.empty());
    }

    void editsMergeOnlyWithinAGestureOnTheSameProperty()
    {
        // DESIGN.md, "The document": a command merges only with the next command of the same
        // property on the same target in the same gesture; two different edits are two steps.
        QUndoStack* stack = m_doc.undoStack();
        const int start = stack->count();
        QSignalSpy changes(&m_doc, &Document::changed);
        Gesture g3 = m_doc.beginGesture();
        m_doc.look().setShadingStyle(ShadingStyle::Gooch, -1, g3);
        m_doc.look().setShowLines(false, g3);
        for (int i = 1; i <= 3; ++i) {
            Light light = m_doc.data().look.light;
            light.vector = Eigen::Vector3d(0.1 * i, 0.6, 0.7).normalized();
            m_doc.look().setLight(light, g3);
        }
        Camera camera;
        camera.eye = Eigen::Vector3d(0, 0, 4);
        m_doc.look().setRenderCamera(camera, g3);
        g3.end();
        QCOMPARE(stack->count(), start + 4);
        QCOMPARE(stack->text(start), QStringLiteral("Change Shading Style"));
        QCOMPARE(stack->text(start + 1), QStringLiteral("Hide Lines"));
        QCOMPARE(stack->text(start + 2), QStringLiteral("Move Light"));
        QCOMPARE(stack->text(start + 3), QStringLiteral("Set Render Camera"));
        QCOMPARE(changes.count(), 6); // one notification per edit, merged or not
        for (const auto& args : changes)
            QVERIFY(args.at(0).value<ChangeSet>().has(Part::Look));
        // Undo takes back the render camera only, then the whole light drag.
        stack->undo();
        QVERIFY(!m_doc.data().look.renderCamera);
        QVERIFY(m_doc.data().look.light.vector.isApprox(Eigen::Vector3d(0.3, 0.6, 0.7).normalized()));
        stack->undo();
        QVERIFY(m_doc.data().look.light.vector.isApprox(Light{}.vector));
        QVERIFY(!m_doc.data().look.showLines);

        // Outside a gesture, the same property twice is two steps.
        const int blendStart = stack->index(); // the two steps undone above go with the next push
        m_doc.look().setSharpness(2.0);
        m_doc.look().setSharpness(3.0);
        m_doc.look().setUnspecifiedMode(UnspecifiedMode::Cosine);
        QCOMPARE(stack->count(), blendStart + 3);
        // In one gesture, the same property on another target is another step; a gesture that
        // comes back to where it began leaves no step.
        const ObjectId a = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("a")));
        const ObjectId b = m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("b")));
        const int drawingStart = stack->count();
        Gesture g4 = m_doc.beginGesture();
        m_doc.drawings().setDrawingOpacity(a, 0.2, g4);
        m_doc.drawings().setDrawingOpacity(b, 0.2, g4);
        g4.end();
        QCOMPARE(stack->count(), drawingStart + 2);
        Gesture g5 = m_doc.beginGesture();
        m_doc.drawings().setDrawingOpacity(a, 0.9, g5);
        m_doc.drawings().setDrawingOpacity(a, 0.2, g5);
        g5.end();
        QCOMPARE(stack->count(), drawingStart + 2);
        QCOMPARE(m_doc.data().drawing(a)->opacity, 0.2);
    }

    void playheadIsNotAnEdit()
    {
        QSignalSpy changes(&m_doc, &Document::changed);
        m_doc.setCurrentFrame(12);
        QCOMPARE(m_doc.currentFrame(), 12);
        QCOMPARE(changes.count(), 1);
        const auto change = changes.front().at(0).value<ChangeSet>();
        QVERIFY(change.onlyPlayhead());
        QCOMPARE(change.frames, std::vector<int>{12});
        QVERIFY(!m_doc.isModified());
        QCOMPARE(m_doc.undoStack()->count(), 0);
        m_doc.setCurrentFrame(12); // no move, no notification
        QCOMPARE(changes.count(), 1);
        // Saved with the project.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("frame.celform"));
        m_doc.saveAs(path);
        Document other;
        other.open(path);
        QCOMPARE(other.currentFrame(), 12);
    }

    void cleanStateFollowsUndo()
    {
        QSignalSpy clean(m_doc.undoStack(), &QUndoStack::cleanChanged);
        m_doc.drawings().addDrawing(smallDrawing(QStringLiteral("a")));
        QVERIFY(m_doc.isModified());
        m_doc.undoStack()->undo();
        QVERIFY(!m_doc.isModified());
        QCOMPARE(clean.count(), 2);
    }
};

QTEST_GUILESS_MAIN(TestDocument)
#include "test_document.moc"
