// Apparent ridges (JDA07; paper 3, section 4.2) on surfaces whose view-dependent curvature is
// known in closed form, the snakes of section 4.2.1, and a shared scanned mesh.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/apparent_ridges.h"
#include "celform/algorithms/ridge_depth_scale.h"
#include "celform/algorithms/ridge_snakes.h"
#include "celform/algorithms/tri_mesh.h"
#include "celform/model/io/mesh_io.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

using namespace celform::algo;

namespace {

constexpr double pi = 3.14159265358979323846;

/// Torus around z (test_meshes.h): outward normals.
TriMesh torus(float R, float r, int nu, int nv)
{
    return celform::test::torus(R, r, nu, nv);
}

/// Closed cylinder around z of radius a and height h (z in [0, h]): nu sectors, nz rings on the
/// side, each flat cap in nr concentric rings around its centre; outward faces. The rims are
/// sharp creases.
TriMesh cappedCylinder(float a, float h, int nu, int nz, int nr = 16)
{
    TriMesh m;
    std::vector<Eigen::Vector3f> v;
    std::vector<Eigen::Vector3i> f;
    auto ring = [&](float radius, float z) {
        const int first = int(v.size());
        for (int i = 0; i < nu; ++i) {
            const double u = 2 * pi * i / nu;
            v.emplace_back(float(radius * std::cos(u)), float(radius * std::sin(u)), z);
        }
        return first;
    };
    // quad strip between rings p and q (q "after" p so that p, p+1, q+1 is outward for up = true)
    auto strip = [&](int p, int q, bool flip) {
        for (int i = 0; i < nu; ++i) {
            const int a0 = p + i, a1 = p + (i + 1) % nu, b0 = q + i, b1 = q + (i + 1) % nu;
            if (flip) {
                f.emplace_back(a0, b1, a1);
                f.emplace_back(a0, b0, b1);
            } else {
                f.emplace_back(a0, a1, b1);
                f.emplace_back(a0, b1, b0);
            }
        }
    };
    std::vector<int> side;
    for (int k = 0; k <= nz; ++k)
        side.push_back(ring(a, h * float(k) / float(nz)));
    for (int k = 0; k < nz; ++k)
        strip(side[std::size_t(k)], side[std::size_t(k + 1)], false);
    for (const bool top : {false, true}) {
        const float z = top ? h : 0.f;
        int outer = top ? side.back() : side.front();
        for (int k = nr - 1; k >= 1; --k) {
            const int inner = ring(a * float(k) / float(nr), z);
            strip(outer, inner, !top);
            outer = inner;
        }
        const int centre = int(v.size());
        v.emplace_back(0.f, 0.f, z);
        for (int i = 0; i < nu; ++i) {
            if (top)
                f.emplace_back(outer + i, outer + (i + 1) % nu, centre);
            else
                f.emplace_back(outer + (i + 1) % nu, outer + i, centre);
        }
    }
    m.vertices.resize(Eigen::Index(v.size()), 3);
    for (std::size_t i = 0; i < v.size(); ++i)
        m.vertices.row(Eigen::Index(i)) = v[i].transpose();
    m.faces.resize(Eigen::Index(f.size()), 3);
    for (std::size_t i = 0; i < f.size(); ++i)
        m.faces.row(Eigen::Index(i)) = f[i].transpose();
    return m;
}

RasterCamera orthoCamera(const Eigen::Vector3d& eye, const Eigen::Vector3d& up, double height, int pixels)
{
    RasterCamera c;
    c.eye = eye;
    c.target = Eigen::Vector3d::Zero();
    c.up = up;
    c.orthographic = true;
    c.orthoHeight = height;
    c.width = c.height = pixels;
    return c;
}

LineView lineView(const RasterCamera& c)
{
    LineView v;
    v.eye = c.eye.cast<float>();
    v.direction = c.forward().cast<float>();
    v.orthographic = c.orthographic;
    return v;
}

/// Segments of mesh seen from camera with the given threshold (and the workspace after the call).
RidgeSegments ridges(const TriMesh& mesh, const RasterCamera& camera, float threshold,
    ApparentRidgeWorkspace* keep = nullptr, int threads = 2, const std::vector<float>* thresholdScale = nullptr)
{
    RidgeShapeData data;
    computeRidgeShapeData(mesh.vertices, mesh.faces, data);
    ApparentRidgeOptions options;
    options.threshold = threshold;
    options.featureSize = data.featureSize;
    options.threads = threads;
    options.thresholdScale = thresholdScale;
    ApparentRidgeWorkspace ws;
    RidgeSegments out;
    computeApparentRidges(
        mesh.vertices, mesh.faces, mesh.vertexFaces(), data.curvatures, lineView(camera), options, ws, out);
    if (keep)
        *keep = std::move(ws);
    return out;
}

} // namespace

