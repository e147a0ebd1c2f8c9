// Offline render speed: the dragon (871k triangles) at 1920x1080, toon shading with lines, the
// whole frame (normals, G-buffer, line extraction and drawing, shading). Goal: under 0.5 s here.
// Issue 25: the toon frame without lines three ways, tone boundaries hard (the baseline, today's
// frame), anti-aliased by coverage (the default) and by 4x supersampling of the tone alone.
#include "celform/algorithms/render.h"
#include "celform/model/io/mesh_io.h"

#include "bench_data.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>

namespace {

using namespace celform;

using bench::dragon;

void renderDragon(
    benchmark::State& state, bool lines, algo::ToneAntialiasing antialiasing = algo::RenderLook{}.toneAntialiasing)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    algo::RasterCamera camera;
    const Eigen::Vector3d centre = algo::centroid(mesh->vertices);
    const double size = algo::boundingBox(mesh->vertices).diagonal().norm();
    camera.target = centre;
    camera.eye = centre + 1.9 * size * Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
    camera.width = 1920;
    camera.height = 1080;
    algo::RenderLook look;
    look.style = algo::Style::Toon;
    look.lines = lines;
    look.toneAntialiasing = antialiasing;
    algo::RenderCache cache; // topology is built once, as in a sequence
    algo::RenderPasses out;
    for (auto _ : state) {
        algo::renderFrame(mesh->vertices, *mesh, camera, look, cache, out);
        benchmark::DoNotOptimize(out.beauty.pixels.data());
    }
}

void BM_RenderDragon1080pToonLines(benchmark::State& state)
{
    renderDragon(state, true);
}
void BM_RenderDragon1080pToon(benchmark::State& state)
{
    renderDragon(state, false);
}
void BM_RenderDragon1080pToonHardTones(benchmark::State& state)
{
    renderDragon(state, false, algo::ToneAntialiasing::Off);
}
void BM_RenderDragon1080pToonSupersampledTones(benchmark::State& state)
{
    renderDragon(state, false, algo::ToneAntialiasing::Supersample4);
}

} // namespace

BENCHMARK(BM_RenderDragon1080pToonLines)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_RenderDragon1080pToon)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_RenderDragon1080pToonHardTones)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_RenderDragon1080pToonSupersampledTones)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
