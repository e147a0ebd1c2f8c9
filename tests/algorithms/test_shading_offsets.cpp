// Automatic per-segment shading offsets (paper 3, section 4.3): with aggressiveness 1 every
// covered segment's ratio, measured by the depth analysis itself, is 1 - Q within one pixel; 0
// changes nothing; 0.5 is halfway; bleeding removes jumps between neighbouring vertices; bad input
// is refused. On a procedural dented sphere (figure 4.16's subject) and a real mesh.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/curvature.h"
#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/render.h"
#include "celform/algorithms/shading_offsets.h"
#include "celform/model/io/mesh_io.h"

#include <cmath>
#include <limits>

using namespace celform::algo;

namespace {

std::shared_ptr<TriMesh> dentedSphere()
{
    // Three dents on different sides: no single light puts a shading line on all of them (4.3).
    auto mesh = celform::test::icosphere(5);
    const Eigen::Vector3f axes[] = {{0.f, 0.f, 1.f}, {0.8f, 0.3f, 0.52f}, {-0.7f, -0.5f, 0.5f}};
    for (Eigen::Index v = 0; v < mesh->vertices.rows(); ++v) {
        const Eigen::Vector3f p = mesh->vertices.row(v);
        float scale = 1.f;
        for (const Eigen::Vector3f& a : axes) {
            const float angle = std::acos(std::clamp(p.dot(a.normalized()), -1.f, 1.f));
            scale -= 0.3f * std::exp(-(angle * angle) / (2.f * 0.25f * 0.25f));
        }
        mesh->vertices.row(v) = p * scale;
    }
    return mesh;
}

/// One analysed picture of a mesh with its G-buffer: what the solver reads.
struct Scene {
    std::shared_ptr<const TriMesh> mesh;
    RasterCamera camera;
    RenderLook look;
    RenderCache cache;
    GBuffer gbuffer;
    RenderPasses passes;
    std::vector<float> curvature;
    float depthThreshold = 0.04f;
    VertexNeighbours neighbours;

    /// Renders and analyses with offsets (may be empty).
    void analyse(const std::vector<float>& offsets, DepthAnalysis& out)
    {
        look.shadingOffsets = offsets.empty() ? nullptr : &offsets;
        renderFrame(mesh->vertices, *mesh, camera, look, cache, passes, nullptr, &gbuffer);
        DepthAnalysisSettings s;
        s.depthThreshold = depthThreshold;
        s.light = look.light;
        s.toonThreshold = look.toon.thresholds.front();
        s.shadingOffsets = look.shadingOffsets;
        analyseDepth(gbuffer, passes.normal, passes.beauty, mesh->faces, curvature, s, out);
    }
    SegmentOffsetInput input(const DepthAnalysis& a) const
    {
        SegmentOffsetInput in;
        in.width = a.width;
        in.height = a.height;
        in.faceId = gbuffer.faceId.data();
        in.barycentric = gbuffer.barycentric.data();
        in.baseline = a.lambert.data();
        in.labels = a.segments.labels.data();
        in.segmentCount = std::int32_t(a.stats.size());
        in.faces = &mesh->faces;
        in.neighbours = &neighbours;
        return in;
    }
};

Scene makeScene(std::shared_ptr<const TriMesh> mesh, int size, const Eigen::Vector3f& light)
{
    Scene s;
    s.mesh = mesh;
    const Eigen::AlignedBox3d box = boundingBox(mesh->vertices);
    const Eigen::Vector3d centre = box.center();
    const double radius = 0.5 * box.diagonal().norm();
    s.camera.eye = centre + Eigen::Vector3d(0.2, 0.3, 1.0).normalized() * radius * 3.2;
    s.camera.target = centre;
    s.camera.up = {0, 1, 0};
    s.camera.width = size;
    s.camera.height = size;
    s.camera.fovYDegrees = 40.0;
    s.look.style = Style::Toon;
    s.look.toon.thresholds = {0.5f};
    s.look.toon.intensities = {0.35f, 1.f};
    s.look.light = light;
    s.look.lines = false;
    Curvatures k;
    computeCurvatures(mesh->vertices, mesh->faces, k);
    s.curvature = k.gaussian;
    s.depthThreshold = float(0.02 * box.diagonal().norm());
    s.neighbours = buildVertexNeighbours(mesh->faces, std::int32_t(mesh->vertexCount()));
    return s;
}

} // namespace

