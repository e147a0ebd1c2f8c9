// Project save and open speed on the dragon (871k triangles) with 20 key viewpoints, each moving
// 10% of the vertices, against a plain write and read of the same number of bytes.
// Run: bench_project (medians of 5 repetitions; the file size is printed as a counter).
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"
#include "celform/model/io/project_file.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <random>

namespace {

using namespace celform;

/// The benchmark project, built once: dragon + 20 keys with sparse offsets on 10% of vertices.
const model::ProjectData* dragonProject()
{
    static std::unique_ptr<model::ProjectData> project = [] {
        const QString path
            = QDir(QStringLiteral(CELFORM_SHARED_DATA_DIR)).filePath(QStringLiteral("meshes/stanford_dragon.ply"));
        if (!QFileInfo::exists(path))
            return std::unique_ptr<model::ProjectData>();
        auto data = std::make_unique<model::ProjectData>();
        auto mesh = std::make_shared<algo::TriMesh>(model::importMesh(path).mesh);
        const auto nv = std::uint32_t(mesh->vertexCount());
        data->baseMesh = mesh;
        data->baseMeshName = QStringLiteral("stanford_dragon.ply");
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> offset(-0.01f, 0.01f);
        for (int k = 0; k < 20; ++k) {
            model::KeyViewpoint key;
            key.id = data->nextId++;
            key.name = QStringLiteral("key %1").arg(k);
            const double a = k * 2 * 3.14159265 / 20;
            key.direction = Eigen::Vector3d(std::cos(a), 0.3, std::sin(a)).normalized();
            key.camera.eye = key.direction * 3;
            model::SparseOffsets offsets;
            // A contiguous-ish 10% region per key, as a brush would make, at a different place each time.
            const std::uint32_t count = nv / 10, start = (nv / 20) * std::uint32_t(k) % (nv - count);
            for (std::uint32_t i = 0; i < count; ++i) {
                offsets.indices.push_back(start + i);
                offsets.deltas.emplace_back(offset(rng), offset(rng), offset(rng));
            }
            key.offsetsByFrame[0] = std::move(offsets);
            data->keys.push_back(std::move(key));
        }
        return data;
    }();
    return project.get();
}

QString benchFile(const QTemporaryDir& dir)
{
    return dir.filePath(QStringLiteral("dragon.celform"));
}

void BM_SaveProject(benchmark::State& state)
{
    const auto* project = dragonProject();
    if (!project) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    QTemporaryDir dir;
    for (auto _ : state)
        model::saveProject(*project, benchFile(dir), /*keepBackup=*/true);
    state.counters["file_MB"] = double(QFileInfo(benchFile(dir)).size()) / 1e6;
}

void BM_OpenProject(benchmark::State& state)
{
    const auto* project = dragonProject();
    if (!project) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    QTemporaryDir dir;
    model::saveProject(*project, benchFile(dir));
    for (auto _ : state) {
        model::ProjectData loaded = model::loadProject(benchFile(dir));
        benchmark::DoNotOptimize(loaded.keys.data());
    }
    state.counters["file_MB"] = double(QFileInfo(benchFile(dir)).size()) / 1e6;
}

/// Baseline: write the same number of bytes with QFile and fsync-free close, then read them back.
void BM_WriteReadSameBytes(benchmark::State& state)
{
    const auto* project = dragonProject();
    if (!project) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    QTemporaryDir dir;
    model::saveProject(*project, benchFile(dir));
    const qint64 size = QFileInfo(benchFile(dir)).size();
    const QByteArray bytes(size, 'x');
    const QString path = dir.filePath(QStringLiteral("raw.bin"));
    for (auto _ : state) {
        QFile out(path);
        out.open(QIODevice::WriteOnly | QIODevice::Truncate);
        out.write(bytes);
        out.close();
        QFile in(path);
        in.open(QIODevice::ReadOnly);
        benchmark::DoNotOptimize(in.readAll().size());
    }
}

} // namespace

BENCHMARK(BM_SaveProject)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_OpenProject)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_WriteReadSameBytes)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
