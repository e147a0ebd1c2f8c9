// Interactive speed of the viewport: orbiting the armadillo (52k triangles) with and without the
// view-dependent preview (paper 1, section 3.2), frames per second as a rate counter. Needs an X
// server: run under xvfb-run (Mesa llvmpipe there, so the figures are a software-GL floor).
#include "celform/model/document.h"
#include "celform/model/mesh_io.h"
#include "celform/views/viewport.h"

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
            scene.document.createKey(QStringLiteral("k%1").arg(k), camera, {}, offsets);
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

void orbitFrames(benchmark::State& state, bool preview)
{
    Scene& s = scene();
    if (!s.ok) {
        state.SkipWithError("needs ../shared/data and an X server (run under xvfb-run)");
        return;
    }
    s.viewport->setPreview(preview);
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
}

void BM_OrbitArmadillo(benchmark::State& state)
{
    orbitFrames(state, false);
}
void BM_OrbitArmadilloPreview(benchmark::State& state)
{
    orbitFrames(state, true);
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

int main(int argc, char** argv)
{
    // The viewport's GL context must go before the QApplication.
    return celform::bench::runViewportBenchmarks(argc, argv, [] {
        if (g_sceneBuilt)
            scene().viewport.reset();
    });
}
