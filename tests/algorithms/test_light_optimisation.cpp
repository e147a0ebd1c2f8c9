// The light optimisation of paper 3 (sections 4.1-4.1.3, 5.0.2-5.0.3) on the thesis's dented
// sphere: the samples reproduce the analysis's counts and eq. 4.2 sums, the gradient method puts
// the shading line across the dent without the objective ever rising, and the annealing and
// random methods repeat for a seed.
#include "test_meshes.h"
#include "test_support.h"

#include "celform/algorithms/curvature.h"
#include "celform/algorithms/depth_analysis.h"
#include "celform/algorithms/light_optimisation.h"
#include "celform/algorithms/render.h"

using namespace celform::algo;

namespace {

RasterCamera camera(int size)
{
    RasterCamera c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    c.width = size;
    c.height = size;
    c.fovYDegrees = 30.0;
    return c;
}

/// A dented sphere rendered and analysed as model::DepthAnalyser does, kept for the samples.
struct Scene {
    std::shared_ptr<TriMesh> mesh;
    Curvatures curvature;
    RenderCache cache;
    RenderPasses passes;
    GBuffer gbuffer;
    DepthAnalysis analysis;
    DepthAnalysisSettings settings;
    std::vector<float> offsets;

    explicit Scene(int size = 200, const Eigen::Vector3f& dent = {0.45f, 0.25f, 0.86f})
        : mesh(celform::test::dentedSphere(5, dent))
    {
        computeCurvatures(mesh->vertices, mesh->faces, curvature);
        settings.depthThreshold = 0.04f;
        settings.toonThreshold = 0.5f;
        render(camera(size));
    }
    void render(const RasterCamera& cam, bool pointLight = false, const Eigen::Vector3f& light = {0.f, 0.f, 1.f})
    {
        RenderLook look;
        look.style = Style::Toon;
        look.toon.thresholds = {settings.toonThreshold};
        look.pointLight = pointLight;
        look.light = light;
        look.lines = false;
        look.shadingOffsets = offsets.empty() ? nullptr : &offsets;
        renderFrame(mesh->vertices, *mesh, cam, look, cache, passes, nullptr, &gbuffer);
        settings.pointLight = pointLight;
        settings.light = light;
        settings.shadingOffsets = look.shadingOffsets;
        analyseDepth(gbuffer, passes.normal, passes.beauty, mesh->faces, curvature.gaussian, settings, analysis);
    }
    void gather(ShadingSamples& samples) const
    {
        gatherShadingSamples(gbuffer, passes.normal, analysis.segments, mesh->faces, settings.shadingOffsets,
            settings.toonThreshold, samples);
    }
};

double distanceFromWindow(double ratio, const RatioWindow& w)
{
    return std::max({0.0, double(w.low) - ratio, ratio - double(w.high)});
}

} // namespace

class TestLightOptimisation : public QObject {
    Q_OBJECT

private slots:
    void samplesReproduceTheAnalysis_data()
    {
        QTest::addColumn<bool>("pointLight");
        QTest::addColumn<bool>("withOffsets");
        QTest::newRow("directional") << false << false;
        QTest::newRow("directional with offsets") << false << true;
        QTest::newRow("point") << true << false;
        QTest::newRow("point with offsets") << true << true;
    }
    void samplesReproduceTheAnalysis()
    {
        QFETCH(bool, pointLight);
        QFETCH(bool, withOffsets);
        Scene scene;
        if (withOffsets) {
            scene.offsets.resize(std::size_t(scene.mesh->vertices.rows()));
            for (Eigen::Index v = 0; v < scene.mesh->vertices.rows(); ++v)
                scene.offsets[std::size_t(v)] = 0.3f * scene.mesh->vertices(v, 0);
        }
        // A unit direction, or a point: the analysis's per-pixel eq. 4.2 is then the same function.
        const Eigen::Vector3f light
            = pointLight ? Eigen::Vector3f(1.5f, 2.0f, 2.5f) : Eigen::Vector3f(0.3f, 0.5f, 0.8f).normalized();
        scene.render(camera(200), pointLight, light);
        QVERIFY(scene.analysis.stats.size() >= 2);

        ShadingSamples samples;
        scene.gather(samples);
        QCOMPARE(samples.segmentCount(), int(scene.analysis.stats.size()));
        LightOptimisationSettings settings;
        LightEvaluation e;
        evaluateLight(samples, {pointLight, light.cast<double>()}, settings, true, e);
        for (int s = 0; s < samples.segmentCount(); ++s) {
            const SegmentStats& st = scene.analysis.stats[std::size_t(s)];
            QCOMPARE(samples.pixels(s), st.pixels);
            // The same comparison multiplied out: a pixel exactly on the threshold may differ.
            QVERIFY2(std::abs(e.bright[std::size_t(s)] - st.bright) <= std::max(1, st.pixels / 2000),
                qPrintable(QStringLiteral("segment %1: %2 vs %3").arg(s).arg(e.bright[std::size_t(s)]).arg(st.bright)));
            // Eq. 4.2 summed over the segment: the directional closed form (sum n) - (l . sum n) l
            // and the point light's per-pixel sum equal the analysis's per-pixel sum.
            const Eigen::Vector3d g = e.gradient[std::size_t(s)];
            QVERIFY2((g - st.lightGradient).norm() <= 1e-3 * std::max(1.0, st.lightGradient.norm()),
                qPrintable(QStringLiteral("segment %1").arg(s)));
        }
    }

