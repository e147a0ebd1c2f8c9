// A shot at the speed of its frames (issue 29): the dragon (871k triangles) at 1920x1080, toon with
// lines, 10 frames along a turntable. In one run:
// - frame/in_process: renderFrame() on the project's shape, the figure the others are read against
//   (bench_render's frame);
// - sequence/in_process_png: renderFrames() over the 10 frames, files written, per frame; its
//   counter minflt_per_frame is the minor page faults of a frame after the first (getrusage:
//   faults of 10 frames less those of 1, over 9);
// - encode/*: one frame's file from its passes, in process (the beauty to PNG, every pass to
//   EXR), with the render thread's part and the writer thread's part as counters;
// - process/*: `celform render --frames 0-9` as a whole process (fork, exec, wait4), per frame,
//   with --threads 1 and 2, PNG and EXR (every pass, the default for .exr, and the beauty alone), and a
//   single frame (start-up, project load and the line topology included).
// Goals: process/png_threads1 <= 1.25x frame/in_process, process/png_threads2 <= 0.7x, EXR <= 1.2x
// PNG, process/single_frame <= frame/in_process + 300 ms, minflt_per_frame <= 2000 (PNG).
// Run: bench_sequence (medians of 5: the machine is shared, and a median of 3 moved by 10 %);
// CELFORM_BENCH_EXECUTABLE=/path/to/celform measures another build's processes. Skips without ../shared/data.
#include "celform/algorithms/render.h"
#include "celform/model/data/project_data.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"

#include "bench_data.h"
#include "bench_process.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>
#include <QString>
#include <QTemporaryDir>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace celform;

constexpr int kFrames = 10;

/// Runs a program to its end; seconds, or a negative number on failure.
double runProcess(const std::vector<std::string>& args)
{
    const bench::Finished f = bench::runProcess(args);
    return WIFEXITED(f.status) && WEXITSTATUS(f.status) == 0 ? f.seconds : -1.0;
}

/// The celform measured: CELFORM_BENCH_EXECUTABLE (an older build, for a before and after in one
/// run), else this build's.
std::string executable()
{
    const char* other = getenv("CELFORM_BENCH_EXECUTABLE");
    return other && *other ? other : CELFORM_EXECUTABLE;
}

/// The dragon's project with a 10-frame turntable, made once with the command line.
struct Shot {
    QTemporaryDir dir;
    std::string celform = executable();
    std::string project;
    bool ok = false;

    Shot()
    {
        const QString mesh
            = QDir(QStringLiteral(CELFORM_SHARED_DATA_DIR)).filePath(QStringLiteral("meshes/stanford_dragon.ply"));
        if (!dir.isValid() || !QFileInfo::exists(mesh))
            return;
        project = dir.filePath(QStringLiteral("dragon.celform")).toStdString();
        ok = runProcess({celform, "new", mesh.toStdString(), "--out", project}) >= 0
            && runProcess({celform, "camera", project, "--turntable", std::to_string(kFrames)}) >= 0
            && runProcess({celform, "set", project, "--style", "toon"}) >= 0;
    }
    [[nodiscard]] std::string out(const char* pattern) const
    {
        return dir.filePath(QString::fromLatin1(pattern)).toStdString();
    }
};

Shot& shot()
{
    static Shot s;
    return s;
}

model::RenderJob job(int frames, const char* pattern)
{
    model::RenderJob j;
    j.firstFrame = 0;
    j.lastFrame = frames - 1;
    j.size = QSize(1920, 1080);
    j.lines = true;
    j.output = QString::fromStdString(shot().out(pattern));
    return j;
}

long minorFaults()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

/// Frame 0 of the shot as renderFrame takes it: the project, its camera at 1920x1080 and its look.
struct FirstFrame {
    model::ProjectData data = model::loadProject(QString::fromStdString(shot().project));
    model::RenderJob j = job(1, "unused.png");
    model::ResolvedRenderJob resolved = model::resolveRenderJob(data, QStringLiteral("dragon"), j);
    algo::RasterCamera camera = model::rasterCamera(model::renderJobCamera(data, resolved.look, j, 0), 1920, 1080);
    algo::RenderLook look = model::renderLookFor(data, resolved.look);
    algo::RenderCache cache;

    void render(algo::RenderPasses& out)
    {
        algo::renderFrame(data.baseMesh->vertices, *data.baseMesh, camera, look, cache, out);
    }
};

void BM_FrameInProcess(benchmark::State& state)
{
    if (!shot().ok) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    FirstFrame frame;
    algo::RenderPasses out;
    for (auto _ : state) {
        frame.render(out);
        benchmark::DoNotOptimize(out.beauty.pixels.data());
    }
}

