// The falloff brush (paper 1, section 3.1.2): weights, image-plane edits that keep depth, the
// sign of rotation, smoothing, the grid against brute force (random points and the dragon) and
// X-mirror matching.
#include "test_support.h"

#include "celform/algorithms/brush.h"
#include "celform/model/io/mesh_io.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace celform::algo;

Q_DECLARE_METATYPE(ImageFrame)
Q_DECLARE_METATYPE(Eigen::Vector3d)

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A camera frame as the viewport builds it: forward from eye to target, right = forward x up.
ImageFrame frameLookingAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& upHint)
{
    ImageFrame f;
    f.forward = (target - eye).normalized();
    f.right = f.forward.cross(upHint).normalized();
    f.up = f.right.cross(f.forward);
    return f;
}

Positions randomPoints(int count, unsigned seed, float extent = 1.0f)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-extent, extent);
    Positions p(count, 3);
    for (int i = 0; i < count; ++i)
        p.row(i) << u(rng), u(rng), 0.5f * u(rng);
    return p;
}

/// A (2n+1) x (2n+1) grid in the z = 0 plane with unit spacing, two triangles per square.
TriMesh planeGrid(int n)
{
    const int side = 2 * n + 1;
    TriMesh m;
    m.vertices.resize(side * side, 3);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            m.vertices.row(y * side + x) << float(x - n), float(y - n), 0.0f;
    m.faces.resize(2 * (side - 1) * (side - 1), 3);
    int f = 0;
    for (int y = 0; y + 1 < side; ++y)
        for (int x = 0; x + 1 < side; ++x) {
            const int a = y * side + x, b = a + 1, c = a + side, d = c + 1;
            m.faces.row(f++) << a, b, d;
            m.faces.row(f++) << a, d, c;
        }
    return m;
}

void bruteForce(const Positions& p, const Eigen::Vector3d& centre, double radius, std::vector<std::uint32_t>& indices,
    std::vector<float>& distances)
{
    indices.clear();
    distances.clear();
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
        // Same arithmetic as the grid, so vertices exactly on the sphere agree.
        const double d2 = (p.row(i).transpose().cast<double>() - centre).squaredNorm();
        if (d2 <= radius * radius) {
            indices.push_back(std::uint32_t(i));
            distances.push_back(float(std::sqrt(d2)));
        }
    }
}

void compareWithBruteForce(const Positions& p, const VertexGrid& grid, const Eigen::Vector3d& centre, double radius)
{
    std::vector<std::uint32_t> got, expected;
    std::vector<float> gotD, expectedD;
    grid.radiusQuery(centre, radius, got, gotD);
    bruteForce(p, centre, radius, expected, expectedD);
    QCOMPARE(got.size(), expected.size());
    QVERIFY(got == expected);
    QVERIFY(gotD == expectedD);
}

/// Applies displacements to a copy of shape at the selected rows.
Positions applied(const Positions& shape, const BrushSelection& s, const Positions& delta)
{
    Positions out = shape;
    for (std::size_t k = 0; k < s.indices.size(); ++k)
        out.row(s.indices[k]) += delta.row(Eigen::Index(k));
    return out;
}

} // namespace

class TestBrush : public QObject {
    Q_OBJECT
private slots:
    void falloff_data()
    {
        QTest::addColumn<double>("d");
        QTest::addColumn<double>("expected");
        QTest::newRow("centre") << 0.0 << 1.0;
        QTest::newRow("half radius") << 1.5 << 0.25;
        QTest::newRow("radius") << 3.0 << 0.0;
        QTest::newRow("beyond") << 4.5 << 0.0;
    }
    void falloff()
    {
        QFETCH(double, d);
        QFETCH(double, expected);
        QCOMPARE(brushFalloff(d, 3.0), expected);
    }

