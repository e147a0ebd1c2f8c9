// How fast `celform` starts as a command-line tool: `celform --version` and `celform info` on the
// bundled sample as whole processes (fork, exec, wait4), against /bin/true in the same run. Each
// repetition is one process: wall time from fork to reaped, and its peak resident set (ru_maxrss).
// Run: bench_cli (medians of 20 repetitions; targets: under 50 ms and 40 MB each);
// CELFORM_BENCH_EXECUTABLE=/path/to/celform bench_cli measures another build instead.
#include "bench_process.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using celform::bench::Finished;
using celform::bench::runProcess;

void process(benchmark::State& state, const std::vector<std::string>& args)
{
    runProcess(args); // warm the page cache and the loader's caches before the timed runs
    for (auto _ : state) {
        const Finished f = runProcess(args);
        if (!WIFEXITED(f.status) || WEXITSTATUS(f.status) != 0) {
            state.SkipWithError("the process failed");
            return;
        }
        state.SetIterationTime(f.seconds);
        state.counters["peak_rss_MB"] = f.peakRssMb;
    }
}

} // namespace

int main(int argc, char** argv)
{
    // CELFORM_BENCH_EXECUTABLE compares another build (an older celform) in the same run.
    const char* other = getenv("CELFORM_BENCH_EXECUTABLE");
    const std::string celform = other && *other ? other : CELFORM_EXECUTABLE;
    const std::string sample = CELFORM_SOURCE_DIR "/resources/samples/elephant-plain.celform";
    // Sub-commands need no display; without one nothing may reach for it.
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    const std::pair<const char*, std::vector<std::string>> programs[] = {
        {"process/bin_true", {"/bin/true"}},
        {"process/celform_version", {celform, "--version"}},
        {"process/celform_info_elephant", {celform, "info", sample}},
        {"process/celform_info_elephant_json", {celform, "info", sample, "--json"}},
    };
    for (const auto& [name, args] : programs)
        benchmark::RegisterBenchmark(name, process, args)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->Repetitions(20)
            ->ReportAggregatesOnly(true);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