class TestApparentRidges : public QObject {
    Q_OBJECT
private slots:
    // A torus (R = 2, r = 0.5) seen along its axis, orthographically. Name a point by u (around the
    // axis) and v (around the tube): normal n = (cos v cos u, cos v sin u, sin v), so n.view =
    // sin v and the tangent part of the view vector runs around the tube (along the principal
    // direction of k = 1/r; the other, cos v / (R + r cos v), is perpendicular to the view's
    // tangent part). P shortens the tube direction by sin v, so Q = diag(1 / (r sin v),
    // cos v / (R + r cos v)) and q1 = 1 / (r sin v) >= 2 > 1/(R - r): along t1 (across the tube,
    // radially on screen) q1 falls from the outer contour (v = 0, screen radius R + r = 2.5) to
    // the top of the tube (v = 90 degrees, radius R = 2, q1 = 1/r, a minimum) and rises again to
    // the inner contour (v = 180 degrees, radius R - r = 1.5). Its only maxima are the two contour
    // circles: every ridge point lies near radius 1.5 or 2.5, none near the top of the tube.
    void torusFromAbove()
    {
        const TriMesh m = torus(2.f, 0.5f, 160, 64);
        const RasterCamera camera = orthoCamera({0, 0, 10}, {0, 1, 0}, 6.0, 600);
        ApparentRidgeWorkspace ws;
        const RidgeSegments s = ridges(m, camera, 0.05f, &ws);
        QVERIFY(s.points.size() > 200);
        int outer = 0, inner = 0;
        const float tube = 2.f * float(pi) * 0.5f / 64.f; // edge length across the tube
        for (const Eigen::Vector3f& p : s.points) {
            const float rho = p.head<2>().norm();
            QVERIFY2(std::abs(rho - 2.f) > 0.3f, qPrintable(QStringLiteral("ridge at radius %1").arg(rho)));
            if (std::abs(rho - 2.5f) < 2 * tube)
                ++outer;
            else if (std::abs(rho - 1.5f) < 2 * tube)
                ++inner;
            else
                QFAIL(qPrintable(QStringLiteral("ridge point at radius %1, off both contours").arg(rho)));
        }
        QVERIFY(outer > 100);
        QVERIFY(inner > 50);
        // The analytic q1 on the top of the tube (v = 90 degrees): 1/r.
        Eigen::Index top = 16 * 160; // j = nv / 4
        QVERIFY(std::abs(ws.q1[std::size_t(top)] - 2.f) < 0.1f);
    }

