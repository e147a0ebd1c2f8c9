// Mesh import speed: the dragon PLY against the bare cost of reading its bytes, and a mid-size OFF.
// Run: bench_import (medians of 5 repetitions are printed).
#include "celform/model/io_error.h"
#include "celform/model/mesh_io.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace {

QString sharedFile(const char* relative)
{
    const QString path = QDir(QStringLiteral(CELFORM_SHARED_DATA_DIR)).filePath(QString::fromUtf8(relative));
    return QFileInfo::exists(path) ? path : QString();
}

void importFile(benchmark::State& state, const char* relative)
{
    const QString path = sharedFile(relative);
    if (path.isEmpty()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    for (auto _ : state) {
        try {
            auto result = celform::model::importMesh(path);
            benchmark::DoNotOptimize(result.mesh.vertices.data());
        } catch (const celform::model::IoError& e) {
            state.SkipWithError(e.what());
            return;
        }
    }
}

void BM_ReadBytesDragon(benchmark::State& state)
{
    const QString path = sharedFile("meshes/stanford_dragon.ply");
    if (path.isEmpty()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    for (auto _ : state) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) {
            state.SkipWithError("cannot open the dragon");
            return;
        }
        const QByteArray bytes = file.readAll();
        benchmark::DoNotOptimize(bytes.constData());
    }
}

void BM_ImportDragonPly(benchmark::State& state)
{
    importFile(state, "meshes/stanford_dragon.ply");
}
void BM_ImportArmadilloOff(benchmark::State& state)
{
    importFile(state, "meshes/cgal_armadillo.off");
}

} // namespace

BENCHMARK(BM_ReadBytesDragon)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ImportDragonPly)->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_ImportArmadilloOff)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

BENCHMARK_MAIN();
