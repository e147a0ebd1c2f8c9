// The depth analysis of paper 3, chapter 4, on cases computed by hand: the distance transform
// against brute force (4.4.1), Hoshen-Kopelman segments (4.5.3; figure 4.6's three spheres), the
// bright/dark ratio of a lit sphere (figure 4.2), the light derivative (eq. 4.2) against finite
// differences, and the depth error of a plane and of a step.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/curvature.h"
#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/distance_transform.h"
#include "celform/algorithms/render.h"
#include "celform/algorithms/segments.h"
#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/render/render_output.h"

#include <limits>
#include <random>
#include <set>

using namespace celform::algo;

Q_DECLARE_METATYPE(Eigen::Vector3f)

namespace {

/// Appends a copy of mesh scaled by radius and moved to centre.
void appendSphere(TriMesh& into, const TriMesh& mesh, const Eigen::Vector3f& centre, float radius)
{
    const Eigen::Index v0 = into.vertices.rows(), f0 = into.faces.rows();
    into.vertices.conservativeResize(v0 + mesh.vertices.rows(), 3);
    into.faces.conservativeResize(f0 + mesh.faces.rows(), 3);
    for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
        into.vertices.row(v0 + i) = centre.transpose() + radius * mesh.vertices.row(i);
    for (Eigen::Index i = 0; i < mesh.faces.rows(); ++i)
        into.faces.row(f0 + i) = mesh.faces.row(i).array() + std::int32_t(v0);
}

RasterCamera camera(int size, const Eigen::Vector3d& eye = {0, 0, 6})
{
    RasterCamera c;
    c.eye = eye;
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    c.width = size;
    c.height = size;
    c.fovYDegrees = 30.0;
    return c;
}

/// Renders mesh with a two-tone look and analyses it with every vertex's curvature set to k.
void analyse(const TriMesh& mesh, const RasterCamera& cam, const Eigen::Vector3f& light, float curvature,
    float depthThreshold, DepthAnalysis& out, bool lines = false, float toonThreshold = 0.5f)
{
    RenderLook look;
    look.style = Style::Toon;
    look.toon.thresholds = {toonThreshold};
    look.light = light;
    look.lines = lines;
    RenderCache cache;
    RenderPasses passes;
    GBuffer g;
    renderFrame(mesh.vertices, mesh, cam, look, cache, passes, nullptr, &g);
    DepthAnalysisSettings settings;
    settings.depthThreshold = depthThreshold;
    settings.light = light;
    settings.toonThreshold = look.toon.thresholds.front();
    const std::vector<float> k(std::size_t(mesh.vertices.rows()), curvature);
    analyseDepth(g, passes.normal, passes.beauty, mesh.faces, k, settings, out);
}

} // namespace

