// Interactive speed of the viewport. Needs an X server: run under xvfb-run (Mesa llvmpipe there,
// so the figures are a software-GL floor).
// - orbiting the armadillo (52k triangles) with and without the view-dependent preview (paper 1,
//   section 3.2), and with the Depth dock's segment overlay following the camera,
//   frames per second as a rate counter;
// - a large mesh: the dragon (871k triangles) in a 400x300 viewport, as test_viewport shows it:
//   a document reset to it (the viewport rebuilds its polydata and frames it), the same until the
//   first frame is drawn, and a mesh edit alone (meshChanged: the polydata is rebuilt). The aim
//   for the mesh edit is well under 200 ms.
#include "celform/model/document/document.h"
#include "celform/model/io/mesh_io.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/overlays/depth_overlay.h"
#include "celform/views/viewport/viewport.h"

#include "bench_data.h"
#include "bench_gui.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <memory>

namespace {

using namespace celform;

struct Scene {
    model::Document document;
    std::unique_ptr<views::Viewport> viewport;
    bool ok = false;
};

bool g_sceneBuilt = false;

/// The armadillo with four keys around it, each moving a tenth of the vertices.
Scene& scene()
{
    static Scene scene;
    if (g_sceneBuilt)
        return scene;
    g_sceneBuilt = true;
    {
        const QString path
            = QDir(QStringLiteral(CELFORM_SHARED_DATA_DIR)).filePath(QStringLiteral("meshes/cgal_armadillo.off"));
        if (!QFileInfo::exists(path) || qEnvironmentVariableIsEmpty("DISPLAY"))
            return scene;
        model::ProjectData data;
        data.baseMesh = std::make_shared<algo::TriMesh>(model::importMesh(path).mesh);
        scene.document.reset(std::move(data));
        const auto nv = std::uint32_t(scene.document.data().baseMesh->vertexCount());
        const Eigen::Vector3d centre = algo::centroid(scene.document.data().baseMesh->vertices);
        for (int k = 0; k < 4; ++k) {
            model::Camera camera;
            const double a = k * M_PI / 2;
            camera.target = centre;
            camera.eye = centre + 300.0 * Eigen::Vector3d(std::cos(a), 0.2, std::sin(a));
            model::SparseOffsets offsets;
            for (std::uint32_t v = std::uint32_t(k) * nv / 4; v < std::uint32_t(k) * nv / 4 + nv / 10; ++v) {
                offsets.indices.push_back(v);
                offsets.deltas.emplace_back(0.5f, 0.0f, 0.0f);
            }
            scene.document.keys().createKey(QStringLiteral("k%1").arg(k), camera, {}, offsets);
        }
        scene.viewport = std::make_unique<views::Viewport>(&scene.document);
        scene.viewport->resize(1280, 720);
        scene.viewport->show();
        for (int i = 0; i < 20 && scene.viewport->renderCount() == 0; ++i)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
        scene.ok = scene.viewport->renderCount() > 0;
    }
    return scene;
}

void orbitFrames(benchmark::State& state, bool preview, bool depthOverlay = false)
{
    Scene& s = scene();
    if (!s.ok) {
        state.SkipWithError("needs ../shared/data and an X server (run under xvfb-run)");
        return;
    }
    s.viewport->setPreview(preview);
    // The Depth dock's analysis following the camera on its worker thread, with the
    // segment overlay drawn over the viewport.
    std::unique_ptr<views::DepthAnalysisRunner> runner;
    std::unique_ptr<views::DepthOverlay> overlay;
    int analyses = 0;
    if (depthOverlay) {
        runner = std::make_unique<views::DepthAnalysisRunner>(&s.document, s.viewport.get());
        overlay = std::make_unique<views::DepthOverlay>(s.viewport.get(), runner.get());
        overlay->setKind(views::DepthOverlay::Kind::Segments);
        QObject::connect(runner.get(), &views::DepthAnalysisRunner::analysed, [&analyses] { ++analyses; });
        runner->setActive(true);
    }
    model::Camera camera = s.viewport->camera();
    const Eigen::Vector3d pivot = s.viewport->pivot();
    const int before = s.viewport->renderCount();
    for (auto _ : state) {
        // One orbit step of 2 degrees about the vertical, then the frame it asks for, drawn and
        // handed to the window as the event loop does.
        camera.eye = pivot + Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()) * (camera.eye - pivot);
        s.viewport->setCamera(camera);
        const int frame = s.viewport->renderCount();
        while (s.viewport->renderCount() == frame)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["frames"] = double(s.viewport->renderCount() - before);
    if (depthOverlay)
        state.counters["analyses"] = double(analyses);
}

struct DragonScene {
    model::Document document;
    std::unique_ptr<views::Viewport> viewport;
    std::shared_ptr<algo::TriMesh> dragon;
    /// What the document shows between timed resets, so that each reset really changes the mesh.
    std::shared_ptr<algo::TriMesh> small;
    bool ok = false;
};

bool g_dragonBuilt = false;

/// Waits until the viewport has drawn a frame after the one counted in before.
bool waitForFrame(views::Viewport& viewport, int before)
{
    viewport.update();
    for (int i = 0; i < 1000 && viewport.renderCount() == before; ++i)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return viewport.renderCount() > before;
}

DragonScene& dragonScene()
{
    static DragonScene scene;
    if (g_dragonBuilt)
        return scene;
    g_dragonBuilt = true;
    const algo::TriMesh* dragon = bench::dragon();
    if (!dragon || qEnvironmentVariableIsEmpty("DISPLAY"))
        return scene;
    scene.dragon = std::make_shared<algo::TriMesh>(*dragon);
    // A tetrahedron: what the document holds between timed resets.
    scene.small = std::make_shared<algo::TriMesh>();
    scene.small->vertices.resize(4, 3);
    scene.small->vertices << 0, 0, 0, 0.1f, 0, 0, 0, 0.1f, 0, 0, 0, 0.1f;
    scene.small->faces.resize(4, 3);
    scene.small->faces << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
    model::ProjectData data;
    data.baseMesh = scene.small;
    scene.document.reset(std::move(data));
    scene.viewport = std::make_unique<views::Viewport>(&scene.document);
    scene.viewport->resize(400, 300);
    scene.viewport->show();
    scene.ok = waitForFrame(*scene.viewport, 0);
    return scene;
}

void resetTo(DragonScene& s, const std::shared_ptr<algo::TriMesh>& mesh)
{
    model::ProjectData data;
    data.baseMesh = mesh;
    s.document.reset(std::move(data)); // the viewport rebuilds on documentReset
}

/// A document reset to the dragon, from the small mesh (reset outside the timing); with
/// toFirstFrame, until the viewport has drawn the dragon.
void dragonReset(benchmark::State& state, bool toFirstFrame)
{
    DragonScene& s = dragonScene();
    if (!s.ok) {
        state.SkipWithError("needs ../shared/data and an X server (run under xvfb-run)");
        return;
    }
    for (auto _ : state) {
        state.PauseTiming();
        resetTo(s, s.small);
        waitForFrame(*s.viewport, s.viewport->renderCount());
        const int before = s.viewport->renderCount();
        state.ResumeTiming();
        resetTo(s, s.dragon);
        if (toFirstFrame && !waitForFrame(*s.viewport, before)) {
            state.SkipWithError("the viewport did not draw");
            return;
        }
    }
}

void BM_DragonReset(benchmark::State& state)
{
    dragonReset(state, false);
}

void BM_DragonResetToFirstFrame(benchmark::State& state)
{
    dragonReset(state, true);
}

/// A mesh edit alone on the dragon: the viewport rebuilds the polydata (drawing not included).
void BM_DragonMeshRebuild(benchmark::State& state)
{
    DragonScene& s = dragonScene();
    if (!s.ok) {
        state.SkipWithError("needs ../shared/data and an X server (run under xvfb-run)");
        return;
    }
    if (s.document.data().baseMesh != s.dragon) {
        resetTo(s, s.dragon);
        waitForFrame(*s.viewport, s.viewport->renderCount());
    }
    model::ChangeSet meshChange = model::ChangeSet::of(model::Part::Mesh);
    meshChange.structure = true;
    for (auto _ : state) {
        emit s.document.changed(meshChange);
        // The rebuild is lazy: the frame pays for it, so each iteration paints one.
        waitForFrame(*s.viewport, s.viewport->renderCount());
    }
    // The frame each edit asked for, outside the timing.
    waitForFrame(*s.viewport, s.viewport->renderCount());
}

void BM_OrbitArmadillo(benchmark::State& state)
{
    orbitFrames(state, false);
}
void BM_OrbitArmadilloPreview(benchmark::State& state)
{
    orbitFrames(state, true);
}
void BM_OrbitArmadilloDepthOverlay(benchmark::State& state)
{
    orbitFrames(state, false, true);
}

} // namespace

BENCHMARK(BM_OrbitArmadillo)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_OrbitArmadilloPreview)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_OrbitArmadilloDepthOverlay)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

BENCHMARK(BM_DragonReset)->Apply([](auto* b) { celform::bench::interactiveBenchmark(b); });
BENCHMARK(BM_DragonResetToFirstFrame)->Apply([](auto* b) { celform::bench::interactiveBenchmark(b); });
BENCHMARK(BM_DragonMeshRebuild)->Apply([](auto* b) { celform::bench::interactiveBenchmark(b); });

int main(int argc, char** argv)
{
    // The viewport's GL context must go before the QApplication.
    return celform::bench::runViewportBenchmarks(argc, argv, [] {
        if (g_sceneBuilt)
            scene().viewport.reset();
        if (g_dragonBuilt)
            dragonScene().viewport.reset();
    });
}
