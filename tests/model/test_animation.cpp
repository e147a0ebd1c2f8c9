// The animation core: the scene's time, camera paths and the turntable, the animated
// base (paper 1, section 4.1) under the key offsets, the one per-frame evaluation, and the
// project file's format 2. Every expected value is computed by hand in the test.
#include "test_support.h"
#include "test_meshes.h"

#include "celform/algorithms/base_animation.h"
#include "celform/model/document/document.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"

#include <Eigen/Geometry>

#include <QTemporaryDir>

#include <cmath>

using namespace celform;
using namespace celform::model;

using celform::test::octahedron;

namespace {

Camera cameraAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target = Eigen::Vector3d::Zero())
{
    Camera c;
    c.eye = eye;
    c.target = target;
    c.up = Eigen::Vector3d(0, 1, 0);
    return c;
}

/// The whole octahedron sliding along +x, one unit per frame, over frames 0..4: one morph target
/// of (1, 0, 0) everywhere with weight = frame.
std::shared_ptr<algo::BaseAnimation> slide()
{
    auto a = std::make_shared<algo::BaseAnimation>();
    a->frameCount = 5;
    algo::Positions delta(6, 3);
    delta.setZero();
    delta.col(0).setOnes();
    a->morphTargets.push_back(delta);
    a->morphWeights = {0.f, 1.f, 2.f, 3.f, 4.f};
    return a;
}

/// One joint turning about +z by 90 degrees per sample (samples 0 and 1), every vertex on it.
std::shared_ptr<algo::BaseAnimation> spin()
{
    auto a = std::make_shared<algo::BaseAnimation>();
    a->frameCount = 2;
    a->jointCount = 1;
    a->joints.assign(6, {0, 0, 0, 0});
    a->jointWeights.assign(6, Eigen::Vector4f(1, 0, 0, 0));
    algo::SkinMatrix identity = algo::SkinMatrix::Zero();
    identity.leftCols<3>().setIdentity();
    algo::SkinMatrix quarter = algo::SkinMatrix::Zero();
    quarter.leftCols<3>() = Eigen::AngleAxisf(float(M_PI / 2), Eigen::Vector3f::UnitZ()).toRotationMatrix();
    a->skinMatrices = {identity, quarter};
    return a;
}

} // namespace

class TestAnimation : public QObject {
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

    void cameraPathHitsItsKeysAndHoldsOutside()
    {
        CameraPath path;
        path.setKey(10, cameraAt({0, 0, 10}));
        path.setKey(0, cameraAt({0, 0, 5}));
        QCOMPARE(path.keys.front().frame, 0); // sorted on insertion
        QCOMPARE(path.at(0).eye, Eigen::Vector3d(0, 0, 5));
        QCOMPARE(path.at(10).eye, Eigen::Vector3d(0, 0, 10));
        QCOMPARE(path.at(-3).eye, Eigen::Vector3d(0, 0, 5));
        QCOMPARE(path.at(99).eye, Eigen::Vector3d(0, 0, 10));
        // Two keys: the natural spline through two points is the straight line.
        QVERIFY((path.at(5).eye - Eigen::Vector3d(0, 0, 7.5)).norm() < 1e-12);
        // Replacing a key keeps one key per frame.
        path.setKey(10, cameraAt({0, 0, 12}));
        QCOMPARE(int(path.keys.size()), 2);
        QVERIFY(path.hasKey(10));
        QVERIFY(!path.hasKey(5));
        QVERIFY(cameraPathProblem(path).isEmpty());
        CameraPath bad = path;
        bad.keys[1].frame = 0;
        QVERIFY(!cameraPathProblem(bad).isEmpty());
    }

