// Playback speed: the bundled elephant sample on a 48-frame turntable, the viewport
// looking through the shot camera at each frame with the look at full quality (toon shading,
// lines, highlights) and the view-dependent preview on, as the editor plays it. Needs an X server
// (run under xvfb-run; llvmpipe there, so the figure is a software-GL floor). The aim is 24 fps.
// - turntableFrames: the viewport alone, at the size of the editor's main view.
// - windowTurntableFrames: the whole editor window at its default size (1400x900) with the sample
//   open, stepping the playhead as playing does: the viewport, the Timeline, the Viewing Sphere and
//   the other docks repaint, and Qt composes the window. Its gap to turntableFrames is what the rest
//   of the window costs per frame.
#include "celform/model/document/document.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/views/overlays/depth_analysis_runner.h"
#include "celform/views/viewport/viewport.h"

#include "bench_gui.h"
#include "editor/main_window.h"

#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QElapsedTimer>

#include <memory>

namespace {

using namespace celform;

struct Shot {
    model::Document document;
    std::unique_ptr<views::Viewport> viewport;
    bool ok = false;
};

bool g_built = false;

Shot& shot()
{
    static Shot s;
    if (g_built)
        return s;
    g_built = true;
    if (qEnvironmentVariableIsEmpty("DISPLAY"))
        return s;
    s.document.open(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform"));
    s.viewport = std::make_unique<views::Viewport>(&s.document);
    // The main view's size in the editor's default 1400x900 window.
    s.viewport->resize(830, 710);
    s.viewport->show();
    if (s.document.data().look.cameraPath.empty())
        s.document.animation().makeTurntable(model::Turntable{}, 830.0 / 710.0);
    s.viewport->setPreview(true);
    for (int i = 0; i < 20 && s.viewport->renderCount() == 0; ++i)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    s.ok = s.viewport->renderCount() > 0;
    return s;
}

void turntableFrames(benchmark::State& state)
{
    Shot& s = shot();
    if (!s.ok) {
        state.SkipWithError("needs an X server (run under xvfb-run)");
        return;
    }
    const double aspect = double(s.viewport->width()) / s.viewport->height();
    int frame = 0;
    for (auto _ : state) {
        // What the editor does per played frame: the playhead moves, the view takes the shot
        // camera there, and the frame is drawn.
        frame = (frame + 1) % 48;
        s.document.setCurrentFrame(frame);
        s.viewport->setCamera(model::cameraAtFrame(s.document.data(), s.document.data().look, frame, aspect));
        const int drawn = s.viewport->renderCount();
        while (s.viewport->renderCount() == drawn)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["paint_ms"] = s.viewport->lastFrameTimes().frame;
    state.counters["lines_ms"] = s.viewport->lastFrameTimes().lines;
}
BENCHMARK(turntableFrames)->Apply([](benchmark::internal::Benchmark* b) { bench::interactiveBenchmark(b, 2.0); });

std::unique_ptr<app::MainWindow> g_window;

/// The editor window on the showcase sample, which opens looking through the shot camera.
app::MainWindow* window()
{
    if (g_window || qEnvironmentVariableIsEmpty("DISPLAY"))
        return g_window.get();
    g_window = std::make_unique<app::MainWindow>(app::MainWindow::Mode::Batch);
    g_window->resize(1400, 900);
    g_window->show();
    if (!g_window->openFile(QStringLiteral(CELFORM_SOURCE_DIR "/resources/samples/elephant.celform"))) {
        g_window.reset();
        return nullptr;
    }
    QElapsedTimer clock;
    clock.start();
    while (g_window->viewport()->renderCount() == 0 && clock.elapsed() < 20000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    return g_window.get();
}

void windowTurntableFrames(benchmark::State& state)
{
    app::MainWindow* w = window();
    if (!w || w->viewport()->renderCount() == 0) {
        state.SkipWithError("needs an X server (run under xvfb-run)");
        return;
    }
    model::Document* doc = w->document();
    views::Viewport* viewport = w->viewport();
    // What playing changes besides the playhead: the Depth tab's background analysis waits.
    for (views::DepthAnalysisRunner* runner : w->findChildren<views::DepthAnalysisRunner*>())
        runner->setHeld(true);
    int frame = doc->currentFrame();
    for (auto _ : state) {
        // As Playback::tick: move the playhead; every listener updates and the window repaints.
        frame = (frame + 1) % 48;
        doc->setCurrentFrame(frame);
        const int drawn = viewport->renderCount();
        while (viewport->renderCount() == drawn)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        // The other widgets' paints of the same update pass.
        QCoreApplication::processEvents();
    }
    for (views::DepthAnalysisRunner* runner : w->findChildren<views::DepthAnalysisRunner*>())
        runner->setHeld(false);
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["paint_ms"] = viewport->lastFrameTimes().frame;
}
BENCHMARK(windowTurntableFrames)->Apply([](benchmark::internal::Benchmark* b) { bench::interactiveBenchmark(b, 2.0); });

} // namespace

int main(int argc, char** argv)
{
    return bench::runViewportBenchmarks(argc, argv, [] {
        g_window.reset();
        if (g_built)
            shot().viewport.reset();
    });
}