class TestDepthAnalysis : public QObject {
    Q_OBJECT

private slots:
    void distanceTransformMatchesBruteForce()
    {
        std::mt19937 random(20021);
        DistanceTransformScratch scratch;
        for (int round = 0; round < 60; ++round) {
            const int w = 1 + int(random() % 23), h = 1 + int(random() % 19);
            const std::size_t n = std::size_t(w) * std::size_t(h);
            std::vector<std::uint8_t> feature(n, 0);
            // Rounds 0 and 1: no feature and every pixel a feature; then densities from sparse to dense.
            const double density = round == 0 ? 0.0 : round == 1 ? 1.0 : double(round % 10) / 20.0;
            for (auto& f : feature)
                f = std::uniform_real_distribution<double>(0, 1)(random) < density ? 1 : 0;
            if (round == 1)
                std::fill(feature.begin(), feature.end(), std::uint8_t(1));
            std::vector<std::int32_t> nearest(n, -7);
            std::vector<std::uint32_t> squared(n, 0);
            nearestFeatureTransform(feature.data(), w, h, nearest.data(), squared.data(), scratch);
            std::vector<float> distance(n);
            distanceTransform(feature.data(), w, h, distance.data(), scratch);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                    long best = std::numeric_limits<long>::max();
                    for (int v = 0; v < h; ++v)
                        for (int u = 0; u < w; ++u)
                            if (feature[std::size_t(v) * std::size_t(w) + std::size_t(u)])
                                best = std::min(best, long(x - u) * (x - u) + long(y - v) * (y - v));
                    if (best == std::numeric_limits<long>::max()) {
                        QCOMPARE(nearest[i], -1);
                        QVERIFY(std::isinf(distance[i]));
                        continue;
                    }
                    QCOMPARE(long(squared[i]), best);
                    QCOMPARE(distance[i], std::sqrt(float(best)));
                    // The index names a feature at exactly that distance.
                    const int u = nearest[i] % w, v = nearest[i] / w;
                    QVERIFY(feature[std::size_t(nearest[i])]);
                    QCOMPARE(long(x - u) * (x - u) + long(y - v) * (y - v), best);
                }
        }
    }

    void segmentsJoinBySignAndDepth()
    {
        // 40x20: left half positive curvature, right half negative; the bottom-left quarter is
        // 1 unit farther away. Three segments of 200 pixels each, plus an island of 4x4 = 16 pixels
        // of negative curvature inside the top-left one, dropped as smaller than 64.
        const int w = 40, h = 20;
        std::vector<std::uint8_t> covered(w * h, 1);
        std::vector<float> k(w * h), depth(w * h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int i = y * w + x;
                k[i] = x < 20 ? 0.5f : -0.25f;
                depth[i] = (x < 20 && y >= 10) ? 3.f : 2.f + 0.001f * float(x);
                if (x >= 5 && x < 9 && y >= 3 && y < 7)
                    k[i] = -1.f;
            }
        SegmentLabels s;
        labelSegments(covered.data(), k.data(), depth.data(), w, h, 0.1f, kMinSegmentPixels, s);
        QCOMPARE(int(s.sizes.size()), 3);
        // Numbered in the order of their first pixel: top-left, top-right/right, bottom-left.
        QCOMPARE(s.labels[0], 0);
        QCOMPARE(s.labels[39], 1);
        QCOMPARE(s.labels[19 * w], 2);
        QCOMPARE(s.sizes[0], 200 - 16);
        QCOMPARE(s.sizes[1], 400);
        QCOMPARE(s.sizes[2], 200);
        QCOMPARE(s.labels[5 * w + 6], -1); // the island is gone
        // Labels are compact and the sizes count them.
        std::vector<int> counted(s.sizes.size(), 0);
        for (const auto l : s.labels)
            if (l >= 0)
                ++counted[std::size_t(l)];
        for (std::size_t i = 0; i < counted.size(); ++i)
            QCOMPARE(counted[i], s.sizes[i]);
        // With no minimum, the island is a fourth segment.
        labelSegments(covered.data(), k.data(), depth.data(), w, h, 0.1f, 1, s);
        QCOMPARE(int(s.sizes.size()), 4);
    }

    void segmentsUseDiagonalsAndSkipTransparentPixels()
    {
        // A diagonal staircase of single pixels is one 8-connected component; a column of
        // uncovered pixels splits the image.
        const int w = 12, h = 12;
        std::vector<std::uint8_t> covered(w * h, 0);
        std::vector<float> k(w * h, 1.f), depth(w * h, 1.f);
        for (int i = 0; i < 12; ++i)
            covered[std::size_t(i * w + i)] = 1;
        SegmentLabels s;
        labelSegments(covered.data(), k.data(), depth.data(), w, h, 0.5f, 1, s);
        QCOMPARE(int(s.sizes.size()), 1);
        QCOMPARE(s.sizes[0], 12);
        // The anti-diagonal as well (upper-right neighbours).
        std::fill(covered.begin(), covered.end(), std::uint8_t(0));
        for (int i = 0; i < 12; ++i)
            covered[std::size_t(i * w + (w - 1 - i))] = 1;
        labelSegments(covered.data(), k.data(), depth.data(), w, h, 0.5f, 1, s);
        QCOMPARE(int(s.sizes.size()), 1);
        std::fill(covered.begin(), covered.end(), std::uint8_t(1));
        for (int y = 0; y < h; ++y)
            covered[std::size_t(y * w + 6)] = 0;
        labelSegments(covered.data(), k.data(), depth.data(), w, h, 0.5f, 1, s);
        QCOMPARE(int(s.sizes.size()), 2);
        QCOMPARE(s.labels[6], -1);
        // An empty image has no segment.
        labelSegments(covered.data(), k.data(), depth.data(), 0, 0, 0.5f, 1, s);
        QVERIFY(s.sizes.empty());
    }

    void threeTouchingSpheresAreThreeSegments()
    {
        // Figure 4.6: three spheres of positive curvature that touch in the picture, at different
        // depths. One curvature sign everywhere; only the depth threshold keeps them apart.
        const auto unit = celform::test::icosphere(4);
        TriMesh scene;
        appendSphere(scene, *unit, {-0.9f, 0.f, 0.f}, 0.5f);
        appendSphere(scene, *unit, {0.f, 0.f, 0.8f}, 0.5f);
        appendSphere(scene, *unit, {0.9f, 0.f, 0.f}, 0.5f);
        DepthAnalysis a;
        analyse(scene, camera(240), Eigen::Vector3f(0, 0, 1), 4.f, 0.05f, a);
        QCOMPARE(int(a.stats.size()), 3);
        // Left to right in the picture, each segment's centroid over its own sphere.
        std::vector<float> xs;
        for (const SegmentStats& s : a.stats) {
            QVERIFY(s.pixels > 1000);
            QVERIFY(s.meanCurvature > 0.f);
            xs.push_back(s.centroid.x());
        }
        std::sort(xs.begin(), xs.end());
        QVERIFY(xs[0] < 100.f && xs[1] > 100.f && xs[1] < 140.f && xs[2] > 140.f);
        // With a threshold larger than any step between them, they merge into one.
        analyse(scene, camera(240), Eigen::Vector3f(0, 0, 1), 4.f, 10.f, a);
        QCOMPARE(int(a.stats.size()), 1);
    }

    void dentedSphereSegmentsItsDent()
    {
        // Figure 4.5: a sphere with a smooth inward dent facing the camera. The dent's floor is
        // still dome-like (both principal curvatures flip sign: K > 0), its rim is a saddle ring
        // (K < 0), the rest of the sphere K > 0: three segments, the middle one of negative
        // curvature around the floor's.
        auto mesh = celform::test::icosphere(5);
        const Eigen::Vector3f axis(0.f, 0.f, 1.f);
        for (Eigen::Index v = 0; v < mesh->vertices.rows(); ++v) {
            const Eigen::Vector3f p = mesh->vertices.row(v);
            const float angle = std::acos(std::clamp(p.dot(axis), -1.f, 1.f));
            const float depth = 0.35f * std::exp(-(angle * angle) / (2.f * 0.28f * 0.28f));
            mesh->vertices.row(v) = p * (1.f - depth);
        }
        Curvatures k;
        computeCurvatures(mesh->vertices, mesh->faces, k);
        RenderLook look;
        look.light = Eigen::Vector3f(0.3f, 0.5f, 1.f);
        RenderCache cache;
        RenderPasses passes;
        GBuffer g;
        const RasterCamera cam = camera(240);
        renderFrame(mesh->vertices, *mesh, cam, look, cache, passes, nullptr, &g);
        DepthAnalysisSettings settings;
        settings.depthThreshold = 0.04f;
        settings.light = look.light;
        DepthAnalysis a;
        analyseDepth(g, passes.normal, passes.beauty, mesh->faces, k.gaussian, settings, a);
        int positive = 0, negative = 0;
        for (const SegmentStats& s : a.stats)
            (s.meanCurvature > 0.f ? positive : negative) += 1;
        QVERIFY2(positive >= 2 && negative >= 1,
            qPrintable(QStringLiteral("%1 positive, %2 negative segments").arg(positive).arg(negative)));
        // The picture's centre (the dent's floor) and a point on the rim differ in sign.
        const int centre = 120 * 240 + 120;
        QVERIFY(a.curvature[std::size_t(centre)] > 0.f);
        QVERIFY(a.segments.labels[std::size_t(centre)] >= 0);
        // The depth error is not zero: the dent's inside has few colour edges.
        QVERIFY(a.meanSquaredError > 0.0);
        // Pictures to hold beside the thesis's figures 4.5 and 4.17 (CELFORM_SCREENSHOT_DIR).
        const QString dir = qEnvironmentVariable("CELFORM_SCREENSHOT_DIR");
        if (!dir.isEmpty()) {
            using celform::model::AnalysisPicture;
            celform::model::writeImage(passes.beauty, dir + QStringLiteral("/dented-beauty.png"));
            for (const auto& [picture, name] :
                {std::pair{AnalysisPicture::Segments, "segments"}, std::pair{AnalysisPicture::Curvature, "curvature"},
                    std::pair{AnalysisPicture::DepthError, "depth-error"}})
                celform::model::writeImage(celform::model::analysisImage(a, picture, false),
                    dir + QStringLiteral("/dented-%1.png").arg(QLatin1String(name)));
        }
    }

    void sphereRatiosFollowTheLight_data()
    {
        QTest::addColumn<Eigen::Vector3f>("light");
        QTest::addColumn<float>("threshold");
        QTest::addColumn<double>("expected");
        // Figure 4.2 with the terminator as the toon boundary (threshold 0): lit from the front the
        // visible half is all bright, from behind all dark, from the side split in two.
        QTest::newRow("front, t=0") << Eigen::Vector3f(0, 0, 1) << 0.f << 1.0;
        QTest::newRow("back, t=0") << Eigen::Vector3f(0, 0, -1) << 0.f << 0.0;
        QTest::newRow("side, t=0") << Eigen::Vector3f(1, 0, 0) << 0.f << 0.5;
        // With the default threshold 0.5 (thesis 3.3), seen from +z nearly orthographically, a
        // point (x, y) of the unit disc has n = (x, y, z): from the front it is bright where
        // z >= 0.5, i.e. x^2 + y^2 <= 3/4, a fraction 3/4 of the disc; from the side where
        // x >= 0.5, a circular segment of area acos(0.5) - 0.5 sqrt(3/4), over pi.
        QTest::newRow("front, t=0.5") << Eigen::Vector3f(0, 0, 1) << 0.5f << 0.75;
        QTest::newRow("side, t=0.5") << Eigen::Vector3f(1, 0, 0) << 0.5f
                                     << (std::acos(0.5) - 0.5 * std::sqrt(0.75)) / M_PI;
    }

    void sphereRatiosFollowTheLight()
    {
        QFETCH(Eigen::Vector3f, light);
        QFETCH(float, threshold);
        QFETCH(double, expected);
        const auto unit = celform::test::icosphere(5);
        DepthAnalysis a;
        // A distant, narrow camera: nearly the orthographic disc the expected values assume.
        RasterCamera cam = camera(200, {0, 0, 60});
        cam.fovYDegrees = 2.5;
        analyse(*unit, cam, light, 1.f, 0.1f, a, false, threshold);
        QCOMPARE(int(a.stats.size()), 1);
        QVERIFY2(std::abs(a.stats[0].ratio - expected) < 0.02,
            qPrintable(QStringLiteral("ratio %1, expected %2").arg(a.stats[0].ratio).arg(expected)));
        QCOMPARE(a.stats[0].inWindow, a.stats[0].ratio >= 0.35f && a.stats[0].ratio <= 0.65f);
        QVERIFY(a.stats[0].meanCurvature > 0.f);
    }

    void lightDerivativeMatchesFiniteDifferences()
    {
        // Eq. 4.2 against central differences of n.l/|l| in each coordinate of l.
        const Eigen::Vector3f n = Eigen::Vector3f(0.3f, -0.5f, 0.8f).normalized();
        const Eigen::Vector3f l(1.5f, 2.f, -0.7f);
        const Eigen::Vector3f d = shadingLightDerivative(l, n);
        auto shade = [&](const Eigen::Vector3d& p) { return n.cast<double>().dot(p) / p.norm(); };
        for (int c = 0; c < 3; ++c) {
            Eigen::Vector3d step = Eigen::Vector3d::Zero();
            step[c] = 1e-5;
            const double numeric = (shade(l.cast<double>() + step) - shade(l.cast<double>() - step)) / 2e-5;
            QVERIFY(std::abs(numeric - double(d[c])) < 1e-4);
        }
        QVERIFY(shadingLightDerivative(Eigen::Vector3f::Zero(), n).isZero());
    }

    void depthErrorOfAFacingPlaneIsZero()
    {
        // Two triangles filling the picture at one depth: whatever the features, every perceived
        // depth equals the actual one.
        TriMesh plane;
        plane.vertices.resize(4, 3);
        plane.vertices << -5, -5, 0, 5, -5, 0, 5, 5, 0, -5, 5, 0;
        plane.faces.resize(2, 3);
        plane.faces << 0, 1, 2, 0, 2, 3;
        RasterCamera cam = camera(64);
        cam.orthographic = true;
        cam.orthoHeight = 4.0;
        DepthAnalysis a;
        analyse(plane, cam, Eigen::Vector3f(0.2f, 0.1f, 1.f), 0.f, 0.1f, a, true);
        QCOMPARE(a.modelPixels, qint64(64 * 64));
        QCOMPARE(a.meanSquaredError, 0.0);
        QCOMPARE(a.maxAbsError, 0.0);
    }

    void depthErrorOfAStepByHand()
    {
        // A 10x3 picture: columns 0-4 at depth 1, columns 5-9 at depth 3, one flat colour each,
        // column 9 background. Features: columns 4 and 5 (colour change) and 8 (next to the
        // background). Perceived depth: columns 0-4 take column 4's (1), 5-6 column 5's (3),
        // 7-8 column 8's (3): every error is zero...
        const int w = 10, h = 3;
        std::vector<float> depth(w * h);
        ImageRGBA beauty(w, h, Eigen::Vector4f(1, 1, 1, 1));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                depth[std::size_t(y * w + x)] = x == 9 ? std::numeric_limits<float>::infinity() : (x < 5 ? 1.f : 3.f);
                float* p = beauty.at(x, y);
                p[0] = p[1] = p[2] = x < 5 ? 0.2f : (x < 9 ? 0.7f : 1.f);
            }
        DepthAnalysis a;
        computeDepthError(depth, beauty, a);
        QCOMPARE(a.modelPixels, qint64(27));
        QCOMPARE(a.featurePixels, qint64(9));
        QCOMPARE(a.meanSquaredError, 0.0);
        // ...until the right region slopes: depth 3 + (x - 5) for columns 5-8. Column 6 takes
        // column 5's depth (3, error -1), column 7 is equally near 5 and 8... no: 7 is 1 from 8 and
        // 2 from 5, so it takes column 8's depth (6, error +1). Columns 5 and 8 are features.
        for (int y = 0; y < h; ++y)
            for (int x = 5; x < 9; ++x)
                depth[std::size_t(y * w + x)] = 3.f + float(x - 5);
        computeDepthError(depth, beauty, a);
        QCOMPARE(a.depthError[6], -1.f);
        QCOMPARE(a.depthError[7], 1.f);
        QCOMPARE(a.depthError[5], 0.f);
        QCOMPARE(a.depthError[9], 0.f);
        // Two pixels of squared error 1 per row, over 27 model pixels.
        QCOMPARE(a.meanSquaredError, 6.0 / 27.0);
        QCOMPARE(a.maxAbsError, 1.0);
        // No feature at all (one colour, nothing next to it): no error.
        ImageRGBA flat(w, h, Eigen::Vector4f(0.5f, 0.5f, 0.5f, 1));
        std::vector<float> full(w * h, 2.f);
        computeDepthError(full, flat, a);
        QCOMPARE(a.featurePixels, qint64(0));
        QCOMPARE(a.meanSquaredError, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestDepthAnalysis)
#include "test_depth_analysis.moc"
