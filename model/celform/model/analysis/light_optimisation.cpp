// Optimise Light for Stereo on a project (light_optimisation.h).
#include "celform/model/analysis/light_optimisation.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/io_error.h"
#include "celform/model/data/blend_evaluator.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <atomic>

namespace celform::model {
namespace {

algo::LightPose poseOf(const Light& light)
{
    return {light.type == LightType::Point, light.vector};
}

Light lightOf(const algo::LightPose& pose)
{
    Light light;
    light.type = pose.point ? LightType::Point : LightType::Directional;
    light.vector = pose.vector;
    return light;
}

/// A generation no shape of the editor uses, so that the two analyses of one run share the
/// curvature even when the caller does not know its shape's generation.
std::uint64_t privateGeneration()
{
    static std::atomic<std::uint64_t> next{std::uint64_t(1) << 62};
    return next++;
}

} // namespace

LightOptimisationReport optimiseLight(const ProjectData& data, const Look& look, const algo::Positions& shape,
    std::uint64_t generation, int frame, const Camera& camera, int width, int height,
    const LightOptimisationRequest& request, DepthAnalyser& analyser, algo::Progress* progress,
    const std::vector<float>* shadingOffsets)
{
    QElapsedTimer timer;
    timer.start();
    LightOptimisationReport report;
    report.before = look.light;
    report.after = look.light;
    report.frame = frame;
    report.width = width;
    report.height = height;
    report.camera = camera;
    if (generation == 0)
        generation = privateGeneration();

    FrameAnalysis frameAnalysis;
    analyser.analyse(
        data, look, shape, generation, frame, camera, width, height, request.analysis, frameAnalysis, shadingOffsets);
    const algo::DepthAnalysis& before = frameAnalysis.analysis;
    report.segmentsBefore = before.stats;
    report.segmentsAfter = before.stats;
    report.mseBefore = report.mseAfter = before.meanSquaredError;
    report.featuresBefore = report.featuresAfter = before.featurePixels;
    // One bar over the whole run: the analysis before, the iterations, the analysis after.
    const std::int64_t steps = std::int64_t(std::max(0, request.optimiser.iterations)) + 2;
    algo::report(progress, 1, steps);
    const auto cancelled = [&] {
        report.run.cancelled = true;
        report.after = report.before;
        report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        return report;
    };
    if (algo::cancelRequested(progress)) {
        report.run.before = report.run.after = poseOf(look.light);
        return cancelled();
    }

    const algo::DepthAnalysisSettings& used = analyser.lastSettings();
    algo::ShadingSamples samples;
    algo::gatherShadingSamples(analyser.gbuffer(), frameAnalysis.passes.normal, before.segments, data.baseMesh->faces,
        used.shadingOffsets, used.toonThreshold, samples);

    algo::LightOptimisationSettings settings = request.optimiser;
    settings.window = request.analysis.window;
    const Eigen::AlignedBox3d box = algo::boundingBox(shape);
    settings.centre = box.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(box.center());
    settings.scale = box.isEmpty() ? 1.0 : std::max(0.5 * box.diagonal().norm(), 1e-9);

    QElapsedTimer iterations;
    iterations.start();
    algo::LightOptimisationWorkspace workspace;
    algo::ProgressPart iterationsPart(progress, 1, steps);
    report.run = algo::optimiseLight(samples, poseOf(look.light), settings, workspace, &iterationsPart);
    report.optimiseMilliseconds = double(iterations.nsecsElapsed()) / 1e6;
    if (report.run.cancelled) {
        report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        return report;
    }
    // The lights the search accepted, the best (by the ratios) last.
    std::vector<Eigen::Vector3d> accepted;
    for (const algo::LightIteration& it : report.run.iterations)
        if (it.accepted)
            accepted.push_back(it.light);
    if (accepted.empty()) { // nothing better than the artist's light: it stays as it is
        report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        algo::report(progress, steps, steps);
        return report;
    }

    // The analysis with the new light: the depth error the artist will see. The ratios are the
    // search's objective; the depth error (4.4) is reported beside them and may rise where the
    // start light's rim of shadow along the outline gave more features than the new shading line.
    report.after = lightOf({report.before.type == LightType::Point, accepted.back()});
    Look moved = look;
    moved.light = report.after;
    analyser.analyse(
        data, moved, shape, generation, frame, camera, width, height, request.analysis, frameAnalysis, shadingOffsets);
    report.segmentsAfter = frameAnalysis.analysis.stats;
    report.mseAfter = frameAnalysis.analysis.meanSquaredError;
    report.featuresAfter = frameAnalysis.analysis.featurePixels;
    if (algo::cancelRequested(progress)) // during the analysis after: the light stays as it was
        return cancelled();
    report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
    algo::report(progress, steps, steps);
    return report;
}

LightOptimisationReport optimiseLightForJob(const ProjectData& data, const QString& source, const RenderJob& job,
    const LightOptimisationRequest& request, algo::Progress* progress)
{
    // The project's look: optimize-light takes no look overrides, and the light found is its own.
    const AnalysisView view = resolveAnalysisView(data, source, job);
    DepthAnalyser analyser;
    return optimiseLight(data, data.look, view.shape, 0, job.firstFrame, view.camera, job.size.width(),
        job.size.height(), request, analyser, progress, &view.offsets);
}

QString lightMethodName(algo::LightMethod method)
{
    switch (method) {
    case algo::LightMethod::Gradient:
        return QStringLiteral("gradient");
    case algo::LightMethod::Annealing:
        return QStringLiteral("annealing");
    case algo::LightMethod::Random:
        return QStringLiteral("random");
    }
    return {};
}

bool lightMethodFromName(const QString& name, algo::LightMethod& method)
{
    for (const algo::LightMethod m :
        {algo::LightMethod::Gradient, algo::LightMethod::Annealing, algo::LightMethod::Random})
        if (name == lightMethodName(m)) {
            method = m;
            return true;
        }
    return false;
}

QString segmentWeightName(algo::SegmentWeight weight)
{
    return weight == algo::SegmentWeight::Area ? QStringLiteral("area") : QStringLiteral("constant");
}

bool segmentWeightFromName(const QString& name, algo::SegmentWeight& weight)
{
    for (const algo::SegmentWeight w : {algo::SegmentWeight::Constant, algo::SegmentWeight::Area})
        if (name == segmentWeightName(w)) {
            weight = w;
            return true;
        }
    return false;
}

} // namespace celform::model
