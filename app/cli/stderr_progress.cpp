// Progress on standard error (stderr_progress.h).
#include "cli/stderr_progress.h"

#include "cli/command.h"

namespace celform::app {

StderrProgress::StderrProgress(Line line)
    : m_line(std::move(line))
{
    m_clock.start();
}

void StderrProgress::progress(std::int64_t done, std::int64_t total, const std::string&)
{
    const qint64 now = m_clock.elapsed();
    const bool due = now >= kQuietMs && now - m_lastPrinted >= kQuietMs;
    const bool last = done == total && m_lastPrinted > 0; // a long job says it finished
    if (!due && !last)
        return;
    m_lastPrinted = now;
    printErr(m_line(done, total));
}

} // namespace celform::app