    void turntableIsOneRevolutionAtTheElevation()
    {
        Turntable t;
        t.frames = 24;
        t.elevationDegrees = 30.0;
        t.startFrame = 10;
        const int before = m_doc.undoStack()->count();
        m_doc.animation().makeTurntable(t, 1.0);
        QCOMPARE(m_doc.undoStack()->count(), before + 1);
        const CameraPath& path = m_doc.data().look.cameraPath;
        QCOMPARE(int(path.keys.size()), 24);
        QCOMPARE(path.keys.front().frame, 10);
        QCOMPARE(path.keys.back().frame, 33);
        QCOMPARE(m_doc.data().time.firstFrame, 10);
        QCOMPARE(m_doc.data().time.lastFrame, 33);
        const double distance = path.keys[0].camera.eye.norm(); // the target is the centroid, 0
        for (std::size_t i = 0; i < path.keys.size(); ++i) {
            const Camera& c = path.keys[i].camera;
            QVERIFY(c.target.norm() < 1e-12);
            QVERIFY(std::abs(c.eye.norm() - distance) < 1e-9);
            // 30 degrees above the plane normal to the y axis.
            QVERIFY(std::abs(std::asin(c.eye.y() / distance) * 180.0 / M_PI - 30.0) < 1e-9);
            // 15 degrees round the axis per frame.
            const Eigen::Vector3d next = path.keys[(i + 1) % path.keys.size()].camera.eye;
            const double turn
                = std::atan2(c.eye.z() * next.x() - c.eye.x() * next.z(), c.eye.x() * next.x() + c.eye.z() * next.z());
            QVERIFY(std::abs(std::abs(turn) * 180.0 / M_PI - 15.0) < 1e-9);
        }
        // Angle 0 looks from +z, as the default view does.
        QVERIFY(std::abs(path.keys[0].camera.eye.x()) < 1e-12 && path.keys[0].camera.eye.z() > 0);
        m_doc.undoStack()->undo();
        QVERIFY(m_doc.data().look.cameraPath.empty());
        QCOMPARE(m_doc.data().time, SceneTime{});
        // Refused settings change nothing.
        t.elevationDegrees = 90.0;
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.animation().makeTurntable(t));
        QVERIFY(m_doc.data().look.cameraPath.empty());
    }

    void sceneTimeIsCheckedAndUndoable()
    {
        SceneTime time;
        time.fps = 0.0;
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.animation().setSceneTime(time));
        time.fps = 30.0;
        time.firstFrame = 5;
        time.lastFrame = 4;
        QVERIFY_THROWS_EXCEPTION(EditRefused, m_doc.animation().setSceneTime(time));
        time.lastFrame = 95;
        m_doc.animation().setSceneTime(time);
        QCOMPARE(m_doc.data().time.fps, 30.0);
        QCOMPARE(m_doc.undoStack()->undoText(), QStringLiteral("Change Frame Rate"));
        m_doc.undoStack()->undo();
        QCOMPARE(m_doc.data().time, SceneTime{});
    }

    void cameraKeysAreUndoSteps()
    {
        m_doc.animation().setCameraKey(3, cameraAt({0, 0, 5}));
        m_doc.animation().setCameraKey(9, cameraAt({5, 0, 0}));
        QCOMPARE(int(m_doc.data().look.cameraPath.keys.size()), 2);
        m_doc.animation().removeCameraKey(3);
        QCOMPARE(m_doc.data().look.cameraPath.keys.front().frame, 9);
        m_doc.undoStack()->undo();
        QCOMPARE(int(m_doc.data().look.cameraPath.keys.size()), 2);
        m_doc.animation().clearCameraPath();
        QVERIFY(m_doc.data().look.cameraPath.empty());
        m_doc.undoStack()->undo();
        QCOMPARE(int(m_doc.data().look.cameraPath.keys.size()), 2);
        // Without camera options, the frame's camera is the path's.
        QCOMPARE(cameraAtFrame(m_doc.data(), m_doc.data().look, 9, 1.0).eye, Eigen::Vector3d(5, 0, 0));
        QCOMPARE(cameraAtFrame(m_doc.data(), m_doc.data().look, 0, 1.0).eye, Eigen::Vector3d(0, 0, 5));
    }

    void skinningTurnsTheVerticesByTheJoint()
    {
        const auto a = spin();
        QVERIFY(a->problem(6).empty());
        algo::Positions out;
        a->evaluate(octahedron()->vertices, 1, out);
        // (1, 0, 0) turned 90 degrees about z is (0, 1, 0); (0, 1, 0) is (-1, 0, 0).
        QVERIFY((out.row(0) - Eigen::RowVector3f(0, 1, 0)).norm() < 1e-6f);
        QVERIFY((out.row(2) - Eigen::RowVector3f(-1, 0, 0)).norm() < 1e-6f);
        QVERIFY((out.row(4) - Eigen::RowVector3f(0, 0, 1)).norm() < 1e-6f);
        // Frames past the end hold the last sample; each vertex alone gives the same floats.
        algo::Positions held;
        a->evaluate(octahedron()->vertices, 7, held);
        QCOMPARE(held, out);
        for (Eigen::Index v = 0; v < 6; ++v)
            QCOMPARE(a->evaluateVertex(octahedron()->vertices, 1, v), Eigen::Vector3f(out.row(v).transpose()));
        // A joint index past the joints is refused.
        auto bad = *a;
        bad.joints[3][0] = 4;
        QVERIFY(!bad.problem(6).empty());
    }

    void keyOffsetsRideOnTheAnimatedBase()
    {
        // Key "front" at frame 0: vertex 4 (0, 0, 1) pushed 0.5 further along +z.
        const ObjectId front = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        SparseOffsets offsets;
        offsets.indices = {4};
        offsets.deltas = {Eigen::Vector3f(0, 0, 0.5f)};
        m_doc.keys().setKeyDeformation(front, 0, offsets, QStringLiteral("Push"));
        m_doc.animation().setAnimatedBase(octahedron(), slide(), 25.0, QStringLiteral("slide"));
        QVERIFY(m_doc.data().animated());
        QCOMPARE(m_doc.data().time.fps, 25.0);
        QCOMPARE(m_doc.data().time.lastFrame, 4);
        QCOMPARE(m_doc.undoStack()->undoText(), QStringLiteral("Import Animated Base"));

        // At frame 2 the base sits at x + 2; its centroid is (2, 0, 0). An eye at (2, 0, 5) looks
        // along the key's direction exactly, so the shape is the moved base plus the key's offset.
        FrameEvaluator evaluator;
        QVERIFY(evaluator.prepare(m_doc.data()));
        evaluator.evaluate(m_doc.data(), 2, {2, 0, 5});
        QVERIFY((evaluator.direction() - Eigen::Vector3d(0, 0, 1)).norm() < 1e-12);
        QVERIFY((evaluator.base().row(0) - Eigen::RowVector3f(3, 0, 0)).norm() < 1e-6f);
        QVERIFY((evaluator.shape().row(4) - Eigen::RowVector3f(2, 0, 1.5f)).norm() < 1e-6f);
        QVERIFY((evaluator.shape().row(1) - Eigen::RowVector3f(1, 0, 0)).norm() < 1e-6f);
        // The key's own shape at a frame (what the brush edits) is that frame's base plus offsets.
        const algo::Positions keyed = m_doc.data().keyShape(*m_doc.data().key(front), 3);
        QVERIFY((keyed.row(4) - Eigen::RowVector3f(3, 0, 1.5f)).norm() < 1e-6f);
        QCOMPARE(m_doc.data().baseCentre(3), Eigen::Vector3d(3, 0, 0));

        // One undo step takes the animation, the base and the time back.
        m_doc.undoStack()->undo();
        QVERIFY(!m_doc.data().animated());
        QCOMPARE(m_doc.data().time, SceneTime{});
    }

    void animatedBaseWithTooFewVerticesIsRefused()
    {
        const ObjectId front = m_doc.keys().createKey(QStringLiteral("front"), cameraAt({0, 0, 5}));
        SparseOffsets offsets;
        offsets.indices = {5};
        offsets.deltas = {Eigen::Vector3f(0, 0, 0.5f)};
        m_doc.keys().setKeyDeformation(front, 0, offsets, QStringLiteral("Push"));
        auto small = std::make_shared<algo::TriMesh>(*octahedron());
        small->vertices.conservativeResize(5, 3);
        small->faces.resize(1, 3);
        small->faces << 0, 1, 2;
        auto a = slide();
        a->morphTargets[0].conservativeResize(5, 3);
        const int count = m_doc.undoStack()->count();
        QVERIFY_THROWS_EXCEPTION(
            IoError, m_doc.animation().setAnimatedBase(small, a, 24.0, QStringLiteral("small.glb")));
        QCOMPARE(m_doc.undoStack()->count(), count);
        QVERIFY(!m_doc.data().animated());
        // An animation that does not match its own mesh is refused too.
        QVERIFY_THROWS_EXCEPTION(
            EditRefused, m_doc.animation().setAnimatedBase(octahedron(), a, 24.0, QStringLiteral("x.glb")));
    }

    void projectFileKeepsTimePathAndAnimation()
    {
        QTemporaryDir dir;
        ProjectData data = m_doc.data();
        data.time = SceneTime{30.0, -2, 40};
        data.look.cameraPath.setKey(0, cameraAt({0, 0, 5}));
        data.look.cameraPath.setKey(12, cameraAt({5, 1, 0}, {0, 0.1, 0}));
        auto both = spin();
        both->morphTargets.push_back(algo::Positions::Constant(6, 3, 0.25f));
        both->morphWeights = {0.f, 1.f};
        data.baseAnimation = both;
        const QString path = dir.filePath(QStringLiteral("anim.celform"));
        saveProject(data, path);
        const ProjectData back = loadProject(path);
        QVERIFY(back == data);
        QCOMPARE(back.time.fps, 30.0);
        QCOMPARE(int(back.look.cameraPath.keys.size()), 2);
        QVERIFY(back.animated());
        QCOMPARE(back.baseAnimation->skinMatrices.size(), std::size_t(2));
    }
};

QTEST_GUILESS_MAIN(TestAnimation)
#include "test_animation.moc"
