// Loop subdivision per frame (issue 25): the elephant sample's base mesh to level 2 and the dragon
// to level 1 as one sparse product of the stencil (positions, then limit normals), each against a
// memcpy of the result's bytes in the same run; a brush step's partial update of about 200
// control vertices on the elephant at level 2 (goal: under 1 ms); the stencil's build.
#include "bench_data.h"

#include "celform/algorithms/subdivision.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/project_file.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

using namespace celform;
using namespace celform::algo;

namespace {

const TriMesh* elephant()
{
    static const std::shared_ptr<const TriMesh> mesh = [] {
        try {
            return model::loadProject(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform"))
                .baseMesh;
        } catch (...) {
            return std::shared_ptr<const TriMesh>();
        }
    }();
    return mesh.get();
}

struct Case {
    const TriMesh* mesh = nullptr;
    SubdivisionStencil stencil;
};

const Case& caseOf(const TriMesh* mesh, int level)
{
    static std::map<std::pair<const TriMesh*, int>, Case> cache;
    Case& c = cache[{mesh, level}];
    if (!c.mesh && mesh) {
        c.mesh = mesh;
        c.stencil = buildSubdivisionStencil(mesh->faces, std::int32_t(mesh->vertexCount()), level);
    }
    return c;
}

const TriMesh* meshOf(int which)
{
    return which == 0 ? elephant() : bench::dragon();
}
int levelOf(int which)
{
    return which == 0 ? 2 : 1;
}

void label(benchmark::State& state, const Case& c)
{
    state.SetLabel(std::to_string(c.mesh->faceCount()) + " to " + std::to_string(c.stencil.faceCount()) + " triangles, "
        + std::to_string(c.stencil.vertexCount()) + " vertices, "
        + std::to_string(c.stencil.positions.nonZeros() / std::max(1, c.stencil.vertexCount())) + " weights per row, "
        + std::to_string(c.stencil.tangentU.nonZeros() / std::max(1, c.stencil.vertexCount())) + " per tangent row, "
        + std::to_string(c.stencil.fallbackVertices.size()) + " fallback normals");
}

/// arg 0: the elephant at level 2; 1: the dragon at level 1.
void BM_SubdividePositions(benchmark::State& state)
{
    const TriMesh* mesh = meshOf(int(state.range(0)));
    if (!mesh) {
        state.SkipWithError("mesh not found");
        return;
    }
    const Case& c = caseOf(mesh, levelOf(int(state.range(0))));
    Positions out;
    applySubdivision(c.stencil, mesh->vertices, out);
    for (auto _ : state) {
        applySubdivision(c.stencil, mesh->vertices, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    label(state, c);
}

void BM_SubdividePositionsAndNormals(benchmark::State& state)
{
    const TriMesh* mesh = meshOf(int(state.range(0)));
    if (!mesh) {
        state.SkipWithError("mesh not found");
        return;
    }
    const Case& c = caseOf(mesh, levelOf(int(state.range(0))));
    Positions out, normals;
    applySubdivision(c.stencil, mesh->vertices, out);
    limitNormals(c.stencil, out, normals);
    for (auto _ : state) {
        applySubdivision(c.stencil, mesh->vertices, out);
        limitNormals(c.stencil, out, normals);
        benchmark::DoNotOptimize(normals.data());
        benchmark::ClobberMemory();
    }
    label(state, c);
}

/// The baseline: a memcpy of the subdivided positions' bytes.
void BM_MemcpyResult(benchmark::State& state)
{
    const TriMesh* mesh = meshOf(int(state.range(0)));
    if (!mesh) {
        state.SkipWithError("mesh not found");
        return;
    }
    const Case& c = caseOf(mesh, levelOf(int(state.range(0))));
    const std::size_t bytes = std::size_t(c.stencil.vertexCount()) * 3 * sizeof(float);
    std::vector<char> src(bytes, 1), dst(bytes, 0);
    for (auto _ : state) {
        std::memcpy(dst.data(), src.data(), bytes);
        benchmark::DoNotOptimize(dst.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * std::int64_t(bytes));
}

/// A brush step: about 200 control vertices near one vertex move; only their rows are redone.
void BM_PartialUpdateElephantLevel2(benchmark::State& state)
{
    const TriMesh* mesh = elephant();
    if (!mesh) {
        state.SkipWithError("sample not found");
        return;
    }
    const Case& c = caseOf(mesh, 2);
    Positions control = mesh->vertices, out, normals;
    applySubdivision(c.stencil, control, out);
    limitNormals(c.stencil, out, normals);
    std::vector<std::uint32_t> order(std::size_t(mesh->vertexCount()));
    std::iota(order.begin(), order.end(), 0u);
    const Eigen::RowVector3f centre = mesh->vertices.row(mesh->vertexCount() / 2);
    std::partial_sort(order.begin(), order.begin() + 200, order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return (mesh->vertices.row(a) - centre).squaredNorm() < (mesh->vertices.row(b) - centre).squaredNorm();
    });
    const std::vector<std::uint32_t> brushed(order.begin(), order.begin() + 200);
    SubdivisionScratch scratch;
    std::size_t rows = 0;
    float delta = 1e-4f;
    for (auto _ : state) {
        for (const auto v : brushed)
            control(v, 1) += delta;
        delta = -delta;
        rows = updateSubdivision(c.stencil, control, brushed, out, normals, scratch);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetLabel(std::to_string(brushed.size()) + " control vertices, " + std::to_string(rows) + " of "
        + std::to_string(c.stencil.vertexCount()) + " rows");
}

void BM_BuildStencil(benchmark::State& state)
{
    const TriMesh* mesh = meshOf(int(state.range(0)));
    if (!mesh) {
        state.SkipWithError("mesh not found");
        return;
    }
    for (auto _ : state) {
        const SubdivisionStencil s
            = buildSubdivisionStencil(mesh->faces, std::int32_t(mesh->vertexCount()), levelOf(int(state.range(0))));
        benchmark::DoNotOptimize(s.positions.weights.data());
        state.SetLabel(std::to_string(s.bytes() >> 20) + " MB");
    }
}

} // namespace

BENCHMARK(BM_SubdividePositions)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SubdividePositionsAndNormals)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MemcpyResult)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PartialUpdateElephantLevel2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BuildStencil)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
