// Fit to Drawing on the elephant with a 1024 px synthetic model sheet (the mesh pulled in the image
// plane, its silhouette drawn from a known camera): the camera fit from 7 degrees off (goal: at
// most 1 s on the 2-core machine), the shape fit from the known camera (goal: at most 2 s), the
// outline extraction, and the shape fit on the dragon (goal: at most 30 s).
// Run: bench_fit (medians of 5 repetitions; IoU and chamfer after the fit are counters).
#include "celform/algorithms/fit_camera.h"
#include "celform/algorithms/fit_shape.h"

#include "bench_data.h"
#include "fit_model_sheet.h"

#include <benchmark/benchmark.h>

namespace {

using namespace celform;

const Eigen::Vector3d kView(0.8, 0.15, 0.55);

const algo::TriMesh* elephant()
{
    return bench::sharedMesh("meshes/cgal_elephant.off");
}

const test::ModelSheet& elephantSheet()
{
    static const test::ModelSheet sheet = test::makeModelSheet(*elephant(), kView, 1024, 0.04);
    return sheet;
}

void BM_FitCameraElephant1024(benchmark::State& state)
{
    const algo::TriMesh* mesh = elephant();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/cgal_elephant.off");
        return;
    }
    const test::ModelSheet& sheet = elephantSheet();
    const algo::RasterCamera start = algo::orbitCamera(sheet.camera, algo::centroid(mesh->vertices), 6.0, -4.0);
    (void)mesh->edgeTopology();
    algo::FitCameraResult result;
    for (auto _ : state) {
        result = algo::fitCamera(mesh->vertices, mesh->faces, mesh->edgeTopology(), start, sheet.outline);
        benchmark::DoNotOptimize(result.camera.eye.data());
    }
    const Eigen::Vector3d centre = algo::centroid(mesh->vertices);
    state.counters["iou"] = result.after.iou;
    state.counters["chamfer_px"] = result.after.chamferPx;
    state.counters["error_deg"]
        = std::acos(std::clamp(
              algo::viewDirection(result.camera, centre).dot(algo::viewDirection(sheet.camera, centre)), -1.0, 1.0))
        * 180.0 / 3.14159265358979323846;
    state.counters["iterations"] = result.iterations;
}

void BM_FitShapeElephant1024(benchmark::State& state)
{
    const algo::TriMesh* mesh = elephant();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/cgal_elephant.off");
        return;
    }
    const test::ModelSheet& sheet = elephantSheet();
    (void)mesh->edgeTopology();
    algo::FitShapeResult result;
    for (auto _ : state) {
        result = algo::fitShape(mesh->vertices, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline);
        benchmark::DoNotOptimize(result.displacements.data());
    }
    state.counters["iou"] = result.after.iou;
    state.counters["chamfer_px"] = result.after.chamferPx;
    state.counters["rounds"] = result.rounds;
}

void BM_OutlineElephant1024(benchmark::State& state)
{
    const algo::TriMesh* mesh = elephant();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/cgal_elephant.off");
        return;
    }
    const test::ModelSheet& sheet = elephantSheet();
    const algo::DrawingImage drawing = test::silhouetteDrawing(sheet.pulled, mesh->faces, sheet.camera);
    for (auto _ : state) {
        const algo::Outline outline = algo::extractOutline(drawing);
        benchmark::DoNotOptimize(outline.contours.data());
    }
}

void BM_FitShapeDragon1024(benchmark::State& state)
{
    const algo::TriMesh* mesh = bench::dragon();
    if (!mesh) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    static const test::ModelSheet sheet = test::makeModelSheet(*mesh, Eigen::Vector3d(0.2, 0.3, 1.0), 1024, 0.03);
    (void)mesh->edgeTopology();
    algo::FitShapeResult result;
    for (auto _ : state) {
        result = algo::fitShape(mesh->vertices, mesh->faces, mesh->edgeTopology(), sheet.camera, sheet.outline);
        benchmark::DoNotOptimize(result.displacements.data());
    }
    state.counters["iou_before"] = result.before.iou;
    state.counters["iou"] = result.after.iou;
    state.counters["chamfer_px"] = result.after.chamferPx;
    state.counters["rounds"] = result.rounds;
}

} // namespace

BENCHMARK(BM_FitCameraElephant1024)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_FitShapeElephant1024)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_OutlineElephant1024)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_FitShapeDragon1024)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(1);

BENCHMARK_MAIN();
