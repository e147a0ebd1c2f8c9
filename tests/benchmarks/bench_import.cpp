// Mesh import speed: the dragon PLY against the bare cost of reading its bytes, and a mid-size OFF;
// what reading in a child process costs (celform/model/io/import_process.h): GLB meshes through Assimp and a
// PSD drawing through OpenImageIO, each in this process and in the child.
// Run: bench_import (medians of 5 repetitions are printed).
#include "bench_data.h"

#include "celform/model/io/image_io.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/mesh_io.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtEndian>

#include <cstring>

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

/// A binary glTF of the mesh's positions and faces, written once per program into a temporary folder.
QString glbOf(const celform::algo::TriMesh& mesh, const QString& name)
{
    static QTemporaryDir folder;
    const QString path = folder.filePath(name);
    if (QFileInfo::exists(path))
        return path;
    const auto nv = mesh.vertexCount(), nf = mesh.faceCount();
    const Eigen::Vector3f lo = mesh.vertices.colwise().minCoeff(), hi = mesh.vertices.colwise().maxCoeff();
    QByteArray json = QStringLiteral(
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":%1,"type":"VEC3","min":[%3,%4,%5],)"
        R"("max":[%6,%7,%8]},{"bufferView":1,"componentType":5125,"count":%2,"type":"SCALAR"}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":%9},{"buffer":0,"byteOffset":%9,)"
        R"("byteLength":%10}],"buffers":[{"byteLength":%11}]})")
                          .arg(nv)
                          .arg(nf * 3)
                          .arg(lo.x())
                          .arg(lo.y())
                          .arg(lo.z())
                          .arg(hi.x())
                          .arg(hi.y())
                          .arg(hi.z())
                          .arg(nv * 12)
                          .arg(nf * 12)
                          .arg(nv * 12 + nf * 12)
                          .toUtf8();
    while (json.size() % 4 != 0)
        json += ' ';
    QByteArray bin(qsizetype(nv * 12 + nf * 12), '\0');
    std::memcpy(bin.data(), mesh.vertices.data(), std::size_t(nv * 12)); // little-endian host, row-major
    std::memcpy(bin.data() + nv * 12, mesh.faces.data(), std::size_t(nf * 12));
    QByteArray glb = "glTF";
    const auto put = [&glb](quint32 v) {
        char b[4];
        qToLittleEndian(v, b);
        glb.append(b, 4);
    };
    put(2);
    put(quint32(12 + 8 + json.size() + 8 + bin.size()));
    put(quint32(json.size()));
    glb += "JSON" + json;
    put(quint32(bin.size()));
    glb.append("BIN\0", 4);
    glb += bin;
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(glb) != glb.size())
        return {};
    return path;
}

celform::algo::TriMesh tetrahedron()
{
    celform::algo::TriMesh mesh;
    mesh.vertices.resize(4, 3);
    mesh.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    mesh.faces.resize(4, 3);
    mesh.faces << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
    return mesh;
}

void importGlb(benchmark::State& state, QString (*file)(), celform::model::ImportIsolation isolation)
{
    const QString path = file();
    if (path.isEmpty()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    for (auto _ : state) {
        try {
            auto result = celform::model::importMesh(path, isolation);
            benchmark::DoNotOptimize(result.mesh.vertices.data());
        } catch (const celform::model::IoError& e) {
            state.SkipWithError(e.what());
            return;
        }
    }
}

QString tetrahedronGlb()
{
    return glbOf(tetrahedron(), QStringLiteral("tetrahedron.glb"));
}

QString armadilloGlb()
{
    const celform::algo::TriMesh* mesh = celform::bench::sharedMesh("meshes/cgal_armadillo.off");
    return mesh ? glbOf(*mesh, QStringLiteral("armadillo.glb")) : QString();
}

/// A raw 8-bit RGB PSD of side x side pixels without layers.
QByteArray psd(int side)
{
    QByteArray out("8BPS\0\1\0\0\0\0\0\0\0\3", 14);
    const auto put = [&out](quint32 v, int bytes) {
        for (int k = bytes - 1; k >= 0; --k)
            out.append(char((v >> (8 * k)) & 0xff));
    };
    put(quint32(side), 4);
    put(quint32(side), 4);
    put(8, 2);
    put(3, 2);
    put(0, 4);
    put(0, 4);
    put(0, 4);
    put(0, 2);
    for (int i = 0; i < 3 * side * side; ++i)
        out.append(char(i * 7));
    return out;
}

void decodePsd(benchmark::State& state, celform::model::ImportIsolation isolation)
{
    const QByteArray bytes = psd(int(state.range(0)));
    for (auto _ : state) {
        try {
            const QImage image = celform::model::decodeImage(bytes, QStringLiteral("psd"), "bench.psd", isolation);
            benchmark::DoNotOptimize(image.constBits());
        } catch (const celform::model::IoError& e) {
            state.SkipWithError(e.what());
            return;
        }
    }
}

/// Medians of 5 repetitions, in milliseconds of wall-clock time.
void medians(benchmark::internal::Benchmark* b)
{
    b->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
}

} // namespace

BENCHMARK(BM_ReadBytesDragon)->Apply(medians);
BENCHMARK(BM_ImportDragonPly)->Apply(medians);
BENCHMARK(BM_ImportArmadilloOff)->Apply(medians);
// In this process against the child: the child's start (fork, exec, Qt, Assimp or OpenImageIO
// loaded again) and the round trip of the result through a temporary file.
using celform::model::ImportIsolation;
BENCHMARK_CAPTURE(importGlb, TetrahedronThisProcess, tetrahedronGlb, ImportIsolation::ThisProcess)->Apply(medians);
BENCHMARK_CAPTURE(importGlb, TetrahedronChild, tetrahedronGlb, ImportIsolation::ChildProcess)->Apply(medians);
BENCHMARK_CAPTURE(importGlb, ArmadilloThisProcess, armadilloGlb, ImportIsolation::ThisProcess)->Apply(medians);
BENCHMARK_CAPTURE(importGlb, ArmadilloChild, armadilloGlb, ImportIsolation::ChildProcess)->Apply(medians);
BENCHMARK_CAPTURE(decodePsd, ThisProcess, ImportIsolation::ThisProcess)->Arg(64)->Arg(2048)->Apply(medians);
BENCHMARK_CAPTURE(decodePsd, Child, ImportIsolation::ChildProcess)->Arg(64)->Arg(2048)->Apply(medians);

BENCHMARK_MAIN();