class TestShadingOffsets : public QObject {
    Q_OBJECT

    /// Solves with aggressiveness 1 and percentile q, then checks the analysis's own ratios.
    void checkExact(Scene& scene, float q, int bleed)
    {
        DepthAnalysis before;
        scene.analyse({}, before);
        QVERIFY(!before.stats.empty());
        std::vector<float> field(std::size_t(scene.mesh->vertexCount()), 0.f);
        SegmentOffsetSettings settings;
        settings.threshold = 0.5f;
        settings.percentile = q;
        settings.bleedRounds = bleed;
        SegmentOffsetScratch scratch;
        SegmentOffsetReport report;
        QVERIFY(solveSegmentOffsets(scene.input(before), settings, field, scratch, &report));
        DepthAnalysis after;
        scene.analyse(field, after);
        QCOMPARE(after.stats.size(), before.stats.size()); // segments follow curvature and depth only
        int covered = 0;
        for (std::size_t s = 0; s < after.stats.size(); ++s) {
            if (!report.covered[s])
                continue;
            ++covered;
            const SegmentStats& st = after.stats[s];
            const double share = 1.0 / double(st.pixels);
            QVERIFY2(std::abs(double(st.ratio) - (1.0 - double(q))) <= share + 1e-9,
                qPrintable(QStringLiteral("segment %1 (%2 px): ratio %3 before, %4 after, wanted %5")
                               .arg(s)
                               .arg(st.pixels)
                               .arg(double(before.stats[s].ratio))
                               .arg(double(st.ratio))
                               .arg(1.0 - double(q))));
        }
        QVERIFY(covered >= 1);
        QVERIFY(report.converged);
    }

private slots:
    void exactOnDentedSphere_data()
    {
        QTest::addColumn<float>("percentile");
        QTest::addColumn<int>("bleed");
        QTest::newRow("median, no bleeding") << 0.5f << 0;
        QTest::newRow("median, bleeding 3") << 0.5f << 3;
        QTest::newRow("Q 0.3, bleeding 2") << 0.3f << 2;
    }
    void exactOnDentedSphere()
    {
        QFETCH(float, percentile);
        QFETCH(int, bleed);
        Scene scene = makeScene(dentedSphere(), 200, Eigen::Vector3f(-0.6f, 0.7f, 0.4f));
        checkExact(scene, percentile, bleed);
    }

    void exactOnRealMesh()
    {
        CELFORM_REQUIRE_SHARED(path, QStringLiteral("meshes/cgal_armadillo.off"));
        auto mesh = std::make_shared<TriMesh>(celform::model::importMesh(path).mesh);
        Scene scene = makeScene(mesh, 256, Eigen::Vector3f(0.4f, 0.6f, 0.7f));
        checkExact(scene, 0.5f, 2);
    }

