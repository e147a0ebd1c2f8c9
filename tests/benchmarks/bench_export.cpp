// Export speed: a PC2 point cache of 100 frames of the Stanford dragon
// (871k triangles) with four key viewpoints seen from a turntable, every frame evaluated by
// FrameEvaluator, against writing the same bytes from memory (fwrite, and QSaveFile as the
// exporter writes them): what the evaluation costs over the disk.
#include "bench_data.h"

#include "celform/model/export/export.h"

#include <benchmark/benchmark.h>

#include <QFileInfo>
#include <QSaveFile>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <random>

namespace {

using namespace celform;

constexpr int kFrames = 100;

/// The dragon with four keys (a tenth of the vertices offset each) and a 100-frame turntable.
const model::ProjectData* dragonShot()
{
    static const std::unique_ptr<model::ProjectData> project = []() -> std::unique_ptr<model::ProjectData> {
        const algo::TriMesh* mesh = bench::dragon();
        if (!mesh)
            return nullptr;
        auto data = std::make_unique<model::ProjectData>();
        data->baseMesh = std::make_shared<algo::TriMesh>(*mesh);
        data->baseMeshName = QStringLiteral("stanford_dragon.ply");
        const auto nv = std::uint32_t(mesh->vertexCount());
        std::mt19937 rng(13);
        std::uniform_real_distribution<float> offset(-0.002f, 0.002f);
        for (int k = 0; k < 4; ++k) {
            model::KeyViewpoint key;
            key.id = data->nextId++;
            key.name = QStringLiteral("key %1").arg(k);
            const double a = k * 2 * M_PI / 4;
            key.direction = Eigen::Vector3d(std::cos(a), 0.2, std::sin(a)).normalized();
            key.camera.eye = data->baseMesh->centre() + key.direction;
            key.camera.target = data->baseMesh->centre();
            model::SparseOffsets offsets;
            const std::uint32_t count = nv / 10, start = (nv / 4) * std::uint32_t(k) % (nv - count);
            for (std::uint32_t i = 0; i < count; ++i) {
                offsets.indices.push_back(start + i);
                offsets.deltas.emplace_back(offset(rng), offset(rng), offset(rng));
            }
            key.offsetsByFrame[0] = std::move(offsets);
            data->keys.push_back(std::move(key));
        }
        model::Turntable turntable;
        turntable.frames = kFrames;
        const double size = algo::boundingBox(mesh->vertices).diagonal().norm();
        data->look.cameraPath = model::turntablePath(turntable, data->baseMesh->centre(), 2.0 * size, model::Camera{});
        data->time.firstFrame = 0;
        data->time.lastFrame = kFrames - 1;
        return data;
    }();
    return project.get();
}

qint64 pc2Bytes(const model::ProjectData& data)
{
    return 32 + qint64(kFrames) * data.baseMesh->vertexCount() * 12;
}

void setCounters(benchmark::State& state, qint64 bytes)
{
    state.counters["MB"] = double(bytes) / 1e6;
    state.counters["MB/s"] = benchmark::Counter(double(bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ExportPc2Dragon100Frames(benchmark::State& state)
{
    const model::ProjectData* data = dragonShot();
    if (!data) {
        state.SkipWithError("shared test data not found (../shared/data/meshes/stanford_dragon.ply)");
        return;
    }
    QTemporaryDir dir;
    model::ExportJob job;
    job.format = model::ExportFormat::Pc2;
    job.firstFrame = 0;
    job.lastFrame = kFrames - 1;
    job.output = dir.filePath(QStringLiteral("dragon.pc2"));
    for (auto _ : state) {
        const model::ExportResult result = model::exportProject(*data, QStringLiteral("dragon"), job);
        benchmark::DoNotOptimize(result.frames);
    }
    if (QFileInfo(job.output).size() != pc2Bytes(*data))
        state.SkipWithError("the cache has the wrong size");
    setCounters(state, pc2Bytes(*data));
}

/// The same number of bytes, already in memory.
const std::vector<char>& sameBytes()
{
    static const std::vector<char> bytes(std::size_t(dragonShot() ? pc2Bytes(*dragonShot()) : 0), '\x7f');
    return bytes;
}

void BM_WriteSameBytesFwrite(benchmark::State& state)
{
    if (!dragonShot()) {
        state.SkipWithError("shared test data not found (../shared/data/meshes/stanford_dragon.ply)");
        return;
    }
    QTemporaryDir dir;
    const std::string path = dir.filePath(QStringLiteral("same.bin")).toStdString();
    const std::vector<char>& bytes = sameBytes();
    for (auto _ : state) {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        const std::size_t written = f ? std::fwrite(bytes.data(), 1, bytes.size(), f) : 0;
        if (!f || std::fclose(f) != 0 || written != bytes.size()) {
            state.SkipWithError("cannot write the temporary file");
            return;
        }
    }
    setCounters(state, qint64(bytes.size()));
}

void BM_WriteSameBytesQSaveFile(benchmark::State& state)
{
    if (!dragonShot()) {
        state.SkipWithError("shared test data not found (../shared/data/meshes/stanford_dragon.ply)");
        return;
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("same.bin"));
    const std::vector<char>& bytes = sameBytes();
    for (auto _ : state) {
        QSaveFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes.data(), qint64(bytes.size())) != qint64(bytes.size())
            || !f.commit()) {
            state.SkipWithError("cannot write the temporary file");
            return;
        }
    }
    setCounters(state, qint64(bytes.size()));
}

} // namespace

BENCHMARK(BM_ExportPc2Dragon100Frames)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_WriteSameBytesFwrite)->Unit(benchmark::kSecond)->UseRealTime()->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_WriteSameBytesQSaveFile)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