    // A capped cylinder seen obliquely from above (30 degrees over the horizon): the side has
    // q1 = 1/(a cos theta) growing towards its contours, the flat cap has q1 = 0, and the rim, a
    // crease, has the largest curvature of the mesh (its discrete curvature grows as the mesh is
    // refined). So besides the two side contours, the ridges run along the top rim: points at
    // radius a and height h, over the whole near half of the rim (seen in front of the cap).
    void cylinderRim()
    {
        const float a = 1.f, h = 2.f;
        const TriMesh m = cappedCylinder(a, h, 128, 32);
        const double elevation = 30.0 * pi / 180.0;
        const RasterCamera camera = orthoCamera(
            Eigen::Vector3d(0, -10 * std::cos(elevation), 1 + 10 * std::sin(elevation)), {0, 0, 1}, 5.0, 600);
        const RidgeSegments s = ridges(m, camera, 0.3f);
        QVERIFY(!s.points.empty());
        int onRim = 0, nearRimFront = 0;
        for (const Eigen::Vector3f& p : s.points) {
            const bool rim = std::abs(p.z() - h) < 0.1f && std::abs(p.head<2>().norm() - a) < 0.1f;
            if (rim) {
                ++onRim;
                if (p.y() < -0.5f) // the front of the rim, towards the viewer
                    ++nearRimFront;
            }
        }
        QVERIFY2(onRim > 60, qPrintable(QString::number(onRim)));
        QVERIFY(nearRimFront > 20);
    }

    // A sphere's view-dependent curvature is not constant: S = I / r and P^-1 stretches by
    // sec(theta), so q1 = 1 / (r cos theta), smallest facing the viewer and growing monotonically
    // to the contour. There is no maximum inside the silhouette: every ridge point lies at the
    // contour (n.v small), none inside it.
    void sphereOnlyAtContour()
    {
        auto sphere = celform::test::icosphere(5);
        const TriMesh& m = *sphere;
        const RasterCamera camera = orthoCamera({0, 0, 10}, {0, 1, 0}, 3.0, 600);
        const RidgeSegments s = ridges(m, camera, 0.05f);
        for (const Eigen::Vector3f& p : s.points) {
            const float ndotv = p.normalized().z();
            QVERIFY2(ndotv < 0.15f, qPrintable(QStringLiteral("ridge inside the silhouette, n.v %1").arg(ndotv)));
        }
    }

    // Rising thresholds keep a subset of the segments (the test is q1 - threshold > 0 at an end),
    // and a threshold far above every q1 keeps nothing.
    void thresholdRemovesLines()
    {
        const TriMesh m = cappedCylinder(1.f, 2.f, 96, 24);
        const RasterCamera camera = orthoCamera({0, -8.66, 6}, {0, 0, 1}, 5.0, 400);
        std::size_t previous = std::numeric_limits<std::size_t>::max();
        std::vector<std::size_t> counts;
        for (const float t : {0.05f, 0.3f, 1.f, 3.f, 1e6f}) {
            const std::size_t n = ridges(m, camera, t).points.size();
            QVERIFY(n <= previous);
            previous = n;
            counts.push_back(n);
        }
        QVERIFY(counts.front() > counts[2]);
        QCOMPARE(counts.back(), std::size_t(0));
    }

    // Paper 3, section 4.4: a per-vertex factor on the threshold. Lowered on one half of the
    // cylinder, lines appear there and only there; a factor of 1 everywhere changes nothing.
    void perVertexThresholdScale()
    {
        const TriMesh m = cappedCylinder(1.f, 2.f, 96, 24);
        const RasterCamera camera = orthoCamera({0, -8.66, 6}, {0, 0, 1}, 5.0, 400);
        // A threshold far above every q1 * featureSize of this mesh.
        auto run = [&](const std::vector<float>* scale) { return ridges(m, camera, 1e9f, nullptr, 2, scale); };
        QVERIFY(run(nullptr).points.empty());
        const std::vector<float> ones(std::size_t(m.vertexCount()), 1.f);
        QVERIFY(run(&ones).points.empty());
        std::vector<float> leftLow(std::size_t(m.vertexCount()), 1.f);
        for (Eigen::Index v = 0; v < m.vertexCount(); ++v)
            if (m.vertices(v, 0) < -0.2f)
                leftLow[std::size_t(v)] = 0.f;
        const RidgeSegments left = run(&leftLow);
        QVERIFY(left.points.size() > 20);
        for (const Eigen::Vector3f& p : left.points)
            QVERIFY2(p.x() < 0.f, qPrintable(QString::number(p.x())));
    }

