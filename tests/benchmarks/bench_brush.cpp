// Brush speed on the dragon (437k vertices): one drag step (selection + displacements) with a
// radius that selects about 5,000 vertices, and building the vertex grid.
// Run: bench_brush (medians of 5 repetitions; the selection size is printed as a counter).
#include "celform/algorithms/brush.h"
#include "celform/model/io/mesh_io.h"

#include "bench_data.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <memory>

namespace {

using namespace celform;

using bench::dragon;

/// Radius around `picked` selecting about `target` vertices: the distance of the target-th nearest.
double radiusFor(const algo::Positions& v, std::uint32_t picked, std::size_t target)
{
    std::vector<float> d(std::size_t(v.rows()));
    for (Eigen::Index i = 0; i < v.rows(); ++i)
        d[std::size_t(i)] = (v.row(i) - v.row(picked)).norm();
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(target), d.end());
    return double(d[target]);
}

void BM_BrushStepDragon(benchmark::State& state)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    const algo::VertexGrid grid(mesh->vertices);
    const std::uint32_t picked = std::uint32_t(mesh->vertexCount() / 3);
    const double radius = radiusFor(mesh->vertices, picked, 5000);
    algo::ImageFrame frame;
    frame.forward = Eigen::Vector3d(-0.3, -0.2, -1.0).normalized();
    frame.right = frame.forward.cross(Eigen::Vector3d::UnitY()).normalized();
    frame.up = frame.right.cross(frame.forward);
    std::size_t selected = 0;
    for (auto _ : state) {
        const algo::BrushSelection selection = algo::selectForBrush(mesh->vertices, grid, picked, radius);
        const algo::Positions delta = algo::brushDrag(selection, frame, 0.001, -0.002);
        benchmark::DoNotOptimize(delta.data());
        selected = selection.indices.size();
    }
    state.counters["selected"] = double(selected);
}

void BM_GridBuildDragon(benchmark::State& state)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    for (auto _ : state) {
        const algo::VertexGrid grid(mesh->vertices);
        benchmark::DoNotOptimize(grid.empty());
    }
    state.counters["vertices"] = double(mesh->vertexCount());
}

} // namespace

BENCHMARK(BM_BrushStepDragon)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_GridBuildDragon)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
