// Playback speed (issue 13): the bundled elephant sample on a 48-frame turntable, the viewport
// looking through the shot camera at each frame with the look at full quality (toon shading,
// lines, highlights) and the view-dependent preview on, as the editor plays it. Needs an X server
// (run under xvfb-run; llvmpipe there, so the figure is a software-GL floor). The aim is 24 fps.
#include "celform/model/document.h"
#include "celform/model/frame_evaluation.h"
#include "celform/views/viewport.h"

#include "bench_gui.h"

#include <benchmark/benchmark.h>

#include <QCoreApplication>

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
        s.document.makeTurntable(model::Turntable{}, 830.0 / 710.0);
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
    state.counters["paint_ms"] = s.viewport->lastFrameMilliseconds();
    state.counters["lines_ms"] = s.viewport->lastLineMilliseconds();
}
BENCHMARK(turntableFrames)->Apply([](benchmark::internal::Benchmark* b) { bench::interactiveBenchmark(b, 2.0); });

} // namespace

int main(int argc, char** argv)
{
    return bench::runViewportBenchmarks(argc, argv, [] {
        if (g_built)
            shot().viewport.reset();
    });
}
