// Curvature speed (principal curvatures and directions, derivative tensor, smoothed Gaussian) on
// the dragon (437k vertices) and the armadillo (26k), one thread, buffers reused as in the editor.
// Peer figure: trimesh2's need_curvatures() + need_dcurv() on the dragon, 0.62 s on one core here
// (quoted in the issue; trimesh2 is not packaged for Debian and is not built here).
// Run: bench_curvature (medians of 5 repetitions).
#include "celform/algorithms/curvature.h"

#include "bench_data.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace celform;

/// givenNormals: pass the mesh's cached normals in (the fit alone); otherwise computeCurvatures
/// computes Max-weighted normals itself, the recommended call and the one comparable with trimesh2.
void runCurvatures(benchmark::State& state, const char* relative, bool givenNormals)
{
    const algo::TriMesh* mesh = bench::sharedMesh(relative);
    if (!mesh) {
        state.SkipWithError((std::string("shared data not found: ") + relative).c_str());
        return;
    }
    const algo::Positions normals = givenNormals ? mesh->normals() : algo::Positions();
    algo::Curvatures curvatures;
    algo::computeCurvatures(mesh->vertices, mesh->faces, normals, curvatures); // first call allocates
    for (auto _ : state) {
        algo::computeCurvatures(mesh->vertices, mesh->faces, normals, curvatures);
        benchmark::DoNotOptimize(curvatures.gaussian.data());
    }
    state.counters["vertices"] = double(mesh->vertexCount());
}

void BM_CurvaturesDragon(benchmark::State& state)
{
    runCurvatures(state, "meshes/stanford_dragon.ply", false);
}
BENCHMARK(BM_CurvaturesDragon)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_CurvaturesArmadillo(benchmark::State& state)
{
    runCurvatures(state, "meshes/cgal_armadillo.off", false);
}
BENCHMARK(BM_CurvaturesArmadillo)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_CurvaturesDragonGivenNormals(benchmark::State& state)
{
    runCurvatures(state, "meshes/stanford_dragon.ply", true);
}
BENCHMARK(BM_CurvaturesDragonGivenNormals)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

} // namespace

BENCHMARK_MAIN();