    void aggressivenessZeroAndHalf()
    {
        Scene scene = makeScene(dentedSphere(), 160, Eigen::Vector3f(-0.6f, 0.7f, 0.4f));
        DepthAnalysis a;
        scene.analyse({}, a);
        const std::size_t n = std::size_t(scene.mesh->vertexCount());
        // Start from non-zero values: A = 0 keeps them exactly, A = 1 replaces them, A = 0.5
        // lands halfway.
        std::vector<float> start(n);
        for (std::size_t v = 0; v < n; ++v)
            start[v] = 0.1f * std::sin(float(v));
        SegmentOffsetSettings settings;
        SegmentOffsetScratch scratch;
        std::vector<float> full = start, none = start, half = start;
        settings.aggressiveness = 1.f;
        QVERIFY(solveSegmentOffsets(scene.input(a), settings, full, scratch));
        settings.aggressiveness = 0.f;
        QVERIFY(solveSegmentOffsets(scene.input(a), settings, none, scratch));
        settings.aggressiveness = 0.5f;
        QVERIFY(solveSegmentOffsets(scene.input(a), settings, half, scratch));
        QVERIFY(none == start);
        QVERIFY(full != start);
        for (std::size_t v = 0; v < n; ++v)
            QVERIFY(std::abs(half[v] - 0.5f * (start[v] + full[v])) < 1e-5f);
    }

    void bleedingRemovesJumps()
    {
        Scene scene = makeScene(dentedSphere(), 200, Eigen::Vector3f(-0.6f, 0.7f, 0.4f));
        DepthAnalysis a;
        scene.analyse({}, a);
        const std::size_t n = std::size_t(scene.mesh->vertexCount());
        auto largestJump = [&](int bleed) {
            std::vector<float> field(n, 0.f);
            SegmentOffsetSettings settings;
            settings.bleedRounds = bleed;
            SegmentOffsetScratch scratch;
            SegmentOffsetReport report;
            [&] { QVERIFY(solveSegmentOffsets(scene.input(a), settings, field, scratch, &report)); }();
            // The mean jump across the edges between two segments (figure 4.15's harsh lines).
            double sum = 0.0;
            int edges = 0;
            for (std::size_t v = 0; v < n; ++v)
                for (auto k = scene.neighbours.start[v]; k < scene.neighbours.start[v + 1]; ++k) {
                    const auto w = std::size_t(scene.neighbours.neighbours[std::size_t(k)]);
                    const auto sv = report.vertexSegment[v], sw = report.vertexSegment[w];
                    if (sv >= 0 && sw >= 0 && sv != sw) {
                        sum += std::abs(double(field[v]) - double(field[w]));
                        ++edges;
                    }
                }
            return float(edges > 0 ? sum / edges : 0.0);
        };
        const float sharp = largestJump(0);
        const float bled = largestJump(8);
        QVERIFY2(sharp > 0.f, "the segments' constants differ");
        QVERIFY2(
            bled < 0.5f * sharp, qPrintable(QStringLiteral("jump %1 without, %2 with bleeding").arg(sharp).arg(bled)));
    }

    void smoothingIsLaplacian()
    {
        // A path 0 - 1 - 2: one round moves the middle halfway to its neighbours' mean.
        Faces faces(1, 3);
        faces << 0, 1, 2;
        const VertexNeighbours nb = buildVertexNeighbours(faces, 3);
        QCOMPARE(nb.neighbours.size(), std::size_t(6));
        std::vector<float> values{0.f, 1.f, 0.f}, scratch;
        smoothVertexValues(nb, 1, nullptr, values, scratch);
        QCOMPARE(values[1], 0.5f);
        QCOMPARE(values[0], 0.25f);
        const std::uint8_t free[] = {0, 1, 0};
        values = {0.f, 1.f, 0.f};
        smoothVertexValues(nb, 1, free, values, scratch);
        QCOMPARE(values[0], 0.f);
        QCOMPARE(values[2], 0.f);
    }

