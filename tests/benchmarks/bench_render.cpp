// Offline render speed: the dragon (871k triangles) at 1920x1080, toon shading with lines, the
// whole frame (normals, G-buffer, line extraction and drawing, shading). Goal: under 0.5 s here.
// Issue 25: the toon frame without lines three ways, tone boundaries hard (the baseline, today's
// frame), anti-aliased by coverage (the default) and by 4x supersampling of the tone alone.
#include "celform/algorithms/render.h"
#include "celform/algorithms/srgb_encode.h"
#include "celform/model/io/mesh_io.h"

#include "bench_data.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

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
// Issue 29: the 8-bit encoding of a 1920x1080 RGBA frame, the power function per channel (the
// writer before) against the exact table (the writer now), with a memcpy of the frame's floats as
// the baseline of the same run.
std::vector<float> frameValues()
{
    std::vector<float> values(std::size_t(1920) * 1080 * 4);
    std::uint32_t state = 12345;
    for (float& v : values) {
        state = state * 1664525u + 1013904223u;
        v = float(state >> 8) / float(1u << 24);
    }
    return values;
}

void BM_EncodeFramePow(benchmark::State& state)
{
    const std::vector<float> in = frameValues();
    std::vector<std::uint8_t> out(in.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < in.size(); ++i)
            out[i]
                = (i & 3) == 3 ? std::uint8_t(std::lround(in[i] * 255.f)) : celform::algo::srgbEncode8Reference(in[i]);
        benchmark::DoNotOptimize(out.data());
    }
}

void BM_EncodeFrameTable(benchmark::State& state)
{
    const std::vector<float> in = frameValues();
    std::vector<std::uint8_t> out(in.size());
    for (auto _ : state) {
        celform::algo::quantise8(in.data(), out.data(), in.size(), 4, 3, true);
        benchmark::DoNotOptimize(out.data());
    }
}

void BM_EncodeFrameMemcpyBaseline(benchmark::State& state)
{
    const std::vector<float> in = frameValues();
    std::vector<float> out(in.size());
    for (auto _ : state) {
        std::memcpy(out.data(), in.data(), in.size() * sizeof(float));
        benchmark::DoNotOptimize(out.data());
    }
}

BENCHMARK(BM_EncodeFramePow)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeFrameTable)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeFrameMemcpyBaseline)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
