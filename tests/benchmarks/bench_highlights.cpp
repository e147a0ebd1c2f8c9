// Stylized highlights (Anjyo & Hiramitsu 2003) on the armadillo (52k triangles) at 1280x720, toon
// shading with lines (the default look):
// - slider to frame: a highlight layer's epsilon changed through HighlightEdits::setHighlightKey, as the
//   Highlights dock does, until the viewport has drawn the new frame; the baseline is the same
//   viewport redrawn with nothing changed. Needs an X server: run under xvfb-run (Mesa llvmpipe
//   there, so the figures are a software-GL floor).
// - offline render: model::renderShape (what `celform render` does per frame) with three
//   highlight layers, against the same render with none.
// "Three layers": a plain one (the one the slider edits), one with rotation, directional scaling,
// split and squaring, and one with a hidden fourth track subtracted from it.
//
// CELFORM_BENCH_SNAPSHOTS=DIR saves the pictures measured (viewport grabs, offline beauty) there.
#include "celform/model/document/document.h"
#include "celform/model/data/project_data.h"
#include "celform/model/render/render_output.h"
#include "celform/views/viewport/viewport.h"

#include "bench_data.h"
#include "bench_gui.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <memory>

namespace {

using namespace celform;
using algo::HighlightOperation;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
/// The two values the slider alternates between (every iteration is a real change).
constexpr float kEpsilonA = 0.05f;
constexpr float kEpsilonB = 0.06f;

const algo::TriMesh* armadillo()
{
    return bench::sharedMesh("meshes/cgal_armadillo.off");
}

model::HighlightTrack track(
    const QString& name, const algo::Color& color, float epsilon, std::vector<HighlightOperation> operations = {})
{
    model::HighlightTrack t;
    t.name = name;
    algo::HighlightLayer layer;
    layer.color = color;
    layer.shape.epsilon = epsilon;
    layer.shape.operations = std::move(operations);
    t.keys.push_back({0.0, layer});
    return t;
}

/// The highlight tracks of a run: the plain layer "key" (the slider's), and with three layers
/// also "shaped" (rotate, scale, split, square) and "ring" (minus the hidden track "hole").
std::vector<model::HighlightTrack> highlightTracks(int layers)
{
    std::vector<model::HighlightTrack> tracks;
    if (layers <= 0)
        return tracks;
    tracks.push_back(track(QStringLiteral("key"), algo::Color(1.0f, 1.0f, 1.0f), kEpsilonA));
    if (layers == 1)
        return tracks;
    tracks.push_back(track(QStringLiteral("shaped"), algo::Color(1.0f, 0.95f, 0.6f), 0.05f,
        {HighlightOperation::rotation(30.0f), HighlightOperation::directionalScaling(0.5f),
            HighlightOperation::split(0.3f, 0.2f), HighlightOperation::squaring(0.2f, 2.0f)}));
    model::HighlightTrack hole = track(QStringLiteral("hole"), algo::Color(1.0f, 1.0f, 1.0f), 0.02f);
    hole.visible = false;
    tracks.push_back(hole);
    model::HighlightTrack ring = track(QStringLiteral("ring"), algo::Color(0.7f, 0.9f, 1.0f), 0.06f);
    ring.combineWith.push_back({algo::HighlightBoolean::Subtraction, hole.name});
    tracks.push_back(ring);
    return tracks;
}

/// A new project on the armadillo: the default look (toon, lines), no highlights.
model::ProjectData armadilloProject()
{
    return model::newProject(std::make_shared<algo::TriMesh>(*armadillo()), QStringLiteral("cgal_armadillo.off"));
}

QString snapshotPath(const QString& name)
{
    const QString dir = qEnvironmentVariable("CELFORM_BENCH_SNAPSHOTS");
    if (dir.isEmpty())
        return {};
    QDir().mkpath(dir);
    return QDir(dir).filePath(name);
}

// --- slider to frame (viewport) ---------------------------------------------------------------

struct Scene {
    model::Document document;
    std::unique_ptr<views::Viewport> viewport;
    bool ok = false;
};

/// Draws frames until the viewport has drawn one more than it had; false after 10 s.
bool awaitFrame(views::Viewport& viewport, int before)
{
    QElapsedTimer timer;
    timer.start();
    while (viewport.renderCount() == before) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        if (timer.elapsed() > 10000)
            return false;
    }
    return true;
}

/// The scene, built on first use; main() destroys it while the QApplication still lives.
std::unique_ptr<Scene>& sceneSlot()
{
    static std::unique_ptr<Scene> slot;
    return slot;
}

/// The armadillo in a 1280x720 viewport, framed from the front (the viewport's Home view),
/// default look.
Scene& scene()
{
    std::unique_ptr<Scene>& slot = sceneSlot();
    if (slot)
        return *slot;
    slot = std::make_unique<Scene>();
    Scene& scene = *slot;
    if (!armadillo() || qEnvironmentVariableIsEmpty("DISPLAY"))
        return scene;
    scene.document.reset(armadilloProject());
    scene.viewport = std::make_unique<views::Viewport>(&scene.document);
    scene.viewport->resize(kWidth, kHeight);
    scene.viewport->show();
    for (int i = 0; i < 20 && scene.viewport->renderCount() == 0; ++i)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    scene.ok = scene.viewport->renderCount() > 0;
    return scene;
}

/// Installs the tracks of a run (undo history dropped) and draws two frames with them, so that
/// shaders and buffers for this configuration are in place before the timing.
bool prepare(Scene& s, int layers)
{
    while (!s.document.data().look.highlights.empty())
        s.document.highlights().removeHighlightLayer(s.document.data().look.highlights.back().id);
    if (layers > 0)
        s.document.highlights().addHighlightLayers(highlightTracks(layers), QStringLiteral("Layers"));
    s.document.undoStack()->clear();
    for (int i = 0; i < 2; ++i) {
        const int before = s.viewport->renderCount();
        s.viewport->update();
        if (!awaitFrame(*s.viewport, before))
            return false;
    }
    return true;
}

