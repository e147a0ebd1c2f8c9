// USD export speed (issue 28): a .usda layer of a few frames of the Stanford dragon (871k
// triangles, four keys, a turntable) with its points and normals time-sampled, against writing
// the same number of bytes from memory with fwrite in the same run: what the evaluation and
// the number formatting (std::to_chars into one buffer per frame) cost over the disk.
#include "bench_dragon_shot.h"

#include "celform/model/export/export.h"

#include <benchmark/benchmark.h>

#include <QFileInfo>
#include <QTemporaryDir>

namespace {

using namespace celform;

constexpr int kFrames = 5;
constexpr const char* kNoData = "shared test data not found (../shared/data/meshes/stanford_dragon.ply)";

model::ExportJob usdJob(const QString& output)
{
    model::ExportJob job;
    job.format = model::ExportFormat::Usda;
    job.firstFrame = 0;
    job.lastFrame = kFrames - 1;
    job.output = output;
    return job;
}

/// The size of the layer, measured by one export (the baseline writes as many bytes).
qint64 usdBytes()
{
    static const qint64 bytes = [] {
        const model::ProjectData* data = bench::dragonShot(kFrames);
        if (!data)
            return qint64(0);
        QTemporaryDir dir;
        const model::ExportJob job = usdJob(dir.filePath(QStringLiteral("size.usda")));
        model::exportProject(*data, QStringLiteral("dragon"), job);
        return QFileInfo(job.output).size();
    }();
    return bytes;
}

void setCounters(benchmark::State& state, qint64 bytes)
{
    state.counters["MB"] = double(bytes) / 1e6;
    state.counters["MB/s"] = benchmark::Counter(double(bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_ExportUsdDragon(benchmark::State& state)
{
    const model::ProjectData* data = bench::dragonShot(kFrames);
    if (!data) {
        state.SkipWithError(kNoData);
        return;
    }
    QTemporaryDir dir;
    const model::ExportJob job = usdJob(dir.filePath(QStringLiteral("dragon.usda")));
    for (auto _ : state) {
        const model::ExportResult result = model::exportProject(*data, QStringLiteral("dragon"), job);
        benchmark::DoNotOptimize(result.frames);
    }
    setCounters(state, QFileInfo(job.output).size());
}

/// The baseline: as many bytes as the layer has, already in memory, written with fwrite.
void BM_WriteSameBytesFwrite(benchmark::State& state)
{
    const qint64 size = usdBytes();
    if (size == 0) {
        state.SkipWithError(kNoData);
        return;
    }
    const std::vector<char> bytes(std::size_t(size), '\x37');
    QTemporaryDir dir;
    const std::string path = dir.filePath(QStringLiteral("same.bin")).toStdString();
    for (auto _ : state)
        if (!bench::fwriteBytes(path, bytes)) {
            state.SkipWithError("cannot write the temporary file");
            return;
        }
    setCounters(state, size);
}

} // namespace

BENCHMARK(BM_ExportUsdDragon)->Unit(benchmark::kSecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_WriteSameBytesFwrite)->Unit(benchmark::kSecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
