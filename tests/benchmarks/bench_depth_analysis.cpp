// Depth analysis speed (paper 3, chapter 4):
// - the distance transform of a 2048x2048 feature map against OpenCV's cv::distanceTransform
//   (DIST_L2, DIST_MASK_PRECISE) on the same map, both on one thread (OpenCV only when its imgproc
//   headers are installed: a benchmark-only dependency);
// - the whole analysis of the dragon (871k triangles) at 1280x720: picture, G-buffer, segments and
//   depth error, with the curvature cached (a still shape, the editor orbiting) and recomputed.
#include "celform/algorithms/distance_transform.h"
#include "celform/model/analysis/depth_analysis.h"

#include "bench_data.h"

#include <benchmark/benchmark.h>

#ifdef CELFORM_HAVE_OPENCV
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#endif

#include <cmath>
#include <cstring>
#include <random>

namespace {

using namespace celform;

constexpr int kSide = 2048;

/// A feature map like a toon picture's: the edges of a few hundred discs (silhouettes and shading
/// lines) plus sparse noise, about 2% of the pixels.
const std::vector<std::uint8_t>& featureMap()
{
    static const std::vector<std::uint8_t> map = [] {
        std::vector<std::uint8_t> m(std::size_t(kSide) * kSide, 0);
        std::mt19937 random(11);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int disc = 0; disc < 300; ++disc) {
            const double cx = u(random) * kSide, cy = u(random) * kSide, r = 10 + u(random) * 120;
            for (int k = 0; k < int(2 * M_PI * r); ++k) {
                const double a = k / r;
                const int x = int(cx + r * std::cos(a)), y = int(cy + r * std::sin(a));
                if (x >= 0 && y >= 0 && x < kSide && y < kSide)
                    m[std::size_t(y) * kSide + std::size_t(x)] = 1;
            }
        }
        for (int i = 0; i < kSide * kSide / 500; ++i)
            m[std::size_t(random()) % m.size()] = 1;
        return m;
    }();
    return map;
}

void BM_NearestFeature_Celform(benchmark::State& state)
{
    const auto& map = featureMap();
    algo::DistanceTransformScratch scratch;
    std::vector<std::int32_t> nearest(map.size());
    for (auto _ : state) {
        algo::nearestFeatureTransform(map.data(), kSide, kSide, nearest.data(), nullptr, scratch);
        benchmark::DoNotOptimize(nearest.data());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(map.size()));
}
BENCHMARK(BM_NearestFeature_Celform)->Unit(benchmark::kMillisecond);

void BM_DistanceTransform_Celform(benchmark::State& state)
{
    const auto& map = featureMap();
    algo::DistanceTransformScratch scratch;
    std::vector<float> distance(map.size());
    for (auto _ : state) {
        algo::distanceTransform(map.data(), kSide, kSide, distance.data(), scratch);
        benchmark::DoNotOptimize(distance.data());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(map.size()));
}
BENCHMARK(BM_DistanceTransform_Celform)->Unit(benchmark::kMillisecond);

#ifdef CELFORM_HAVE_OPENCV
void BM_DistanceTransform_OpenCV(benchmark::State& state)
{
    const auto& map = featureMap();
    cv::setNumThreads(1); // the same thread count as ours
    // OpenCV measures the distance to the nearest zero pixel.
    cv::Mat source(kSide, kSide, CV_8UC1);
    for (std::size_t i = 0; i < map.size(); ++i)
        source.data[i] = map[i] ? 0 : 255;
    cv::Mat distance;
    for (auto _ : state) {
        cv::distanceTransform(source, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
        benchmark::DoNotOptimize(distance.data);
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(map.size()));
}
BENCHMARK(BM_DistanceTransform_OpenCV)->Unit(benchmark::kMillisecond);
#endif

void BM_Memcpy_FeatureMapAsFloats(benchmark::State& state)
{
    // The floor: writing the 16 MB a distance image takes.
    std::vector<float> a(std::size_t(kSide) * kSide, 1.f), b(a.size());
    for (auto _ : state) {
        std::memcpy(b.data(), a.data(), a.size() * sizeof(float));
        benchmark::DoNotOptimize(b.data());
    }
}
BENCHMARK(BM_Memcpy_FeatureMapAsFloats)->Unit(benchmark::kMillisecond);

void analyseDragon(benchmark::State& state, bool cachedCurvature)
{
    const algo::TriMesh* mesh = bench::dragon();
    if (!mesh) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    model::ProjectData data;
    data.baseMesh = std::make_shared<algo::TriMesh>(*mesh);
    model::Camera camera;
    const Eigen::Vector3d centre = algo::centroid(mesh->vertices);
    const double size = algo::boundingBox(mesh->vertices).diagonal().norm();
    camera.target = centre;
    camera.eye = centre + 1.9 * size * Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
    model::DepthAnalyser analyser;
    model::FrameAnalysis out;
    const std::uint64_t generation = cachedCurvature ? algo::newShapeGeneration() : 0;
    for (auto _ : state) {
        analyser.analyse(
            data, data.look, data.baseMesh->vertices, generation, 0, camera, 1280, 720, model::AnalysisSettings{}, out);
        benchmark::DoNotOptimize(out.analysis.meanSquaredError);
    }
    state.counters["segments"] = double(out.analysis.stats.size());
}

void BM_Analysis_Dragon_1280x720_CurvatureCached(benchmark::State& state)
{
    analyseDragon(state, true);
}
BENCHMARK(BM_Analysis_Dragon_1280x720_CurvatureCached)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_Analysis_Dragon_1280x720_WithCurvature(benchmark::State& state)
{
    analyseDragon(state, false);
}
BENCHMARK(BM_Analysis_Dragon_1280x720_WithCurvature)->Unit(benchmark::kMillisecond)->MinTime(2.0);

} // namespace

BENCHMARK_MAIN();
