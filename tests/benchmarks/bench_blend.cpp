// Shape blending against memcpy of the same memory traffic, and the viewing sphere's build and
// facet lookup with 1,000 keys (paper 1, section 3.2).
#include "celform/algorithms/blend.h"
#include "celform/algorithms/view_sphere.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <random>
#include <vector>

using namespace celform::algo;

namespace {

constexpr int kVertices = 1000000;
constexpr int kKeys = 3;

Positions randomPositions(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.f, 1.f);
    Positions p(n, 3);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
            p(i, k) = u(rng);
    return p;
}

std::vector<Eigen::Vector3d> randomKeys(int count, unsigned seed)
{
    // Rejects directions closer than 1 degree to an earlier one (ViewSphere refuses 0.5).
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    const double minCos = std::cos(1.0 * 3.14159265358979 / 180.0);
    std::vector<Eigen::Vector3d> keys;
    while (static_cast<int>(keys.size()) < count) {
        const Eigen::Vector3d v = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
        bool ok = true;
        for (const auto& k : keys)
            ok = ok && k.dot(v) < minCos;
        if (ok)
            keys.push_back(v);
    }
    return keys;
}

void BM_BlendDense1M(benchmark::State& state)
{
    const Positions base = randomPositions(kVertices, 1);
    std::vector<Positions> offsets;
    std::vector<WeightedOffsets> keys;
    for (int k = 0; k < kKeys; ++k)
        offsets.push_back(randomPositions(kVertices, 10 + k));
    for (int k = 0; k < kKeys; ++k)
        keys.push_back({{nullptr, offsets[k].data(), std::size_t(kVertices), true}, 0.3f});
    Positions out(kVertices, 3);
    for (auto _ : state) {
        blendShape(base, keys, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    // Bytes moved: base and three offset arrays read, out written.
    state.SetBytesProcessed(state.iterations() * int64_t(kVertices) * 12 * (kKeys + 2));
}

/// memcpy whose read + written bytes equal the dense blend's: (4 reads + 1 write) * 12 MB / 2.
void BM_MemcpySameBytes(benchmark::State& state)
{
    const std::size_t bytes = std::size_t(kVertices) * 12 * (kKeys + 2) / 2;
    std::vector<char> src(bytes, 1);
    std::vector<char> dst(bytes, 0);
    for (auto _ : state) {
        std::memcpy(dst.data(), src.data(), bytes);
        benchmark::DoNotOptimize(dst.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * int64_t(bytes) * 2);
}

void BM_BlendSparse(benchmark::State& state)
{
    const Positions base = randomPositions(kVertices, 1);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> pick(0.0, 1.0);
    std::vector<std::vector<std::uint32_t>> indices(kKeys);
    std::vector<std::vector<float>> offsets(kKeys);
    std::vector<WeightedOffsets> keys;
    for (int k = 0; k < kKeys; ++k) {
        for (int i = 0; i < kVertices; ++i) {
            if (pick(rng) < 0.1) {
                indices[k].push_back(std::uint32_t(i));
                offsets[k].insert(offsets[k].end(), {0.1f, -0.2f, 0.3f});
            }
        }
        keys.push_back({{indices[k].data(), offsets[k].data(), indices[k].size(), false}, 0.3f});
    }
    Positions out(kVertices, 3);
    for (auto _ : state) {
        blendShape(base, keys, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
}

void BM_FacetLookup1000Keys(benchmark::State& state)
{
    const auto sphere = ViewSphere::build(randomKeys(1000, 2), UnspecifiedRegions::Dummy);
    if (!sphere) {
        state.SkipWithError("build failed");
        return;
    }
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    std::vector<Eigen::Vector3d> views(4096);
    for (auto& v : views)
        v = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    std::size_t i = 0;
    for (auto _ : state) {
        ViewBlend b = sphere->blend(views[i++ & 4095], 2.0);
        benchmark::DoNotOptimize(b);
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_BuildSphere1000Keys(benchmark::State& state)
{
    const auto keys = randomKeys(1000, 2);
    for (auto _ : state) {
        auto sphere = ViewSphere::build(keys, UnspecifiedRegions::Dummy);
        benchmark::DoNotOptimize(sphere);
    }
}

} // namespace

BENCHMARK(BM_BlendDense1M)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_MemcpySameBytes)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_BlendSparse)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_FacetLookup1000Keys)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_BuildSphere1000Keys)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

BENCHMARK_MAIN();
