// Export speed: a PC2 point cache of 100 frames of the Stanford dragon
// (871k triangles) with four key viewpoints seen from a turntable, every frame evaluated by
// FrameEvaluator, against writing the same bytes from memory (fwrite, and QSaveFile as the
// exporter writes them): what the evaluation costs over the disk.
#include "bench_dragon_shot.h"

#include "celform/model/export/export.h"

#include <benchmark/benchmark.h>

#include <QFileInfo>
#include <QSaveFile>
#include <QTemporaryDir>

namespace {

using namespace celform;

constexpr int kFrames = 100;

const model::ProjectData* dragonShot()
{
    return bench::dragonShot(kFrames);
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
    for (auto _ : state)
        if (!bench::fwriteBytes(path, bytes)) {
            state.SkipWithError("cannot write the temporary file");
            return;
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
