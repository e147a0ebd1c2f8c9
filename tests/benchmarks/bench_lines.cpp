// Feature-line speed on the dragon (871k triangles): edge adjacency (once per topology), feature
// edges for one perspective frame (goal < 10 ms on one core, issue 25; with the default crease
// hysteresis) and chaining them into strokes. Baseline of the same run (issue 25): a memcpy of
// the edge arrays the extraction reads (vertex and face pairs per edge, 21 MB for the dragon).
// Run: bench_lines (medians of 5 repetitions; edge and stroke counts are printed as counters).
#include "celform/algorithms/lines.h"
#include "celform/model/io/mesh_io.h"

#include "bench_data.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>

#include <cstring>
#include <memory>
#include <vector>

namespace {

using namespace celform;

using bench::dragon;

const algo::EdgeTopology& dragonTopology()
{
    static const algo::EdgeTopology topology
        = algo::buildEdgeTopology(dragon()->faces, std::int32_t(dragon()->vertexCount()));
    return topology;
}

/// A perspective camera two bounding-box diagonals away, looking at the centre from the front-left.
algo::LineView dragonView(const algo::TriMesh& mesh)
{
    const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
    algo::LineView view;
    const Eigen::Vector3d eye
        = box.center() + 2.0 * box.diagonal().norm() * Eigen::Vector3d(-0.4, 0.3, 1.0).normalized();
    view.eye = eye.cast<float>();
    view.direction = (box.center() - eye).normalized().cast<float>();
    return view;
}

void BM_EdgeTopologyDragon(benchmark::State& state)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    std::int64_t edges = 0;
    for (auto _ : state) {
        const algo::EdgeTopology t = algo::buildEdgeTopology(mesh->faces, std::int32_t(mesh->vertexCount()));
        edges = t.edges.rows();
        benchmark::DoNotOptimize(t.edges.data());
    }
    state.counters["edges"] = double(edges);
}
BENCHMARK(BM_EdgeTopologyDragon)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_CopyEdgeArraysDragon(benchmark::State& state)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    const algo::EdgeTopology& topology = dragonTopology();
    const std::size_t bytes = sizeof(std::int32_t) * std::size_t(topology.edges.size());
    std::vector<std::int32_t> edges(std::size_t(topology.edges.size())), faces(std::size_t(topology.faces.size()));
    for (auto _ : state) {
        std::memcpy(edges.data(), topology.edges.data(), bytes);
        std::memcpy(faces.data(), topology.faces.data(), bytes);
        benchmark::DoNotOptimize(edges.data());
        benchmark::DoNotOptimize(faces.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(2 * bytes));
}
BENCHMARK(BM_CopyEdgeArraysDragon)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_ExtractFeatureEdgesDragon(benchmark::State& state)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    const algo::EdgeTopology& topology = dragonTopology();
    const algo::LineView view = dragonView(*mesh);
    const algo::LineSettings settings; // silhouettes, creases (45 degrees, hysteresis to 30), borders
    algo::FeatureEdges features;
    for (auto _ : state) {
        algo::extractFeatureEdges(mesh->vertices, mesh->faces, topology, mesh->faceMaterials, view, settings, features);
        benchmark::DoNotOptimize(features.edges.data());
    }
    state.counters["features"] = double(features.edges.size());
}
BENCHMARK(BM_ExtractFeatureEdgesDragon)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_ChainStrokesDragon(benchmark::State& state)
{
    const algo::TriMesh* mesh = dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    const algo::EdgeTopology& topology = dragonTopology();
    algo::FeatureEdges features;
    algo::extractFeatureEdges(
        mesh->vertices, mesh->faces, topology, mesh->faceMaterials, dragonView(*mesh), algo::LineSettings{}, features);
    std::size_t strokes = 0;
    for (auto _ : state) {
        const std::vector<algo::Stroke> s = algo::chainStrokes(topology, features);
        strokes = s.size();
        benchmark::DoNotOptimize(s.data());
    }
    state.counters["features"] = double(features.edges.size());
    state.counters["strokes"] = double(strokes);
}
BENCHMARK(BM_ChainStrokesDragon)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

} // namespace

BENCHMARK_MAIN();