    // The falloff choices: at d = r/2, t = 1/2: smooth 3t^2 - 2t^3 = 0.5, sphere
    // sqrt(1 - 1/4) = 0.8660..., the paper's 0.25; all 1 at the centre and 0 at the radius.
    void falloffCurves()
    {
        QCOMPARE(brushFalloff(1.5, 3.0, BrushFalloff::Paper), 0.25);
        QCOMPARE(brushFalloff(1.5, 3.0, BrushFalloff::Smooth), 0.5);
        QVERIFY(std::abs(brushFalloff(1.5, 3.0, BrushFalloff::Sphere) - std::sqrt(0.75)) < 1e-15);
        QCOMPARE(brushFalloff(0.75, 3.0, BrushFalloff::Smooth), 0.84375); // t = 3/4: 27/16 - 27/32
        for (const auto curve : {BrushFalloff::Paper, BrushFalloff::Smooth, BrushFalloff::Sphere}) {
            QCOMPARE(brushFalloff(0.0, 3.0, curve), 1.0);
            QCOMPARE(brushFalloff(3.0, 3.0, curve), 0.0);
            QCOMPARE(brushFalloff(4.0, 3.0, curve), 0.0);
        }
        // The profile: weights are strength times the curve, the picked vertex at the strength.
        const Positions p = randomPoints(2000, 4);
        const VertexGrid grid(p);
        const BrushSelection s = selectForBrush(p, grid, 3, 0.4, {BrushFalloff::Sphere, 0.5});
        QVERIFY(s.indices.size() > 5);
        for (std::size_t k = 0; k < s.indices.size(); ++k) {
            const double d = (p.row(s.indices[k]) - p.row(3)).cast<double>().norm();
            const double expected = s.indices[k] == 3 ? 0.5 : 0.5 * brushFalloff(d, 0.4, BrushFalloff::Sphere);
            QVERIFY(std::abs(s.weights[k] - expected) < 1e-6);
        }
    }

    void selectionWeightsFollowFalloff()
    {
        const Positions p = randomPoints(5000, 3);
        const VertexGrid grid(p);
        const double r = 0.3;
        const BrushSelection s = selectForBrush(p, grid, 17, r);
        QCOMPARE(s.picked, 17u);
        QVERIFY(std::is_sorted(s.indices.begin(), s.indices.end()));
        QCOMPARE(s.indices.size(), s.weights.size());
        std::size_t expectedCount = 0;
        for (Eigen::Index i = 0; i < p.rows(); ++i)
            expectedCount += (p.row(i) - p.row(17)).cast<double>().norm() < r ? 1 : 0;
        QCOMPARE(s.indices.size(), expectedCount);
        bool sawPicked = false;
        for (std::size_t k = 0; k < s.indices.size(); ++k) {
            const double d = (p.row(s.indices[k]) - p.row(17)).cast<double>().norm();
            QVERIFY(d < r);
            if (s.indices[k] == 17) {
                sawPicked = true;
                QCOMPARE(s.weights[k], 1.0f);
            } else {
                QVERIFY(std::abs(s.weights[k] - brushFalloff(d, r)) < 1e-6);
            }
        }
        QVERIFY(sawPicked);
        // A zero radius still selects the picked vertex.
        const BrushSelection single = selectForBrush(p, grid, 5, 0.0);
        QCOMPARE(single.indices, std::vector<std::uint32_t>{5});
        QCOMPARE(single.weights, std::vector<float>{1.0f});
    }