void BM_SequenceInProcess(benchmark::State& state)
{
    if (!shot().ok) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    const model::ProjectData data = model::loadProject(QString::fromStdString(shot().project));
    for (auto _ : state) {
        const long before = minorFaults();
        model::renderFrames(data, QStringLiteral("dragon"), job(1, "one_####.png"));
        const long afterOne = minorFaults();
        const auto start = std::chrono::steady_clock::now();
        model::renderFrames(data, QStringLiteral("dragon"), job(kFrames, "seq_####.png"));
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const long afterAll = minorFaults();
        state.SetIterationTime(seconds / kFrames);
        state.counters["minflt_per_frame"] = double((afterAll - afterOne) - (afterOne - before)) / (kFrames - 1);
    }
}

/// One frame's file made from its passes and written, as a sequence's writer does it after the
/// render thread has encoded it (encode/*: what the writer thread costs a frame beside the render).
/// allPasses: every pass to EXR; else the beauty to PNG.
void BM_WriteFrame(benchmark::State& state, bool allPasses)
{
    if (!shot().ok) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    FirstFrame frame;
    algo::RenderPasses passes;
    frame.render(passes);
    const QString path = QString::fromStdString(shot().out(allPasses ? "w.exr" : "w.png"));
    model::EncodedFrame encoded;
    static const std::vector<std::string> rgba = {"R", "G", "B", "A"};
    double encodeSeconds = 0, writeSeconds = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        if (!allPasses)
            model::encodeChannels(
                path, 1920, 1080, rgba, passes.beauty.pixels.data(), passes.beauty.pixels.size(), true, encoded);
        const auto encodedAt = std::chrono::steady_clock::now();
        if (allPasses)
            model::writePassesExr(passes, path);
        else
            model::writeEncoded(encoded, path);
        const auto end = std::chrono::steady_clock::now();
        encodeSeconds += std::chrono::duration<double>(encodedAt - start).count();
        writeSeconds += std::chrono::duration<double>(end - encodedAt).count();
    }
    // The render thread's part (gathering or quantising) and the writer's (codec and file), in ms.
    state.counters["render_thread_ms"] = 1e3 * encodeSeconds / double(state.iterations());
    state.counters["writer_ms"] = 1e3 * writeSeconds / double(state.iterations());
}

void process(benchmark::State& state, std::vector<std::string> extra, int frames)
{
    if (!shot().ok) {
        state.SkipWithError("shared test data not found (../shared/data)");
        return;
    }
    std::vector<std::string> args = {shot().celform, "render", shot().project, "--size", "1920x1080", "--lines", "on"};
    args.insert(args.end(), extra.begin(), extra.end());
    // One untimed run before a command's first repetition: the first process after the
    // in-process benchmarks (which free a few hundred MB) was up to 30 % slower, its fresh pages
    // costing the virtual machine more, whatever the command.
    static std::set<std::vector<std::string>> warmed;
    if (warmed.insert(args).second && runProcess(args) < 0) {
        state.SkipWithError("celform render failed");
        return;
    }
    for (auto _ : state) {
        const double seconds = runProcess(args);
        if (seconds < 0) {
            state.SkipWithError("celform render failed");
            return;
        }
        state.SetIterationTime(seconds / frames);
    }
}

} // namespace

int main(int argc, char** argv)
{
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    const auto common = [](benchmark::internal::Benchmark* b) {
        b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(5)->ReportAggregatesOnly(true);
    };
    benchmark::RegisterBenchmark("frame/in_process", BM_FrameInProcess)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond)
        ->Repetitions(5)
        ->ReportAggregatesOnly(true);
    common(benchmark::RegisterBenchmark("sequence/in_process_png", BM_SequenceInProcess));
    for (const bool allPasses : {false, true})
        benchmark::RegisterBenchmark(
            allPasses ? "encode/exr_every_pass" : "encode/png_beauty", BM_WriteFrame, allPasses)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond)
            ->Repetitions(5)
            ->ReportAggregatesOnly(true);
    const std::string frames = "0-" + std::to_string(kFrames - 1);
    const std::string png = shot().out("p_####.png");
    const std::string exr = shot().out("e_####.exr");
    common(benchmark::RegisterBenchmark("process/png_threads1", process,
        std::vector<std::string>{"--frames", frames, "--threads", "1", "--out", png}, kFrames));
    common(benchmark::RegisterBenchmark("process/png_threads2", process,
        std::vector<std::string>{"--frames", frames, "--threads", "2", "--out", png}, kFrames));
    common(benchmark::RegisterBenchmark("process/exr_threads1", process,
        std::vector<std::string>{"--frames", frames, "--threads", "1", "--out", exr}, kFrames));
    // The default .exr holds every pass (12 float channels); the beauty alone is what the PNG holds.
    common(benchmark::RegisterBenchmark("process/exr_beauty_threads1", process,
        std::vector<std::string>{
            "--frames", frames, "--threads", "1", "--pass", "beauty", "--out", shot().out("b_####.exr")},
        kFrames));
    common(benchmark::RegisterBenchmark("process/single_frame", process,
        std::vector<std::string>{"--frame", "0", "--out", shot().out("single.png")}, 1));
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