    // Issue 26, fix 6: a vertex touched by five segments counts every one's votes. The fifth
    // segment to reach the centre of a fan of five triangles votes the most; four fixed slots
    // dropped it silently.
    void fifthSegmentVotesCount()
    {
        Faces faces(5, 3);
        for (int f = 0; f < 5; ++f)
            faces.row(f) << 0, 1 + f, 1 + (f + 1) % 5;
        const VertexNeighbours neighbours = buildVertexNeighbours(faces, 6);
        // One row of pixels: segments 0-3 one pixel each on faces 0-3, barely touching vertex 0;
        // segment 4 four pixels on face 4, mostly on vertex 0.
        const int width = 8;
        std::vector<std::int32_t> faceId{0, 1, 2, 3, 4, 4, 4, 4}, labels{0, 1, 2, 3, 4, 4, 4, 4};
        std::vector<Eigen::Vector3f> barycentric(width, Eigen::Vector3f(0.9f, 0.05f, 0.05f));
        for (int i = 0; i < 4; ++i)
            barycentric[std::size_t(i)] = Eigen::Vector3f(0.1f, 0.45f, 0.45f);
        std::vector<float> baseline(width, 0.f);
        SegmentOffsetInput in;
        in.width = width;
        in.height = 1;
        in.faceId = faceId.data();
        in.barycentric = barycentric.data();
        in.baseline = baseline.data();
        in.labels = labels.data();
        in.segmentCount = 5;
        in.faces = &faces;
        in.neighbours = &neighbours;
        std::vector<float> field(6, 0.f);
        SegmentOffsetScratch scratch;
        SegmentOffsetReport report;
        QVERIFY(solveSegmentOffsets(in, SegmentOffsetSettings{}, field, scratch, &report));
        QCOMPARE(report.vertexSegment[0], 4);
        // Only the chosen segments are solved (issue 26, fix 5): leaving out segment 4, the
        // centre keeps its value and segment 4 counts as uncovered.
        const std::vector<std::uint8_t> solve{1, 1, 1, 1, 0};
        in.solve = solve.data();
        field.assign(6, 0.f);
        QVERIFY(solveSegmentOffsets(in, SegmentOffsetSettings{}, field, scratch, &report));
        QCOMPARE(report.vertexSegment[0], -1);
        QCOMPARE(report.covered[4], std::uint8_t(0));
        QCOMPARE(field[0], 0.f);
    }

    void refusesBadInput()
    {
        Scene scene = makeScene(dentedSphere(), 96, Eigen::Vector3f(-0.6f, 0.7f, 0.4f));
        DepthAnalysis a;
        scene.analyse({}, a);
        const std::size_t n = std::size_t(scene.mesh->vertexCount());
        SegmentOffsetSettings settings;
        SegmentOffsetScratch scratch;
        // A field of the wrong size.
        std::vector<float> small(n - 1, 0.f);
        const std::vector<float> smallCopy = small;
        QVERIFY(!solveSegmentOffsets(scene.input(a), settings, small, scratch));
        QVERIFY(small == smallCopy);
        // NaN in the field.
        std::vector<float> field(n, 0.f);
        field[3] = std::numeric_limits<float>::quiet_NaN();
        QVERIFY(!solveSegmentOffsets(scene.input(a), settings, field, scratch));
        QVERIFY(std::isnan(field[3]));
        // NaN in the picture.
        std::vector<float> lambert = a.lambert;
        for (std::size_t i = 0; i < lambert.size(); ++i)
            if (a.segments.labels[i] >= 0) {
                lambert[i] = std::numeric_limits<float>::quiet_NaN();
                break;
            }
        SegmentOffsetInput in = scene.input(a);
        in.baseline = lambert.data();
        field.assign(n, 0.f);
        QVERIFY(!solveSegmentOffsets(in, settings, field, scratch));
        // Settings out of range.
        field.assign(n, 0.f);
        settings.percentile = 1.5f;
        QVERIFY(!solveSegmentOffsets(scene.input(a), settings, field, scratch));
        settings.percentile = 0.5f;
        settings.aggressiveness = -0.1f;
        QVERIFY(!solveSegmentOffsets(scene.input(a), settings, field, scratch));
        for (float v : field)
            QCOMPARE(v, 0.f);
    }
};

QTEST_GUILESS_MAIN(TestShadingOffsets)
#include "test_shading_offsets.moc"
