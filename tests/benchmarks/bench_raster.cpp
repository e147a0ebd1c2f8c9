// CPU rasteriser speed (DESIGN.md, "Rendering"): the dragon (871k triangles) into a 1080p
// G-buffer with a framed perspective camera, and 5,000 random anti-aliased strokes.
// Run: bench_raster (medians of 5 repetitions; covered pixels printed as a counter).
#include "celform/algorithms/raster.h"
#include "celform/model/io/mesh_io.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <memory>
#include <random>

namespace {

using namespace celform;

struct Dragon {
    algo::TriMesh mesh;
    algo::Positions normals;
};

const Dragon* dragon()
{
    static std::unique_ptr<Dragon> data = [] {
        const QString path
            = QDir(QStringLiteral(CELFORM_SHARED_DATA_DIR)).filePath(QStringLiteral("meshes/stanford_dragon.ply"));
        if (!QFileInfo::exists(path))
            return std::unique_ptr<Dragon>();
        auto d = std::make_unique<Dragon>();
        d->mesh = model::importMesh(path).mesh;
        d->normals = algo::vertexNormals(d->mesh.vertices, d->mesh.faces);
        return d;
    }();
    return data.get();
}

/// A 1920 x 1080 perspective camera that frames the bounding sphere of the vertices.
algo::RasterCamera framedCamera(const algo::Positions& vertices)
{
    const Eigen::AlignedBox3d box = algo::boundingBox(vertices);
    const double radius = 0.5 * box.diagonal().norm();
    algo::RasterCamera c;
    c.width = 1920;
    c.height = 1080;
    c.fovYDegrees = 30;
    c.target = box.center();
    const double distance = radius / std::sin(0.5 * c.fovYDegrees * M_PI / 180.0);
    c.eye = c.target + distance * Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
    c.up = Eigen::Vector3d::UnitY();
    return c;
}

void BM_RasterizeDragon1080p(benchmark::State& state)
{
    const Dragon* d = dragon();
    if (!d) {
        state.SkipWithError("shared data not found: meshes/stanford_dragon.ply");
        return;
    }
    const algo::RasterCamera camera = framedCamera(d->mesh.vertices);
    algo::GBuffer g;
    for (auto _ : state) {
        algo::rasterise(d->mesh.vertices, d->mesh.faces, d->normals, camera, g);
        benchmark::DoNotOptimize(g.depth.data());
    }
    std::size_t covered = 0;
    for (std::int32_t id : g.faceId)
        covered += id >= 0 ? 1 : 0;
    state.counters["triangles"] = double(d->mesh.faceCount());
    state.counters["covered"] = double(covered);
}

void BM_DrawStrokes(benchmark::State& state)
{
    // A G-buffer half covered by a quad at depth 10, so half the samples take the depth test.
    algo::Positions v(4, 3);
    v << -960, -540, 0, 0, -540, 0, 0, 540, 0, -960, 540, 0;
    algo::Faces f(2, 3);
    f << 0, 1, 2, 0, 2, 3;
    algo::RasterCamera camera;
    camera.eye = Eigen::Vector3d(0, 0, 10);
    camera.orthographic = true;
    camera.orthoHeight = 1080;
    camera.width = 1920;
    camera.height = 1080;
    algo::GBuffer g;
    algo::rasterise(v, f, algo::Positions(0, 3), camera, g);

    // 5,000 strokes of 10 points, a few pixels per segment like chained mesh edges.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> px(0.f, 1920.f), py(0.f, 1080.f), step(-6.f, 6.f);
    std::uniform_real_distribution<float> width(1.f, 4.f), depth(8.f, 12.f);
    std::vector<algo::StyledStroke> strokes(5000);
    for (algo::StyledStroke& s : strokes) {
        Eigen::Vector2f p(px(rng), py(rng));
        for (int k = 0; k < 10; ++k) {
            s.points.push_back(p);
            s.widths.push_back(width(rng));
            s.depths.push_back(depth(rng));
            p += Eigen::Vector2f(step(rng), step(rng));
        }
    }
    std::vector<float> coverage;
    for (auto _ : state) {
        coverage.assign(std::size_t(1920 * 1080), 0.f);
        algo::drawStrokes(strokes, g, coverage);
        benchmark::DoNotOptimize(coverage.data());
    }
    state.counters["segments"] = double(strokes.size() * 9);
}

} // namespace

BENCHMARK(BM_RasterizeDragon1080p)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_DrawStrokes)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

BENCHMARK_MAIN();
