// Key viewpoints in the document (paper 1, section 3): keys from cameras and drawings, brush
// strokes as single undo steps, imported deformations, and the blended shape.
#include "test_support.h"
#include "test_meshes.h"

#include "celform/algorithms/brush.h"
#include "celform/model/data/blend_evaluator.h"
#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <QTemporaryDir>

using namespace celform;
using namespace celform::model;

using celform::test::octahedron;

namespace {

Camera cameraAt(const Eigen::Vector3d& eye)
{
    Camera c;
    c.eye = eye;
    c.target = Eigen::Vector3d::Zero();
    c.up = std::abs(eye.normalized().y()) > 0.99 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(0, 1, 0);
    return c;
}

} // namespace

class TestKeys : public QObject {
    Q_OBJECT

private:
    Document m_doc;

private slots:
    void init()
    {
        ProjectData data;
        data.baseMesh = octahedron();
        data.baseMeshName = QStringLiteral("octahedron");
        m_doc.reset(std::move(data));
    }

    void keyDirectionComesFromCameraAndCentroid()
    {
        const ObjectId id = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        QVERIFY(m_doc.data().key(id)->direction.isApprox(Eigen::Vector3d(0, 0, 1)));
        // Offset target: the direction still runs from the centroid towards the eye.
        Camera c = cameraAt({3, 0, 4});
        c.target = Eigen::Vector3d(1, 1, 0);
        const ObjectId k2 = m_doc.keys().createKey(QStringLiteral("side"), c);
        QVERIFY(m_doc.data().key(k2)->direction.isApprox(Eigen::Vector3d(0.6, 0, 0.8)));
        QCOMPARE(m_doc.data().key(k2)->offsetsByFrame.count(0), std::size_t(1));
    }

