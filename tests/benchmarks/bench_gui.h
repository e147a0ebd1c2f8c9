// The main() of benchmark programs that host a Viewport: a QApplication when there is a display
// (viewport benchmarks skip themselves without one), and a clean-up hook that runs before the
// application goes (a viewport's GL context must not outlive it).
#pragma once

#include "celform/views/viewport/viewport.h"

#include <QApplication>
#include <QSurfaceFormat>

#include <benchmark/benchmark.h>

#include <functional>
#include <memory>

namespace celform::bench {

inline int runViewportBenchmarks(int argc, char** argv, const std::function<void()>& beforeAppGoes = {})
{
    QSurfaceFormat::setDefaultFormat(views::Viewport::defaultFormat());
    std::unique_ptr<QApplication> app;
    if (!qEnvironmentVariableIsEmpty("DISPLAY"))
        app = std::make_unique<QApplication>(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (beforeAppGoes)
        beforeAppGoes();
    return 0;
}

/// Milliseconds, real time, five repetitions reported as aggregates (minTime 0: the default).
inline void interactiveBenchmark(benchmark::internal::Benchmark* b, double minTime = 0.0)
{
    b->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(5)->ReportAggregatesOnly(true);
    if (minTime > 0.0)
        b->MinTime(minTime);
}

} // namespace celform::bench