    void gradientMethodPutsTheShadingLineAcrossTheDent()
    {
        // Front-lit from the camera as in the thesis's runs (5.0.3): the sphere is three quarters
        // bright (N.L >= 0.5 on a disc of radius sin 60 degrees) and the dent, facing the camera,
        // bright throughout.
        Scene scene;
        ShadingSamples samples;
        scene.gather(samples);
        LightOptimisationSettings settings;
        LightOptimisationWorkspace work;
        const LightOptimisationResult r = optimiseLight(samples, {false, {0.0, 0.0, 1.0}}, settings, work);
        QVERIFY(!r.cancelled);
        QVERIFY(r.objectiveBefore > 0.0);
        QVERIFY2(r.objectiveAfter < 0.5 * r.objectiveBefore,
            qPrintable(QStringLiteral("%1 -> %2").arg(r.objectiveBefore).arg(r.objectiveAfter)));
        QCOMPARE(r.after.vector.norm(), 1.0);

        // The objective of the accepted light never rises (5.0.2's steps are accepted only when
        // they do not make it worse).
        double previous = r.objectiveBefore;
        for (const LightIteration& it : r.iterations) {
            QVERIFY(it.objective <= previous);
            previous = it.objective;
        }
        QCOMPARE(previous, r.objectiveAfter);

        // Every segment is inside the window or closer to it than before.
        QCOMPARE(r.ratioAfter.size(), r.ratioBefore.size());
        for (std::size_t s = 0; s < r.ratioAfter.size(); ++s)
            QVERIFY2(distanceFromWindow(r.ratioAfter[s], settings.window)
                    <= distanceFromWindow(r.ratioBefore[s], settings.window) + 1e-9,
                qPrintable(QStringLiteral("segment %1: %2 -> %3").arg(s).arg(r.ratioBefore[s]).arg(r.ratioAfter[s])));

        // The shading line crosses the dent: its saddle ring (the segments of negative curvature)
        // was all bright and now has both tones, rendered with the light found.
        scene.render(camera(200), false, r.after.vector.cast<float>());
        int ring = 0;
        for (std::size_t s = 0; s < scene.analysis.stats.size(); ++s) {
            const SegmentStats& st = scene.analysis.stats[s];
            if (st.meanCurvature >= 0.f)
                continue;
            ++ring;
            QVERIFY2(r.ratioBefore[s] > 0.95f, qPrintable(QString::number(r.ratioBefore[s])));
            QVERIFY2(st.bright > 0 && st.bright < st.pixels,
                qPrintable(QStringLiteral("%1 of %2 bright").arg(st.bright).arg(st.pixels)));
            QCOMPARE(st.ratio, r.ratioAfter[s]);
        }
        QVERIFY(ring >= 1);
    }

    void weightAndWindowChangeTheResult()
    {
        Scene scene;
        ShadingSamples samples;
        scene.gather(samples);
        LightOptimisationWorkspace work;
        LightOptimisationSettings lenient;
        lenient.window = {0.2f, 0.8f};
        LightOptimisationSettings strict;
        strict.window = {0.5f, 0.5f};
        const LightPose start{false, {0.0, 0.0, 1.0}};
        const LightOptimisationResult a = optimiseLight(samples, start, lenient, work);
        const LightOptimisationResult b = optimiseLight(samples, start, strict, work);
        // 5.0.3: the lenient window keeps the light nearer where the artist put it.
        const double turnA = std::acos(std::clamp(a.after.vector.z(), -1.0, 1.0));
        const double turnB = std::acos(std::clamp(b.after.vector.z(), -1.0, 1.0));
        QVERIFY2(turnA < turnB, qPrintable(QStringLiteral("%1 vs %2 rad").arg(turnA).arg(turnB)));
        LightOptimisationSettings area;
        area.weight = SegmentWeight::Area;
        const LightOptimisationResult c = optimiseLight(samples, start, area, work);
        QVERIFY(c.objectiveAfter <= c.objectiveBefore);
        QVERIFY(!c.after.vector.isApprox(a.after.vector));
    }

