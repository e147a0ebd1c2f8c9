// Optimise Light Along Shot (light_track_optimisation.h).
#include "celform/model/analysis/light_track_optimisation.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/analysis/depth_analysis.h"

#include <QElapsedTimer>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace celform::model {
namespace {

/// One frame's share of the whole run's bar: the frame's own steps scaled into kScale steps.
class FrameProgress : public algo::Progress {
public:
    static constexpr std::int64_t kScale = 1000;
    FrameProgress(algo::Progress* whole, std::int64_t index, std::int64_t frames)
        : m_whole(whole)
        , m_index(index)
        , m_frames(frames)
    { }
    void progress(std::int64_t done, std::int64_t total, const std::string& label) override
    {
        const std::int64_t part = total > 0 ? std::clamp(done * kScale / total, std::int64_t(0), kScale) : 0;
        algo::report(m_whole, m_index * kScale + part, m_frames * kScale, label);
    }
    [[nodiscard]] bool isCancelRequested() const override { return algo::cancelRequested(m_whole); }

private:
    algo::Progress* m_whole;
    std::int64_t m_index;
    std::int64_t m_frames;
};

/// Issue 26: the track's depth error is no higher at any sampled frame than with the project's
/// light there. The forward pass keeps each key within the turn limit of the one before, which can
/// hold a key where it is worse than the project's light. Such a key goes back to the project's
/// light, and its neighbours turn towards it as far as the limit needs (the forward pair first,
/// then backwards from it), each kept only where it is no worse than the project's light at its
/// frame, else sent back too. A key sent back stays there, so the sweeps end; with a single light
/// (no earlier track) keys sent back are one light and never turn from each other.
void holdTheStartingLightsBound(const ProjectData& data, const QString& source, const RenderJob& job,
    const LightTrackRequest& request, const std::vector<int>& frames, const std::vector<Eigen::Vector3d>& centres,
    LightTrackReport& report)
{
    const std::size_t n = report.frames.size();
    if (n == 0 || centres.size() != n)
        return;
    DepthAnalyser analyser;
    FrameAnalysis scratch;
    RenderJob one = job;
    static std::atomic<std::uint64_t> next{std::uint64_t(6) << 60};
    auto mseWith = [&](std::size_t k, const Light& light) {
        one.firstFrame = one.lastFrame = frames[k];
        const AnalysisView view = resolveAnalysisView(data, source, one);
        Look lit = data.look;
        lit.light = light;
        lit.lightTrack = {};
        analyser.analyse(data, lit, view.shape, next++, frames[k], view.camera, job.size.width(), job.size.height(),
            request.light.analysis, scratch, &view.offsets);
        return scratch.analysis.meanSquaredError;
    };
    std::vector<char> back(n, 0); // keys sent back to the project's light
    auto sendBack = [&](std::size_t k) {
        LightTrackFrame& f = report.frames[k];
        f.light = f.original;
        f.mse = f.mseOriginal;
        back[k] = 1;
    };
    // Turns key k towards key `towards` until within the limit; false when nothing had to move.
    auto pull = [&](std::size_t k, std::size_t towards) {
        if (back[k])
            return false;
        LightTrackFrame& f = report.frames[k];
        const Light& other = report.frames[towards].light;
        const double allowed = request.maxTurnDegrees * double(std::abs(frames[k] - frames[towards]));
        if (lightTurnDegrees(other, f.light, centres[k]) <= allowed + 1e-9)
            return false;
        // From the other key towards this one, as far as allowed.
        const Light turned = limitLightTurn(other, f.light, centres[k], allowed);
        const double mse = mseWith(k, turned);
        f.limited = true;
        if (mse <= f.mseOriginal) {
            f.light = turned;
            f.mse = mse;
        } else {
            sendBack(k);
        }
        return true;
    };
    for (std::size_t sweep = 0; sweep <= n; ++sweep) {
        bool changed = false;
        for (std::size_t k = 0; k < n; ++k)
            if (!back[k] && report.frames[k].mse > report.frames[k].mseOriginal) {
                sendBack(k);
                changed = true;
            }
        for (std::size_t k = 1; k < n; ++k)
            changed = pull(k, k - 1) || changed;
        for (std::size_t k = n - 1; k-- > 0;)
            changed = pull(k, k + 1) || changed;
        if (!changed)
            break;
    }
    for (std::size_t k = 0; k < n; ++k)
        report.frames[k].turnDegrees
            = k == 0 ? 0.0 : lightTurnDegrees(report.frames[k - 1].light, report.frames[k].light, centres[k]);
}

} // namespace

double LightTrackReport::meanMseOriginal() const
{
    double sum = 0.0;
    for (const LightTrackFrame& f : frames)
        sum += f.mseOriginal;
    return frames.empty() ? 0.0 : sum / double(frames.size());
}

double LightTrackReport::meanMse() const
{
    double sum = 0.0;
    for (const LightTrackFrame& f : frames)
        sum += f.mse;
    return frames.empty() ? 0.0 : sum / double(frames.size());
}