    // The result does not depend on the number of threads.
    void deterministicAcrossThreads()
    {
        const TriMesh m = torus(2.f, 0.7f, 90, 40);
        const RasterCamera camera = orthoCamera({3, -6, 4}, {0, 0, 1}, 7.0, 400);
        const RidgeSegments one = ridges(m, camera, 0.1f, nullptr, 1);
        const RidgeSegments two = ridges(m, camera, 0.1f, nullptr, 2);
        QCOMPARE(one.points.size(), two.points.size());
        QVERIFY(one.points == two.points);
        QVERIFY(one.keys == two.keys);
    }

    // Listing 4.4 on hand-made segments: a chain given out of order and with flipped segments is
    // one open snake; a loop is one closed snake; a chain of 5 segments (6 vertices) is dropped;
    // ends 1 px apart join, ends 5 px apart do not; one Laplacian pass moves interior vertices.
    void snakes()
    {
        const RasterCamera camera = orthoCamera({0, 0, 10}, {0, 1, 0}, 100.0, 100); // 1 unit = 1 px
        RidgeSegments s;
        auto add = [&](Eigen::Vector3f p, Eigen::Vector3f q) {
            s.points.push_back(p);
            s.points.push_back(q);
            s.keys.push_back(std::uint32_t(s.keys.size()));
            s.keys.push_back(std::uint32_t(s.keys.size()));
        };
        // Open zigzag chain of 20 segments along x (y alternates 0, 1), in shuffled order, every
        // other one reversed, ends off by 0.5 px.
        std::vector<int> order(20);
        std::iota(order.begin(), order.end(), 0);
        std::reverse(order.begin() + 3, order.end() - 4);
        for (const int i : order) {
            Eigen::Vector3f p(-40.f + 3.f * float(i), float(i % 2), 0.f),
                q(-40.f + 3.f * float(i + 1), float((i + 1) % 2), 0.f);
            q.x() += 0.5f;
            if (i % 2)
                add(q, p);
            else
                add(p, q);
        }
        // A closed square loop of 12 segments around (20, 20).
        std::vector<Eigen::Vector3f> loop;
        for (int k = 0; k < 12; ++k) {
            const double angle = 2 * pi * k / 12;
            loop.emplace_back(float(20 + 8 * std::cos(angle)), float(20 + 8 * std::sin(angle)), 0.f);
        }
        for (int k = 0; k < 12; ++k)
            add(loop[std::size_t(k)], loop[std::size_t((k + 1) % 12)]);
        // A short chain of 5 segments (2 px each, the join distance: ends exactly 2 px apart are
        // not "closer than" it): noise.
        for (int k = 0; k < 5; ++k)
            add({-20.f + 2.f * float(k), -30.f, 0.f}, {-20.f + 2.f * float(k + 1), -30.f, 0.f});
        // Two long chains 5 px apart end to end: not joined.
        for (int k = 0; k < 12; ++k)
            add({-40.f + 2.f * float(k), 30.f, 0.f}, {-40.f + 2.f * float(k + 1), 30.f, 0.f});
        for (int k = 0; k < 12; ++k)
            add({-11.f + 2.f * float(k), 30.f, 0.f}, {-11.f + 2.f * float(k + 1), 30.f, 0.f});

        SnakeWorkspace ws;
        RidgeSnakes out;
        clusterSnakes(s, camera, SnakeOptions(), ws, out);
        int open21 = 0, closed12 = 0, open13 = 0;
        for (const Stroke& stroke : out.strokes) {
            QVERIFY(stroke.vertices.size() >= 10);
            QCOMPARE(stroke.kinds, std::uint8_t(kRidge));
            if (!stroke.closed && stroke.vertices.size() == 21)
                ++open21;
            else if (stroke.closed && stroke.vertices.size() == 12)
                ++closed12;
            else if (!stroke.closed && stroke.vertices.size() == 13)
                ++open13;
        }
        QCOMPARE(out.strokes.size(), std::size_t(4));
        QCOMPARE(open21, 1);
        QCOMPARE(closed12, 1);
        QCOMPARE(open13, 2);
        // The zigzag's vertex k has y = k % 2; one pass moves each interior vertex to the mean of
        // its two neighbours (both at the other parity): y = (k + 1) % 2. The ends stay at 0.
        for (const Stroke& stroke : out.strokes)
            if (stroke.vertices.size() == 21) {
                for (std::size_t i = 1; i + 1 < stroke.vertices.size(); ++i)
                    QCOMPARE(out.points[std::size_t(stroke.vertices[i])].y(), float((i + 1) % 2));
                QCOMPARE(out.points[std::size_t(stroke.vertices.front())].y(), 0.f);
                QCOMPARE(out.points[std::size_t(stroke.vertices.back())].y(), 0.f);
            }
        // Smaller minimum: the short chain appears.
        SnakeOptions all;
        all.minVertices = 2;
        clusterSnakes(s, camera, all, ws, out);
        QCOMPARE(out.strokes.size(), std::size_t(5));
    }