    void pointLightMoves()
    {
        Scene scene;
        scene.render(camera(200), true, {0.f, 0.f, 3.f});
        ShadingSamples samples;
        scene.gather(samples);
        LightOptimisationSettings settings;
        settings.scale = 1.0;
        LightOptimisationWorkspace work;
        const LightOptimisationResult r = optimiseLight(samples, {true, {0.0, 0.0, 3.0}}, settings, work);
        QVERIFY(r.after.point);
        QVERIFY(r.objectiveAfter < r.objectiveBefore);
        // Steps of 1/8 radius shrinking by 31/32: at most sum (1/8)(31/32)^i < 4 radii in all.
        QVERIFY((r.after.vector - Eigen::Vector3d(0, 0, 3)).norm() < 4.0);
    }

    void seededMethodsRepeat_data()
    {
        QTest::addColumn<int>("method");
        QTest::newRow("annealing") << int(LightMethod::Annealing);
        QTest::newRow("random") << int(LightMethod::Random);
    }
    void seededMethodsRepeat()
    {
        QFETCH(int, method);
        Scene scene;
        ShadingSamples samples;
        scene.gather(samples);
        LightOptimisationSettings settings;
        settings.method = LightMethod(method);
        settings.iterations = 40;
        LightOptimisationWorkspace work;
        const LightPose start{false, {0.0, 0.0, 1.0}};
        settings.seed = 7;
        const LightOptimisationResult a = optimiseLight(samples, start, settings, work);
        const LightOptimisationResult b = optimiseLight(samples, start, settings, work);
        settings.seed = 8;
        const LightOptimisationResult c = optimiseLight(samples, start, settings, work);
        QCOMPARE(a.after.vector, b.after.vector);
        QCOMPARE(a.iterations.size(), b.iterations.size());
        QVERIFY(!a.after.vector.isApprox(c.after.vector));
        QVERIFY(a.objectiveAfter < a.objectiveBefore);
        QVERIFY(std::abs(a.after.vector.norm() - 1.0) < 1e-12);
        double previous = a.objectiveBefore;
        for (const LightIteration& it : a.iterations) {
            QVERIFY(it.objective <= previous);
            previous = it.objective;
        }
    }

    void cancelKeepsTheLight()
    {
        Scene scene;
        ShadingSamples samples;
        scene.gather(samples);
        LightOptimisationWorkspace work;
        // Asks to stop once three of the 64 iterations are done.
        struct StopAtThree : Progress {
            int calls = 0;
            bool stop = false;
            void progress(std::int64_t done, std::int64_t total, const std::string&) override
            {
                ++calls;
                stop = !(done < 3 && total == 64);
            }
            bool isCancelRequested() const override { return stop; }
        } progress;
        const LightOptimisationResult r = optimiseLight(samples, {false, {0.0, 0.0, 1.0}}, {}, work, &progress);
        const int calls = progress.calls;
        QVERIFY(r.cancelled);
        QCOMPARE(calls, 3);
        QCOMPARE(r.after.vector, Eigen::Vector3d(0, 0, 1));
        QCOMPARE(r.ratioAfter, r.ratioBefore);
    }

    void nothingToDoInsideTheWindow()
    {
        Scene scene;
        ShadingSamples samples;
        scene.gather(samples);
        LightOptimisationSettings settings;
        settings.window = {0.f, 1.f};
        LightOptimisationWorkspace work;
        const LightOptimisationResult r = optimiseLight(samples, {false, {0.0, 0.0, 2.0}}, settings, work);
        QCOMPARE(r.objectiveBefore, 0.0);
        QVERIFY(r.iterations.empty());
        QCOMPARE(r.after.vector, Eigen::Vector3d(0, 0, 1)); // directions come back unit
    }

    void unusableInputIsHarmless()
    {
        ShadingSamples empty;
        LightOptimisationWorkspace work;
        const LightOptimisationResult none = optimiseLight(empty, {false, {0.0, 1.0, 0.0}}, {}, work);
        QVERIFY(none.iterations.empty());
        QCOMPARE(none.after.vector, Eigen::Vector3d(0, 1, 0));
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const LightOptimisationResult bad = optimiseLight(empty, {false, {nan, 0.0, 0.0}}, {}, work);
        QVERIFY(bad.iterations.empty());
        const LightOptimisationResult zero = optimiseLight(empty, {false, {0.0, 0.0, 0.0}}, {}, work);
        QVERIFY(zero.iterations.empty());
    }
};

QTEST_APPLESS_MAIN(TestLightOptimisation)
#include "test_light_optimisation.moc"
