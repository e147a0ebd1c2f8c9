// The command line's algo::Progress: a long sub-command says how far it is on standard error, as
// `celform export` does, and is never cancelled (the command line stops with Ctrl+C).
#pragma once

#include "celform/algorithms/progress.h"

#include <QElapsedTimer>
#include <QString>

#include <functional>

namespace celform::app {

/// Prints line(done, total) on standard error once the job has run kQuietMs, then at most once
/// every kQuietMs, and the last step once anything was printed, so a long job says it finished
/// and a short one prints nothing.
class StderrProgress : public algo::Progress {
public:
    static constexpr qint64 kQuietMs = 1000;
    using Line = std::function<QString(std::int64_t done, std::int64_t total)>;

    explicit StderrProgress(Line line);
    void progress(std::int64_t done, std::int64_t total, const std::string& label) override;
    [[nodiscard]] bool isCancelRequested() const override { return false; }

private:
    Line m_line;
    QElapsedTimer m_clock;
    qint64 m_lastPrinted = 0;
};

} // namespace celform::app