    void dragFollowsCursorAndKeepsDepth_data()
    {
        QTest::addColumn<ImageFrame>("frame");
        QTest::addColumn<Eigen::Vector3d>("eye"); // NaN for orthographic: depth is dot(p, forward)
        const double nan = std::numeric_limits<double>::quiet_NaN();
        QTest::newRow("perspective oblique")
            << frameLookingAt({3.0, 2.0, 4.0}, {0.1, -0.2, 0.05}, {0.2, 1.0, 0.1}) << Eigen::Vector3d(3.0, 2.0, 4.0);
        QTest::newRow("perspective from below")
            << frameLookingAt({-1.0, -4.0, 0.5}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}) << Eigen::Vector3d(-1.0, -4.0, 0.5);
        QTest::newRow("orthographic oblique")
            << frameLookingAt({0.0, 0.0, 0.0}, {-0.6, 0.3, -0.74}, {0.3, 0.9, -0.2}) << Eigen::Vector3d(nan, nan, nan);
        QTest::newRow("orthographic axis") << ImageFrame{} << Eigen::Vector3d(nan, nan, nan);
    }
    void dragFollowsCursorAndKeepsDepth()
    {
        QFETCH(ImageFrame, frame);
        QFETCH(Eigen::Vector3d, eye);
        const Positions p = randomPoints(4000, 11);
        const VertexGrid grid(p);
        const std::uint32_t picked = 123;
        const BrushSelection s = selectForBrush(p, grid, picked, 0.4);
        QVERIFY(s.indices.size() > 50);
        const double dx = 0.37, dy = -0.21;
        const Positions delta = brushDrag(s, frame, dx, dy);
        QCOMPARE(delta.rows(), Eigen::Index(s.indices.size()));
        const Positions moved = applied(p, s, delta);
        const Eigen::Vector3d expectedMove = dx * frame.right + dy * frame.up;
        const Eigen::Vector3d actualMove = (moved.row(picked) - p.row(picked)).transpose().cast<double>();
        QVERIFY2((actualMove - expectedMove).norm() < 1e-6, "the picked vertex follows the cursor");
        const Eigen::Vector3d origin = eye.allFinite() ? eye : Eigen::Vector3d::Zero();
        for (const std::uint32_t v : s.indices) {
            const double before = (p.row(v).transpose().cast<double>() - origin).dot(frame.forward);
            const double after = (moved.row(v).transpose().cast<double>() - origin).dot(frame.forward);
            QVERIFY2(std::abs(after - before) < 1e-6, "camera-space depth is kept");
        }
        // Weights scale the image-plane move.
        for (std::size_t k = 0; k < s.indices.size(); ++k) {
            const Eigen::Vector3d d = delta.row(Eigen::Index(k)).transpose().cast<double>();
            QVERIFY((d - double(s.weights[k]) * expectedMove).norm() < 1e-6);
        }
    }

    void pushChangesOnlyDepth()
    {
        const ImageFrame frame = frameLookingAt({2.0, 3.0, -1.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
        const Positions p = randomPoints(2000, 5);
        const BrushSelection s = selectForBrush(p, VertexGrid(p), 9, 0.5);
        const Positions delta = brushPush(s, frame, 0.25);
        for (std::size_t k = 0; k < s.indices.size(); ++k) {
            const Eigen::Vector3d d = delta.row(Eigen::Index(k)).transpose().cast<double>();
            QVERIFY(std::abs(d.dot(frame.right)) < 1e-7);
            QVERIFY(std::abs(d.dot(frame.up)) < 1e-7);
            QVERIFY(std::abs(d.dot(frame.forward) - 0.25 * double(s.weights[k])) < 1e-6);
        }
    }

    void rotateTurnsRightTowardUp_data()
    {
        QTest::addColumn<ImageFrame>("frame");
        QTest::newRow("axis") << ImageFrame{};
        QTest::newRow("oblique") << frameLookingAt({1.0, 2.0, 3.0}, {-0.5, 0.2, 0.1}, {0.1, 0.2, 1.0});
    }
    void rotateTurnsRightTowardUp()
    {
        QFETCH(ImageFrame, frame);
        const Eigen::Vector3d pivot(0.3, -0.2, 0.7);
        Positions shape(4, 3);
        shape.row(0) = pivot.transpose().cast<float>();
        shape.row(1) = (pivot + frame.right).transpose().cast<float>();
        shape.row(2) = (pivot + frame.right + 0.5 * frame.forward).transpose().cast<float>();
        shape.row(3) = (pivot + frame.right).transpose().cast<float>();
        BrushSelection s;
        s.picked = 0;
        s.radius = 2.0;
        s.indices = {0, 1, 2, 3};
        s.weights = {1.0f, 1.0f, 1.0f, 0.5f};
        const Positions moved = applied(shape, s, brushRotate(s, shape, frame, kPi / 2));
        const auto at = [&](int i) { return Eigen::Vector3d(moved.row(i).transpose().cast<double>()); };
        // Counter-clockwise on screen (x right, y up): right goes to up.
        QVERIFY((at(0) - pivot).norm() < 1e-6);
        QVERIFY((at(1) - (pivot + frame.up)).norm() < 1e-6);
        QVERIFY2((at(2) - (pivot + frame.up + 0.5 * frame.forward)).norm() < 1e-6, "depth is kept");
        // Weight 0.5: half the angle.
        const Eigen::Vector3d half = pivot + std::sqrt(0.5) * (frame.right + frame.up);
        QVERIFY((at(3) - half).norm() < 1e-6);
        // For this right-handed frame that is a right-hand rotation about -forward.
        const Eigen::Vector3d viaAxis = pivot + Eigen::AngleAxisd(kPi / 2, -frame.forward) * frame.right;
        QVERIFY((at(1) - viaAxis).norm() < 1e-6);
    }

    void scaleKeepsDepth()
    {
        const ImageFrame frame = frameLookingAt({0.0, 0.0, 5.0}, {0.2, 0.1, 0.0}, {0.0, 1.0, 0.2});
        const Eigen::Vector3d pivot(1.0, 2.0, 3.0);
        const Eigen::Vector3d offset = 2.0 * frame.right - 1.0 * frame.up + 3.0 * frame.forward;
        Positions shape(3, 3);
        shape.row(0) = pivot.transpose().cast<float>();
        shape.row(1) = (pivot + offset).transpose().cast<float>();
        shape.row(2) = (pivot + offset).transpose().cast<float>();
        BrushSelection s;
        s.picked = 0;
        s.indices = {0, 1, 2};
        s.weights = {1.0f, 1.0f, 0.5f};
        const Positions moved = applied(shape, s, brushScale(s, shape, frame, 2.0));
        const auto at = [&](int i) { return Eigen::Vector3d(moved.row(i).transpose().cast<double>()); };
        QVERIFY((at(0) - pivot).norm() < 1e-6);
        QVERIFY((at(1) - (pivot + 4.0 * frame.right - 2.0 * frame.up + 3.0 * frame.forward)).norm() < 1e-5);
        QVERIFY((at(2) - (pivot + 3.0 * frame.right - 1.5 * frame.up + 3.0 * frame.forward)).norm() < 1e-5);
    }

    void smoothingReducesSpike()
    {
        TriMesh m = planeGrid(5);
        const std::uint32_t centre = 5 * 11 + 5;
        m.vertices(centre, 2) = 2.0f;
        const BrushSelection s = selectForBrush(m.vertices, VertexGrid(m.vertices), centre, 2.5);
        const Positions delta = brushSmooth(s, m.vertices, m.faces, 1.0);
        const Positions moved = applied(m.vertices, s, delta);
        // Full strength at the picked vertex: it lands on the average of its 6 neighbours (z = 0).
        QVERIFY(std::abs(moved(centre, 2)) < 1e-6);
        // The neighbours are pulled up a little, never above the old spike.
        float highest = 0.0f;
        for (const std::uint32_t v : s.indices)
            highest = std::max(highest, moved(v, 2));
        QVERIFY(highest < 0.5f);
        // Half strength moves half way; unselected vertices have no row.
        const Positions halfMoved = applied(m.vertices, s, brushSmooth(s, m.vertices, m.faces, 0.5));
        QVERIFY(std::abs(halfMoved(centre, 2) - 1.0f) < 1e-6);
        // A flat neighbourhood does not move in the plane's normal direction.
        TriMesh flat = planeGrid(5);
        const Positions still = brushSmooth(s, flat.vertices, flat.faces, 1.0);
        QVERIFY(still.col(2).cwiseAbs().maxCoeff() < 1e-7);
    }

    // Relax: the smoothing step in each vertex's tangent plane. A vertex pushed
    // sideways in a flat grid goes back towards the average of its ring and stays in the plane;
    // the spike of the test above is left alone (its move is along its normal), so the shape and
    // the silhouette are kept.
    void relaxMovesAlongTheSurface()
    {
        TriMesh m = planeGrid(5);
        const std::uint32_t centre = 5 * 11 + 5;
        const Eigen::RowVector3f rest = m.vertices.row(centre);
        m.vertices(centre, 0) += 0.3f; // off-centre in the plane
        const BrushSelection s = selectForBrush(m.vertices, VertexGrid(m.vertices), centre, 2.5);
        Positions out;
        std::vector<std::int32_t> scratch;
        brushSmooth(s, m.vertices, m.faces, m.vertexFaces(), 1.0, out, scratch, true);
        const Positions moved = applied(m.vertices, s, out);
        QVERIFY(std::abs(moved(centre, 0) - rest.x()) < 0.05f); // back near the ring's average
        QVERIFY(moved.col(2).cwiseAbs().maxCoeff() < 1e-7f); // nothing left the plane

        TriMesh spike = planeGrid(5);
        spike.vertices(centre, 2) = 2.0f;
        brushSmooth(s, spike.vertices, spike.faces, spike.vertexFaces(), 1.0, out, scratch, true);
        const Positions relaxed = applied(spike.vertices, s, out);
        // The tip's normal is +z: its move to the ring's average is all normal, so it stays.
        QVERIFY(std::abs(relaxed(centre, 2) - 2.0f) < 1e-6f);
        brushSmooth(s, spike.vertices, spike.faces, spike.vertexFaces(), 1.0, out, scratch, false);
        QVERIFY(std::abs(applied(spike.vertices, s, out)(centre, 2)) < 1e-6f); // Smooth flattens it
    }

    void radiusQueryMatchesBruteForce()
    {
        Positions p = randomPoints(20000, 21);
        const VertexGrid grid(p);
        std::mt19937 rng(4);
        std::uniform_real_distribution<double> u(-1.2, 1.2);
        for (const double r : {0.0, 0.01, 0.05, 0.2, 0.7, 5.0})
            for (int t = 0; t < 10; ++t)
                compareWithBruteForce(p, grid, {u(rng), u(rng), u(rng)}, r);
        // Exactly on a vertex with radius 0, and far outside the box.
        compareWithBruteForce(p, grid, p.row(7).transpose().cast<double>(), 0.0);
        compareWithBruteForce(p, grid, {50.0, -3.0, 2.0}, 1.0);
        compareWithBruteForce(p, grid, {50.0, -3.0, 2.0}, 60.0);
        // Far outliers must not break the index (or make it scan everything: not checked here).
        p.conservativeResize(p.rows() + 2, 3);
        p.row(p.rows() - 2) << 1e6f, 0.0f, 0.0f;
        p.row(p.rows() - 1) << -1e6f, 1e5f, 3.0f;
        const VertexGrid withOutliers(p);
        for (int t = 0; t < 10; ++t)
            compareWithBruteForce(p, withOutliers, {u(rng), u(rng), u(rng)}, 0.1);
        compareWithBruteForce(p, withOutliers, {1e6, 0.0, 0.0}, 1.0);
        // An explicit cell size gives the same answers.
        const VertexGrid coarse(p, 0.5);
        compareWithBruteForce(p, coarse, {0.1, 0.2, 0.0}, 0.3);
    }

    void nearestMatchesBruteForce()
    {
        const Positions p = randomPoints(3000, 8);
        const VertexGrid grid(p);
        std::mt19937 rng(9);
        std::uniform_real_distribution<double> u(-1.5, 1.5);
        for (int t = 0; t < 200; ++t) {
            const Eigen::Vector3d q(u(rng), u(rng), u(rng));
            double best = std::numeric_limits<double>::infinity();
            std::int64_t bestIndex = -1;
            for (Eigen::Index i = 0; i < p.rows(); ++i) {
                const double d = (p.row(i).transpose().cast<double>() - q).norm();
                if (d < best) {
                    best = d;
                    bestIndex = i;
                }
            }
            QCOMPARE(grid.nearest(q, std::numeric_limits<double>::infinity()), bestIndex);
            QCOMPARE(grid.nearest(q, best * 0.999), std::int64_t(-1));
        }
        QCOMPARE(VertexGrid().nearest({0, 0, 0}, 1.0), std::int64_t(-1));
        QVERIFY(VertexGrid().empty());
        std::vector<std::uint32_t> indices{1};
        std::vector<float> distances{1.0f};
        VertexGrid().radiusQuery({0, 0, 0}, 1.0, indices, distances);
        QVERIFY(indices.empty() && distances.empty());
    }

    void dragonQueriesMatchBruteForce()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/stanford_dragon.ply"));
        const TriMesh dragon = celform::model::importMesh(path).mesh;
        QElapsedTimer timer;
        timer.start();
        const VertexGrid grid(dragon.vertices);
        const qint64 buildNs = timer.nsecsElapsed();
        const Eigen::AlignedBox3d box = boundingBox(dragon.vertices);
        const double diag = box.diagonal().norm();
        for (const std::uint32_t v : {0u, 1000u, 123456u, std::uint32_t(dragon.vertexCount() - 1)})
            for (const double r : {0.002 * diag, 0.03 * diag, 0.1 * diag})
                compareWithBruteForce(dragon.vertices, grid, dragon.vertices.row(v).transpose().cast<double>(), r);
        qInfo("dragon: %lld vertices, grid built in %.1f ms", qlonglong(dragon.vertexCount()), double(buildNs) / 1e6);
    }

    void mirrorMapPairsSymmetricVertices()
    {
        // Random half with x > 0, its mirror image, points on the plane, shuffled; plus one stray.
        std::mt19937 rng(12);
        std::uniform_real_distribution<float> u(0.05f, 1.0f), s(-1.0f, 1.0f);
        std::vector<Eigen::Vector3f> points;
        for (int i = 0; i < 500; ++i) {
            const Eigen::Vector3f q(u(rng), s(rng), s(rng));
            points.push_back(q);
            points.emplace_back(-q.x(), q.y(), q.z());
        }
        for (int i = 0; i < 50; ++i)
            points.emplace_back(0.0f, s(rng), s(rng));
        std::vector<int> order(points.size());
        std::iota(order.begin(), order.end(), 0);
        std::shuffle(order.begin(), order.end(), rng);
        Positions p(Eigen::Index(points.size()) + 1, 3);
        for (std::size_t i = 0; i < points.size(); ++i)
            p.row(Eigen::Index(i)) = points[std::size_t(order[i])].transpose();
        p.row(p.rows() - 1) << 0.5f, 5.0f, 5.0f; // no mirror partner
        const std::vector<std::int32_t> map = mirrorMap(p, 1e-5);
        QCOMPARE(map.size(), std::size_t(p.rows()));
        QCOMPARE(map.back(), -1);
        for (Eigen::Index i = 0; i + 1 < p.rows(); ++i) {
            const std::int32_t j = map[std::size_t(i)];
            QVERIFY(j >= 0);
            QCOMPARE(map[std::size_t(j)], std::int32_t(i)); // pairs map to each other
            QCOMPARE(p(j, 0), -p(i, 0));
            QCOMPARE(p(j, 1), p(i, 1));
            if (p(i, 0) == 0.0f)
                QCOMPARE(j, std::int32_t(i));
        }
    }
};

QTEST_GUILESS_MAIN(TestBrush)
#include "test_brush.moc"
