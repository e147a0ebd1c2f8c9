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
    for (const LightKey& key : found.keys)
        report.after.setKey(key.frame, key.light);
    report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
    return report;
}

} // namespace celform::model