    // Paper 3, section 4.4, by hand: two faces sharing vertices 1 and 2, four covered pixels.
    // Face 0's pixels: at vertex 0 (error 2) and halfway between 1 and 2 (error 0); face 1's: at
    // vertex 3 (error 4) and at vertex 1 (error -2). e_rms = sqrt((4 + 0 + 16 + 4) / 4) = sqrt(6).
    // e_0 = 2, e_1 = (0.5 * 0 + 1 * 2) / 1.5 = 4/3, e_2 = 0, e_3 = 4, vertex 4 unseen.
    // With strength 2: s_v = 1 / (1 + 2 e_v / sqrt(6)).
    void depthErrorScalesTheThreshold()
    {
        Faces faces(2, 3);
        faces << 0, 1, 2, 3, 2, 1;
        GBuffer g;
        g.width = 4;
        g.height = 1;
        g.faceId = {0, 0, 1, 1};
        g.barycentric = {{1, 0, 0}, {0, 0.5f, 0.5f}, {1, 0, 0}, {0, 0, 1}};
        DepthAnalysis a;
        a.depthError = {2.f, 0.f, 4.f, -2.f};
        a.meanSquaredError = 6.0;
        std::vector<float> scale, weight;
        depthErrorRidgeScale(a, g, faces, 5, 2.f, scale, weight);
        const float k = 2.f / std::sqrt(6.f);
        QCOMPARE(scale.size(), std::size_t(5));
        QVERIFY(std::abs(scale[0] - 1.f / (1.f + k * 2.f)) < 1e-6f);
        QVERIFY(std::abs(scale[1] - 1.f / (1.f + k * 4.f / 3.f)) < 1e-6f);
        QCOMPARE(scale[2], 1.f);
        QVERIFY(std::abs(scale[3] - 1.f / (1.f + k * 4.f)) < 1e-6f);
        QCOMPARE(scale[4], 1.f);
        // Strength 0, or a picture without error: one threshold everywhere.
        depthErrorRidgeScale(a, g, faces, 5, 0.f, scale, weight);
        QVERIFY(std::all_of(scale.begin(), scale.end(), [](float s) { return s == 1.f; }));
        a.meanSquaredError = 0.0;
        depthErrorRidgeScale(a, g, faces, 5, 2.f, scale, weight);
        QVERIFY(std::all_of(scale.begin(), scale.end(), [](float s) { return s == 1.f; }));
    }