void saveViewport(Scene& s, const QString& name)
{
    const QString path = snapshotPath(name);
    if (!path.isEmpty())
        s.viewport->renderedImage().save(path);
}

/// The Highlights dock's edit path: the layer at the frame, the change, HighlightEdits::setHighlightKey.
void dockEdit(model::Document& document, float epsilon)
{
    const model::HighlightTrack& track = document.data().look.highlights.front();
    algo::HighlightLayer layer = track.layerAt(0);
    layer.shape.epsilon = epsilon;
    document.highlights().setHighlightKey(track.id, 0, layer);
}

void sliderFrames(benchmark::State& state, bool change)
{
    const int layers = int(state.range(0));
    Scene& s = scene();
    if (!s.ok) {
        state.SkipWithError("needs ../shared/data and an X server (run under xvfb-run)");
        return;
    }
    if (!prepare(s, layers)) {
        state.SkipWithError("the viewport drew no frame");
        return;
    }
    const model::Camera camera = s.viewport->camera();
    double editMs = 0.0, paintMs = 0.0;
    bool high = true;
    for (auto _ : state) {
        const int before = s.viewport->renderCount();
        if (change) {
            // The slider moves: the look changes (the viewport recomputes its per-vertex look
            // attributes on lookChanged and asks for a frame), then the frame it asked for.
            QElapsedTimer edit;
            edit.start();
            dockEdit(s.document, high ? kEpsilonB : kEpsilonA);
            editMs += double(edit.nsecsElapsed()) / 1e6;
            high = !high;
        } else {
            s.viewport->update(); // the same frame again, nothing changed
        }
        if (!awaitFrame(*s.viewport, before)) {
            state.SkipWithError("the viewport drew no frame");
            return;
        }
        paintMs += s.viewport->lastFrameTimes().frame;
    }
    if (s.viewport->camera() != camera)
        state.SkipWithError("the camera moved");
    const double n = std::max(1.0, double(state.iterations()));
    state.counters["paint_ms"] = paintMs / n;
    if (change)
        state.counters["edit_ms"] = editMs / n;
    saveViewport(s, QStringLiteral("viewport_%1layers_%2.png").arg(layers).arg(change ? "slider" : "redraw"));
    s.document.undoStack()->clear();
}

void BM_HighlightSliderToFrame(benchmark::State& state)
{
    sliderFrames(state, true);
}
void BM_HighlightRedrawNoChange(benchmark::State& state)
{
    sliderFrames(state, false);
}

// --- offline render ---------------------------------------------------------------------------

/// Front view of the armadillo framed as the viewport's frameAll() frames it (30 degree vertical
/// field of view, bounding sphere in the narrower field with a 5% margin).
model::Camera offlineCamera(const algo::TriMesh& mesh)
{
    const Eigen::AlignedBox3d box = algo::boundingBox(mesh.vertices);
    model::Camera camera;
    camera.target = box.center();
    const double radius = 0.5 * box.diagonal().norm();
    const double halfY = camera.fovYDegrees * M_PI / 360.0;
    const double halfX = std::atan(std::tan(halfY) * double(kWidth) / double(kHeight));
    camera.eye = camera.target + Eigen::Vector3d::UnitZ() * (1.05 * radius / std::sin(std::min(halfX, halfY)));
    return camera;
}

void BM_HighlightOfflineRender(benchmark::State& state)
{
    const int layers = int(state.range(0));
    if (!armadillo()) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    model::ProjectData data = armadilloProject();
    data.look.highlights = highlightTracks(layers);
    const QString problem = model::highlightTracksProblem(data.look.highlights, {});
    if (!problem.isEmpty()) {
        const std::string message = problem.toStdString();
        state.SkipWithError(message.c_str());
        return;
    }
    const model::Camera camera = offlineCamera(*data.baseMesh);
    algo::RenderCache cache; // topology is built once, as in a sequence
    algo::RenderPasses passes;
    for (auto _ : state) {
        passes = model::renderShape(
            data, data.look, data.baseMesh->vertices, 0, camera, kWidth, kHeight, algo::StereoOutput::Off, cache);
        benchmark::DoNotOptimize(passes.beauty.pixels.data());
    }
    // Sanity: how many pixels the highlights cover (zero for the baseline).
    state.counters["highlight_px"]
        = double(std::count_if(passes.highlights.begin(), passes.highlights.end(), [](float c) { return c > 0.0f; }));
    const QString path = snapshotPath(QStringLiteral("offline_%1layers.png").arg(layers));
    if (!path.isEmpty())
        model::writeImage(passes.beauty, path);
}

} // namespace

// Arg: visible highlight layers (0 = none; 3 = three visible plus the hidden operand).
BENCHMARK(BM_HighlightRedrawNoChange)->Arg(0)->Arg(1)->Arg(3)->Apply([](auto* b) {
    celform::bench::interactiveBenchmark(b, 2.0);
});
BENCHMARK(BM_HighlightSliderToFrame)->Arg(1)->Arg(3)->Apply([](auto* b) {
    celform::bench::interactiveBenchmark(b, 2.0);
});
BENCHMARK(BM_HighlightOfflineRender)->Arg(0)->Arg(1)->Arg(3)->Apply([](auto* b) {
    celform::bench::interactiveBenchmark(b);
});

int main(int argc, char** argv)
{
    return celform::bench::runViewportBenchmarks(argc, argv, [] { sceneSlot().reset(); });
}
