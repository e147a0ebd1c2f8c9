// The one progress interface of long jobs: every slow algorithm, model job and editor job reports
// through it and asks it whether to stop (docs/architecture.md, "Long jobs"). The editor's
// JobRunner implements it over a progress dialog, the command line over standard error, and the
// live analysis over its coalescing runner.
#pragma once

#include <cstdint>
#include <string>

namespace celform::algo {

class Progress {
public:
    Progress() = default;
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    virtual ~Progress() = default;

    /// done of total steps of the job so far (total 0: unknown), with what is being done now as a
    /// short phrase (UTF-8, translated by the caller; empty keeps the last one). Called from the
    /// thread doing the work, never from two threads at once.
    virtual void progress(std::int64_t done, std::int64_t total, const std::string& label) = 0;
    /// True once the user asked to stop: the job returns at its next check, leaving what it was
    /// given unchanged. May be called from any thread.
    [[nodiscard]] virtual bool isCancelRequested() const = 0;
};

/// Reports to progress when there is one; a null progress is a job nobody watches.
inline void report(Progress* progress, std::int64_t done, std::int64_t total, const std::string& label = {})
{
    if (progress)
        progress->progress(done, total, label);
}

/// Whether the job should stop; never for a null progress.
[[nodiscard]] inline bool cancelRequested(const Progress* progress)
{
    return progress && progress->isCancelRequested();
}

/// A part of a larger job: steps done..total of the part are steps offset + done of the whole's
/// total, so a job made of several reporting parts shows one bar from 0 to the end. Cancel is
/// the whole's.
class ProgressPart : public Progress {
public:
    ProgressPart(Progress* whole, std::int64_t offset, std::int64_t total)
        : m_whole(whole)
        , m_offset(offset)
        , m_total(total)
    { }
    void progress(std::int64_t done, std::int64_t, const std::string& label) override
    {
        report(m_whole, m_offset + done, m_total, label);
    }
    [[nodiscard]] bool isCancelRequested() const override { return cancelRequested(m_whole); }

private:
    Progress* m_whole;
    std::int64_t m_offset;
    std::int64_t m_total;
};

} // namespace celform::algo
