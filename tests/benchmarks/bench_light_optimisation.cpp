// Optimise Light for Stereo: 64 iterations over a 512x512 analysis of a model of about
// 338k triangles (the thesis's 'mike', Table 5.1: 1.7 s on its GPU; the goal here is 0.17 s) and
// of about 13k triangles (its 'snake' and dented sphere: 0.7-0.8 s). The thesis's time includes
// its renders; so does the "WholeRun" case here: the analysis before, the iterations and the
// analysis after, with the curvature cached as the editor has it, or computed.
#include "bench_data.h"
#include "test_meshes.h"

#include "celform/algorithms/light_optimisation.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/light_optimisation.h"

#include <benchmark/benchmark.h>

using namespace celform;

namespace {

std::shared_ptr<const algo::TriMesh> model338k()
{
    static std::shared_ptr<const algo::TriMesh> mesh;
    if (!mesh)
        if (const algo::TriMesh* elephant = bench::sharedMesh("meshes/cgal_refined_elephant.off"))
            mesh = test::subdivided(*elephant); // 88,928 triangles become 355,712: about the thesis's 338k
    return mesh;
}

std::shared_ptr<const algo::TriMesh> model13k()
{
    static std::shared_ptr<algo::TriMesh> mesh;
    if (!mesh)
        if (const algo::TriMesh* fandisk = bench::sharedMesh("meshes/cgal_fandisk.off"))
            mesh = std::make_shared<algo::TriMesh>(*fandisk);
    return mesh;
}

/// A project on the mesh, front-lit as the thesis starts (5.0.3), and a camera framing it.
struct Setup {
    model::ProjectData data;
    model::Camera camera;
    explicit Setup(std::shared_ptr<const algo::TriMesh> mesh, bool pointLight = false)
    {
        data = model::newProject(std::move(mesh), QStringLiteral("bench"));
        const Eigen::Vector3d centre = algo::centroid(data.baseMesh->vertices);
        const double size = algo::boundingBox(data.baseMesh->vertices).diagonal().norm();
        camera.target = centre;
        camera.eye = centre + 1.6 * size * Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
        if (pointLight) {
            data.look.light.type = model::LightType::Point;
            data.look.light.vector = camera.eye;
        } else {
            data.look.light.vector = (camera.eye - centre).normalized();
        }
    }
};

void iterations(benchmark::State& state, std::shared_ptr<const algo::TriMesh> mesh, bool pointLight)
{
    if (!mesh) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    Setup setup(mesh, pointLight);
    model::DepthAnalyser analyser;
    model::FrameAnalysis analysis;
    analyser.analyse(setup.data, setup.data.look, setup.data.baseMesh->vertices, algo::newShapeGeneration(), 0,
        setup.camera, 512, 512, {}, analysis);
    algo::ShadingSamples samples;
    algo::gatherShadingSamples(analyser.gbuffer(), analysis.passes.normal, analysis.analysis.segments,
        setup.data.baseMesh->faces, analyser.lastSettings().shadingOffsets, analyser.lastSettings().toonThreshold,
        samples);
    algo::LightOptimisationSettings settings;
    settings.window = {0.5f, 0.5f}; // strict: no early stop, all 64 iterations run
    const Eigen::AlignedBox3d box = algo::boundingBox(setup.data.baseMesh->vertices);
    settings.centre = box.center();
    settings.scale = 0.5 * box.diagonal().norm();
    algo::LightOptimisationWorkspace work;
    const algo::LightPose start{pointLight, setup.data.look.light.vector};
    std::size_t done = 0;
    for (auto _ : state) {
        const algo::LightOptimisationResult r = algo::optimiseLight(samples, start, settings, work);
        done = r.iterations.size();
        benchmark::DoNotOptimize(r.after.vector);
    }
    state.counters["iterations"] = double(done);
    state.counters["pixels"] = double(samples.segmentStart.back());
    state.counters["segments"] = double(samples.segmentCount());
    state.counters["triangles"] = double(mesh->faces.rows());
}

void wholeRun(benchmark::State& state, std::shared_ptr<const algo::TriMesh> mesh, bool cachedCurvature)
{
    if (!mesh) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    Setup setup(mesh);
    model::DepthAnalyser analyser;
    model::LightOptimisationRequest request; // the medium window: it may stop before 64 iterations
    // The thesis's run alone, as the figures of docs/light-optimisation.md were measured (the
    // default objective, both, adds a depth-error search where the ratios raise the MSE).
    request.objective = model::LightObjective::Ratios;
    const std::uint64_t generation = cachedCurvature ? algo::newShapeGeneration() : 0;
    double mseBefore = 0, mseAfter = 0;
    std::size_t done = 0;
    for (auto _ : state) {
        const model::LightOptimisationReport report = model::optimiseLight(setup.data, setup.data.look,
            setup.data.baseMesh->vertices, generation, 0, setup.camera, 512, 512, request, analyser);
        mseBefore = report.mseBefore;
        mseAfter = report.mseAfter;
        done = report.run.iterations.size();
        benchmark::DoNotOptimize(report.after.vector);
    }
    state.counters["mse_before"] = mseBefore;
    state.counters["mse_after"] = mseAfter;
    state.counters["iterations"] = double(done);
}

void BM_LightIterations64_338k_512x512(benchmark::State& state)
{
    iterations(state, model338k(), false);
}
BENCHMARK(BM_LightIterations64_338k_512x512)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_LightIterations64_338k_512x512_PointLight(benchmark::State& state)
{
    iterations(state, model338k(), true);
}
BENCHMARK(BM_LightIterations64_338k_512x512_PointLight)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_LightIterations64_13k_512x512(benchmark::State& state)
{
    iterations(state, model13k(), false);
}
BENCHMARK(BM_LightIterations64_13k_512x512)->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_LightWholeRun_338k_512x512_CurvatureCached(benchmark::State& state)
{
    wholeRun(state, model338k(), true);
}
BENCHMARK(BM_LightWholeRun_338k_512x512_CurvatureCached)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_LightWholeRun_338k_512x512_WithCurvature(benchmark::State& state)
{
    wholeRun(state, model338k(), false);
}
BENCHMARK(BM_LightWholeRun_338k_512x512_WithCurvature)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_LightWholeRun_13k_512x512_WithCurvature(benchmark::State& state)
{
    wholeRun(state, model13k(), false);
}
BENCHMARK(BM_LightWholeRun_13k_512x512_WithCurvature)->Unit(benchmark::kMillisecond)->MinTime(1.0);

} // namespace

BENCHMARK_MAIN();