double LightTrackReport::largestTurnDegrees() const
{
    double largest = 0.0;
    for (const LightTrackFrame& f : frames)
        largest = std::max(largest, f.turnDegrees);
    return largest;
}

LightTrackReport optimiseLightTrack(const ProjectData& data, const QString& source, const RenderJob& job,
    const LightTrackRequest& request, algo::Progress* progress)
{
    QElapsedTimer timer;
    timer.start();
    LightTrackReport report;
    report.before = report.after = data.look.lightTrack;
    report.lightBefore = data.look.light;
    report.width = job.size.width();
    report.height = job.size.height();
    const int step = std::max(1, job.step);
    std::vector<int> frames;
    for (int f = job.firstFrame; f <= job.lastFrame; f += step)
        frames.push_back(f);

    DepthAnalyser analyser;
    FrameAnalysis scratch;
    RenderJob one = job;
    // A generation per distinct shape, so that a still shape keeps its curvature across frames.
    static std::atomic<std::uint64_t> next{std::uint64_t(5) << 60};
    std::uint64_t generation = 0;
    algo::Positions lastShape;
    LightTrack found;
    std::vector<Eigen::Vector3d> centres; // per sampled frame: the shape's centre (point lights turn about it)
    for (std::size_t k = 0; k < frames.size(); ++k) {
        QElapsedTimer frameTimer;
        frameTimer.start();
        const int frame = frames[k];
        one.firstFrame = one.lastFrame = frame;
        const AnalysisView view = resolveAnalysisView(data, source, one);
        if (generation == 0 || view.shape.rows() != lastShape.rows() || view.shape != lastShape) {
            generation = next++;
            lastShape = view.shape;
        }
        const Eigen::AlignedBox3d box = algo::boundingBox(view.shape);
        const Eigen::Vector3d centre = box.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : box.center();
        centres.push_back(centre);
        const int width = job.size.width(), height = job.size.height();
        auto mseWith = [&](const Light& light) {
            Look lit = data.look;
            lit.light = light;
            lit.lightTrack = {};
            analyser.analyse(data, lit, view.shape, generation, frame, view.camera, width, height,
                request.light.analysis, scratch, &view.offsets);
            return scratch.analysis.meanSquaredError;
        };

        LightTrackFrame out;
        out.frame = frame;
        out.original = data.look.lightAt(double(frame));
        // Thesis 5.0.3 lets the artist choose the start; each later frame starts from the previous
        // frame's answer (issue 26: "each key starts from the previous one's result").
        Look start = data.look;
        start.lightTrack = {};
        start.light = k == 0 ? out.original : found.keys.back().light;
        LightOptimisationRequest frameRequest = request.light;
        if (k > 0)
            frameRequest.start = LightStart::Current;
        FrameProgress part(progress, std::int64_t(k), std::int64_t(frames.size()));
        const LightOptimisationReport run = optimiseLight(data, start, view.shape, generation, frame, view.camera,
            width, height, frameRequest, analyser, &part, &view.offsets);
        if (run.cancelled() || algo::cancelRequested(progress)) {
            report.cancelled = true;
            report.after = report.before;
            report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
            return report;
        }
        out.start = run.start;
        out.mseStart = run.mseBefore;
        out.light = run.after;
        out.mse = run.mseAfter;
        out.mseOriginal = out.original == out.start ? out.mseStart : mseWith(out.original);
        if (k > 0) {
            // The temporal term: no more than maxTurn per frame from the previous key. The turned
            // back light is kept only when it is no worse than where the frame started (which is
            // the previous key itself, a turn of 0).
            const Light& previous = found.keys.back().light;
            const double allowed = request.maxTurnDegrees * double(frame - frames[k - 1]);
            const Light limited = limitLightTurn(previous, out.light, centre, allowed);
            if (!(limited == out.light)) {
                out.limited = true;
                const double mse = mseWith(limited);
                out.light = mse <= out.mseStart ? limited : out.start;
                out.mse = mse <= out.mseStart ? mse : out.mseStart;
            }
            // Still worse than the project's light here: turn towards it, as far as the limit lets.
            if (out.mse > out.mseOriginal) {
                const Light towards = limitLightTurn(previous, out.original, centre, allowed);
                const double mse = towards == out.original ? out.mseOriginal : mseWith(towards);
                if (mse < out.mse) {
                    out.light = towards;
                    out.mse = mse;
                }
            }
            out.turnDegrees = lightTurnDegrees(previous, out.light, centre);
        } else if (out.mse > out.mseOriginal) { // a start at the camera that found nothing better
            out.light = out.original;
            out.mse = out.mseOriginal;
        }
        found.setKey(frame, out.light);
        out.milliseconds = double(frameTimer.nsecsElapsed()) / 1e6;
        report.frames.push_back(out);
        algo::report(
            progress, std::int64_t(k + 1) * FrameProgress::kScale, std::int64_t(frames.size()) * FrameProgress::kScale);
    }
    holdTheStartingLightsBound(data, source, job, request, frames, centres, report);
    for (const LightTrackFrame& f : report.frames)
        report.after.setKey(f.frame, f.light);
    report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
    return report;
}

} // namespace celform::model