    // The ridge pipeline on a torus: every snake has at least 10 vertices.
    void noShortSnakes()
    {
        const TriMesh m = torus(2.f, 0.7f, 120, 48);
        RidgeShapeData data;
        computeRidgeShapeData(m.vertices, m.faces, data);
        RasterCamera camera = orthoCamera({3, -6, 4}, {0, 0, 1}, 7.0, 500);
        RidgeScratch scratch;
        RidgeSnakes snakes;
        extractRidgeSnakes(m.vertices, m.faces, m.vertexFaces(), data, camera, 0.1f, scratch, snakes);
        QVERIFY(!snakes.strokes.empty());
        for (const Stroke& s : snakes.strokes)
            QVERIFY(s.vertices.size() >= 10);

        // Issue 26, fix 7: raw ridges (figure 4.8) keep every extracted segment: each appears in a
        // stroke, nothing is smoothed (every point is a segment end as extracted) and short pieces
        // stay, so there are strokes under 10 vertices and more points than in the snakes.
        RidgeSnakes raw;
        extractRidgeSnakes(
            m.vertices, m.faces, m.vertexFaces(), data, camera, 0.1f, scratch, raw, nullptr, SnakeOptions::raw());
        std::size_t rawSegments = 0, shortStrokes = 0;
        for (const Stroke& s : raw.strokes) {
            rawSegments += s.vertices.size() - (s.closed ? 0 : 1);
            shortStrokes += s.vertices.size() < 10 ? 1 : 0;
        }
        QCOMPARE(rawSegments, scratch.segments.points.size() / 2);
        QVERIFY(shortStrokes > 0);
        std::size_t snakeSegments = 0;
        for (const Stroke& s : snakes.strokes)
            snakeSegments += s.vertices.size() - (s.closed ? 0 : 1);
        QVERIFY(rawSegments > snakeSegments);
        for (const Eigen::Vector3f& p : raw.points)
            QVERIFY(std::find(scratch.segments.points.begin(), scratch.segments.points.end(), p)
                != scratch.segments.points.end());
    }

    // A scanned mesh: lines exist, are finite, lie on the model and form snakes; more of them at
    // a lower threshold.
    void armadillo()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_armadillo.off"));
        const TriMesh m = celform::model::importMesh(path).mesh;
        const Eigen::AlignedBox3d box = boundingBox(m.vertices);
        const Eigen::Vector3d centre = box.center();
        RasterCamera camera;
        camera.eye = centre + Eigen::Vector3d(0, 0, 3 * box.diagonal().norm());
        camera.target = centre;
        camera.fovYDegrees = 25;
        camera.width = camera.height = 800;
        RidgeShapeData data;
        computeRidgeShapeData(m.vertices, m.faces, data);
        QVERIFY(data.featureSize > 0.f);
        RidgeScratch scratch;
        RidgeSnakes snakes;
        extractRidgeSnakes(m.vertices, m.faces, m.vertexFaces(), data, camera, 0.3f, scratch, snakes);
        const std::size_t segments = scratch.segments.points.size() / 2;
        QVERIFY(segments > 500);
        QVERIFY(segments < std::size_t(m.faceCount()) / 4);
        QVERIFY(snakes.strokes.size() > 20);
        const Eigen::AlignedBox3f loose(
            (box.min() - 0.01 * box.diagonal()).cast<float>(), (box.max() + 0.01 * box.diagonal()).cast<float>());
        for (const Eigen::Vector3f& p : snakes.points)
            QVERIFY(p.allFinite() && loose.contains(p));
        RidgeSnakes more;
        extractRidgeSnakes(m.vertices, m.faces, m.vertexFaces(), data, camera, 0.1f, scratch, more);
        QVERIFY(scratch.segments.points.size() / 2 > segments);
        qInfo("armadillo: %zu segments, %zu snakes at 0.3; %zu segments at 0.1", segments, snakes.strokes.size(),
            scratch.segments.points.size() / 2);
    }
};

QTEST_GUILESS_MAIN(TestApparentRidges)
#include "test_apparent_ridges.moc"