    // DESIGN.md, "Time" (paper 1, section 4.2): offsets keyed at some frames are interpolated per
    // vertex, held outside the keyed range; a vertex missing at a keyed frame is zero there.
    void offsetsOverTime()
    {
        KeyViewpoint key;
        key.offsetsByFrame[0] = SparseOffsets{{1, 2}, {Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(0, 4, 0)}};
        key.offsetsByFrame[10] = SparseOffsets{{1, 3}, {Eigen::Vector3f(3, 0, 0), Eigen::Vector3f(0, 0, 2)}};
        const auto natural = TimeInterpolation::NaturalSpline;
        // Two keyed frames: the natural spline is linear between them.
        const auto mid = ProjectData::offsetsAt(key, 5, natural);
        QVERIFY(!mid.stored);
        QCOMPARE(mid.get()->indices, (std::vector<std::uint32_t>{1, 2, 3}));
        QVERIFY(mid.get()->deltas[0].isApprox(Eigen::Vector3f(2, 0, 0)));
        QVERIFY(mid.get()->deltas[1].isApprox(Eigen::Vector3f(0, 2, 0)));
        QVERIFY(mid.get()->deltas[2].isApprox(Eigen::Vector3f(0, 0, 1)));
        // At and outside the keyed frames: the stored offsets themselves.
        QCOMPARE(ProjectData::offsetsAt(key, 10, natural).stored, &key.offsetsByFrame[10]);
        QCOMPARE(ProjectData::offsetsAt(key, 25, natural).stored, &key.offsetsByFrame[10]);
        QCOMPARE(ProjectData::offsetsAt(key, -4, natural).stored, &key.offsetsByFrame[0]);
        // keyShape follows the project's setting.
        m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}), {}, key.offsetsByFrame[0], 0);
        ObjectId id = m_doc.data().keys.back().id;
        m_doc.keys().setKeyDeformation(id, 10, key.offsetsByFrame[10], QStringLiteral("key 10"));
        const algo::Positions shape = m_doc.data().keyShape(*m_doc.data().key(id), 5);
        QVERIFY(shape.row(1).isApprox(m_doc.data().baseMesh->vertices.row(1) + Eigen::RowVector3f(2, 0, 0)));
    }

    void duplicateDirectionIsRefused()
    {
        m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const ProjectData before = m_doc.data();
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.keys().createKey(QStringLiteral("again"), cameraAt({0, 0, 9})));
        QVERIFY(m_doc.data() == before);
    }

    // A key without a direction (a hand-edited file the blend meets) is named, not numbered.
    void blendNamesAKeyWithoutDirection()
    {
        ProjectData data = m_doc.data();
        KeyViewpoint key;
        key.id = 7;
        key.name = QStringLiteral("lost");
        key.direction = Eigen::Vector3d::Zero();
        data.keys.push_back(key);
        BlendEvaluator blender;
        QString error;
        QVERIFY(!blender.update(data, &error));
        QVERIFY2(error.contains(QStringLiteral("“lost”")), qPrintable(error));
        data.keys.back().direction = Eigen::Vector3d(0, 0, 1);
        QVERIFY(blender.update(data, &error));
    }

    void keyFromDrawingNeedsAlignment()
    {
        Drawing d;
        d.name = QStringLiteral("side drawing");
        d.image = QImage(4, 4, QImage::Format_RGBA8888);
        const ObjectId drawing = m_doc.drawings().addDrawing(d);
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.keys().createKeyFromDrawing(drawing));
        m_doc.drawings().setDrawingCamera(drawing, cameraAt({5, 0, 0}));
        const ObjectId key = m_doc.keys().createKeyFromDrawing(drawing);
        const KeyViewpoint* k = m_doc.data().key(key);
        QVERIFY(k->direction.isApprox(Eigen::Vector3d(1, 0, 0)));
        QCOMPARE(k->drawingIds, std::vector<ObjectId>{drawing});
        QCOMPARE(k->name, QStringLiteral("side drawing"));
        QVERIFY(k->camera == m_doc.data().drawing(drawing)->camera);
    }

    void strokeIsOneUndoStepAndUndoIsExact()
    {
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const ProjectData before = m_doc.data();
        const int count = m_doc.undoStack()->count();
        Gesture g1 = m_doc.beginGesture();
        for (int step = 0; step < 5; ++step) {
            algo::Positions move(2, 3);
            move << 0.1f, 0, 0, 0, 0.05f, 0;
            m_doc.keys().displaceKeyVertices(key, 0, {2, 4}, move, QStringLiteral("Brush"), g1);
        }
        g1.end();
        QCOMPARE(m_doc.undoStack()->count(), count + 1);
        const algo::Positions shape = m_doc.data().keyShape(*m_doc.data().key(key), 0);
        QVERIFY(shape.row(2).isApprox(Eigen::RowVector3f(0.5f, 1, 0)));
        QVERIFY(shape.row(4).isApprox(Eigen::RowVector3f(0, 0.25f, 1)));
        QVERIFY(shape.row(0) == m_doc.data().baseMesh->vertices.row(0));
        const ProjectData after = m_doc.data();
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data() == before);
        m_doc.undoStack()->redo();
        QVERIFY(m_doc.data() == after);
        // A new stroke is a new undo step.
        algo::Positions move(1, 3);
        move << 0, 0, 0.2f;
        Gesture g2 = m_doc.beginGesture();
        m_doc.keys().displaceKeyVertices(key, 0, {4}, move, QStringLiteral("Brush"), g2);
        g2.end();
        QCOMPARE(m_doc.undoStack()->count(), count + 2);
    }

    void brushAlgorithmThroughDocument()
    {
        // The falloff brush of paper 1, section 3.1.2, driven as the command line and viewport do.
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        const KeyViewpoint& k = *m_doc.data().key(key);
        const algo::Positions shape = m_doc.data().keyShape(k, 0);
        const algo::VertexGrid grid(shape);
        const auto selection = algo::selectForBrush(shape, grid, 4, 1.5); // picks (0,0,1)
        const algo::ImageFrame frame{k.camera.right(), k.camera.trueUp(), k.camera.forward()};
        m_doc.keys().displaceKeyVertices(
            key, 0, selection.indices, algo::brushDrag(selection, frame, 0.3, 0.0), QStringLiteral("Brush"));
        const algo::Positions moved = m_doc.data().keyShape(*m_doc.data().key(key), 0);
        // The picked vertex follows exactly; depth (z for this camera) is kept everywhere.
        QVERIFY(moved.row(4).isApprox(Eigen::RowVector3f(0.3f, 0, 1)));
        for (Eigen::Index v = 0; v < moved.rows(); ++v)
            QCOMPARE(moved(v, 2), shape(v, 2));
        // (1, 0, 0) is at distance sqrt(2) from the pick: falloff (1 - sqrt2/1.5)^2.
        const double w = algo::brushFalloff(std::sqrt(2.0), 1.5);
        QVERIFY(std::abs(moved(0, 0) - (1.0 + 0.3 * w)) < 1e-6);
    }

    void mirrorStrokeOnTheElephantMovesTheOtherHindLeg()
    {
        // Issue 24: the elephant faces +x and is roughly (not vertex-exactly) symmetric across z.
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_elephant.off"));
        Document doc;
        doc.reset(newProject(std::make_shared<const algo::TriMesh>(importMesh(path).mesh), QStringLiteral("elephant")));
        const algo::TriMesh& mesh = *doc.data().baseMesh;
        QCOMPARE(doc.data().mirrorPlane, MirrorPlane::Z);
        const std::uint32_t picked = test::elephantHindLegVertex(mesh);
        const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
        const Eigen::Vector3d c = box.center(), size = box.sizes();
        const ObjectId key = doc.keys().createKey(QStringLiteral("side"), cameraAt(c + Eigen::Vector3d(0, 0, 5)));
        auto stroke = [&](MirrorPlane plane, std::size_t& near, std::size_t& far) -> BrushStroke {
            BrushStroke s
                = doc.keys().beginBrushStroke(key, 0, picked, 0.06 * size.norm(), doc.data().key(key)->camera, plane);
            doc.keys().applyBrushStroke(s, {BrushMotion::Drag, 0.0, 0.05});
            doc.keys().endBrushStroke(s);
            near = far = 0;
            for (std::uint32_t v : s.indices)
                (mesh.vertices(v, 2) > c.z() ? near : far) += 1;
            return s;
        };
        std::size_t near = 0, far = 0;
        stroke(MirrorPlane::Off, near, far);
        qInfo("elephant hind leg, vertex %u, no mirror: %zu on its side, %zu on the other", picked, near, far);
        QVERIFY(near > 10);
        QCOMPARE(far, std::size_t(0));
        const BrushStroke mirrored = stroke(MirrorPlane::Z, near, far);
        qInfo("elephant hind leg, Z mirror: %zu on its side, %zu on the other (twin %u)", near, far,
            mirrored.mirrorSelection.picked);
        QVERIFY(!mirrored.twinMissing);
        QVERIFY(far > near / 2); // the triangulation differs between the legs: not as many
        // The twin's selection moves the mirror image of the drag (the camera looks along -z: the
        // reflected up is the same up), and the plane is one undo step to change.
        const int count = doc.undoStack()->count();
        doc.keys().setMirrorPlane(MirrorPlane::X);
        QCOMPARE(doc.data().mirrorPlane, MirrorPlane::X);
        doc.undoStack()->undo();
        QCOMPARE(doc.data().mirrorPlane, MirrorPlane::Z);
        QCOMPARE(doc.undoStack()->count(), count + 1);
    }

    void importDeformation()
    {
        QTemporaryDir dir;
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        algo::TriMesh deformed = *m_doc.data().baseMesh;
        deformed.vertices(4, 2) = 1.5f;
        const QString good = dir.filePath(QStringLiteral("deformed.obj"));
        exportMesh(deformed, good);
        QVERIFY(m_doc.keys().importKeyDeformation(key, importMesh(good), good).isEmpty());
        const SparseOffsets& offsets = m_doc.data().key(key)->offsetsByFrame.at(0);
        QCOMPARE(offsets.indices, std::vector<std::uint32_t>{4});
        QCOMPARE(offsets.deltas.front(), Eigen::Vector3f(0, 0, 0.5f));

        algo::TriMesh small;
        small.vertices = deformed.vertices.topRows(3);
        small.faces.resize(1, 3);
        small.faces << 0, 1, 2;
        const QString bad = dir.filePath(QStringLiteral("small.obj"));
        exportMesh(small, bad);
        const ProjectData before = m_doc.data();
        try {
            m_doc.keys().importKeyDeformation(key, importMesh(bad), bad);
            QFAIL("a mesh with the wrong vertex count was accepted");
        } catch (const IoError& e) {
            QVERIFY(e.message().contains(QStringLiteral("small.obj")));
            QVERIFY(e.message().contains(QStringLiteral("3 vertices")));
        }
        QVERIFY(m_doc.data() == before);
    }

    // Issue 26, fix 1: on an animated base the imported mesh is the shape at the frame, so the
    // deformation is the mesh minus the base AT that frame, not minus the rest pose.
    void importDeformationSubtractsTheBaseAtTheFrame()
    {
        ProjectData data = m_doc.data();
        auto slide = std::make_shared<algo::BaseAnimation>(); // +x one unit per frame
        slide->frameCount = 5;
        algo::Positions delta = algo::Positions::Zero(6, 3);
        delta.col(0).setOnes();
        slide->morphTargets.push_back(delta);
        slide->morphWeights = {0.f, 1.f, 2.f, 3.f, 4.f};
        data.baseAnimation = slide;
        m_doc.reset(std::move(data));
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}), {}, {}, 3);
        algo::Positions scratch;
        MeshImport imported;
        imported.mesh = *m_doc.data().baseMesh;
        imported.mesh.vertices = m_doc.data().basePositions(3, scratch);
        imported.mesh.vertices(4, 2) += 0.5f;
        QVERIFY(m_doc.keys().importKeyDeformation(key, imported, QStringLiteral("k.obj"), 3).isEmpty());
        const SparseOffsets& offsets = m_doc.data().key(key)->offsetsByFrame.at(3);
        QCOMPARE(offsets.indices, std::vector<std::uint32_t>{4});
        QCOMPARE(offsets.deltas.front(), Eigen::Vector3f(0, 0, 0.5f));
    }

    void blendAtKeyIsTheKeyAndBetweenIsBarycentric()
    {
        // Keys at +X, +Y, +Z with distinct offsets on vertex 4; Dummy mode adds the other axes.
        const Eigen::Vector3d dirs[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        ObjectId ids[3];
        for (int i = 0; i < 3; ++i) {
            SparseOffsets o{{4}, {Eigen::Vector3f(float(i + 1), 0, 0)}};
            ids[i] = m_doc.keys().createKey(QStringLiteral("k%1").arg(i), cameraAt(5 * dirs[i]), {}, o);
        }
        algo::Positions shape;
        for (int i = 0; i < 3; ++i) {
            m_doc.blender().shape(m_doc.data(), dirs[i], 0, shape);
            QVERIFY(shape == m_doc.data().keyShape(*m_doc.data().key(ids[i]), 0));
        }
        // The centre of the facet: weights 1/3 each, offset (1 + 2 + 3) / 3 = 2.
        m_doc.blender().shape(m_doc.data(), Eigen::Vector3d(1, 1, 1), 0, shape);
        QVERIFY(std::abs(shape(4, 0) - 2.f) < 1e-5f);
        const BlendResult r = m_doc.blender().weights(m_doc.data(), Eigen::Vector3d(1, 1, 1).normalized());
        QCOMPARE(r.shares.size(), std::size_t(3));
        QVERIFY(std::abs(r.baseShare) < 1e-9);
        // Disabling a key takes it out of the blend: +X becomes the base (dummy) there.
        m_doc.keys().setKeyEnabled(ids[0], false);
        m_doc.blender().shape(m_doc.data(), dirs[0], 0, shape);
        QVERIFY(shape == m_doc.data().baseMesh->vertices);
    }

    void relinkAndRealign()
    {
        Drawing d;
        d.name = QStringLiteral("a");
        const ObjectId drawing = m_doc.drawings().addDrawing(d);
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        m_doc.keys().linkKeyDrawing(key, drawing);
        QCOMPARE(m_doc.data().key(key)->drawingIds, std::vector<ObjectId>{drawing});
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data().key(key)->drawingIds.empty());
        m_doc.keys().setKeyCamera(key, cameraAt({0, 5, 0.001}));
        QVERIFY(m_doc.data().key(key)->direction.y() > 0.99);
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data().key(key)->direction.isApprox(Eigen::Vector3d(0, 0, 1)));
    }

    void brushAtANewFrameStartsFromWhatIsShown()
    {
        // Only frame 0 keyed: frame 3 holds its offsets (paper 1, section 4.2, held outside the
        // keyed range). A push of 0.05 over a held 0.05 stores 0.10, not 0.05.
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        algo::Positions move(1, 3);
        move << 0.05f, 0, 0;
        m_doc.keys().displaceKeyVertices(key, 0, {4}, move, QStringLiteral("Brush"));
        m_doc.keys().displaceKeyVertices(key, 3, {4}, move, QStringLiteral("Brush"));
        const KeyViewpoint& k = *m_doc.data().key(key);
        QCOMPARE(k.offsetsByFrame.size(), std::size_t(2));
        QVERIFY(k.offsetsByFrame.at(3).at(4).isApprox(Eigen::Vector3f(0.10f, 0, 0)));
        // Undo takes the new keyed frame away entirely.
        m_doc.undoStack()->undo();
        QCOMPARE(m_doc.data().key(key)->offsetsByFrame.size(), std::size_t(1));
    }

    void brushBetweenKeyedFramesKeepsTheInterpolatedShape()
    {
        // Frames 0 and 10 keyed differently; a step at 5 on one vertex stores the interpolated
        // offsets of every vertex there, so the shape at 5 changes only where the brush touched.
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        SparseOffsets at0, at10;
        at0.indices = {1, 4};
        at0.deltas = {Eigen::Vector3f(0.2f, 0, 0), Eigen::Vector3f(0, 0.1f, 0)};
        at10.indices = {1, 2};
        at10.deltas = {Eigen::Vector3f(-0.2f, 0, 0), Eigen::Vector3f(0, 0, 0.3f)};
        m_doc.keys().setKeyDeformation(key, 0, at0, QStringLiteral("0"));
        m_doc.keys().setKeyDeformation(key, 10, at10, QStringLiteral("10"));
        const algo::Positions before = m_doc.data().keyShape(*m_doc.data().key(key), 5);
        algo::Positions move(1, 3);
        move << 0, 0.05f, 0;
        m_doc.keys().displaceKeyVertices(key, 5, {2}, move, QStringLiteral("Brush"));
        const KeyViewpoint& k = *m_doc.data().key(key);
        QCOMPARE(k.offsetsByFrame.size(), std::size_t(3));
        const algo::Positions after = m_doc.data().keyShape(k, 5);
        for (Eigen::Index v = 0; v < after.rows(); ++v) {
            if (v == 2)
                QVERIFY(after.row(v).isApprox(before.row(v) + Eigen::RowVector3f(0, 0.05f, 0)));
            else
                QVERIFY(after.row(v) == before.row(v));
        }
        // The other frames are untouched.
        QVERIFY(k.offsetsByFrame.at(0) == at0);
        QVERIFY(k.offsetsByFrame.at(10) == at10);
    }

    void keysSurviveSaveAndOpen()
    {
        QTemporaryDir dir;
        const ObjectId key = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        algo::Positions move(1, 3);
        move << 0.25f, 0, 0;
        m_doc.keys().displaceKeyVertices(key, 0, {4}, move, QStringLiteral("Brush"));
        const QString path = dir.filePath(QStringLiteral("keys.celform"));
        m_doc.saveAs(path);
        Document other;
        other.open(path);
        QVERIFY(other.data() == m_doc.data());
        algo::Positions a, b;
        m_doc.blender().shape(m_doc.data(), Eigen::Vector3d(0.3, 0.2, 1), 0, a);
        other.blender().shape(other.data(), Eigen::Vector3d(0.3, 0.2, 1), 0, b);
        QVERIFY(a == b);
    }
};

QTEST_GUILESS_MAIN(TestKeys)
#include "test_keys.moc"
