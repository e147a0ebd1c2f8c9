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

/// The thesis's start (5.0.3): a light at the camera, towards the eye or at it.
Light cameraLight(const Light& current, const Camera& camera)
{
    Light light = current;
    if (light.type == LightType::Point)
        light.vector = camera.eye;
    else
        light.vector = (camera.eye - camera.target).normalized();
    return light;
}

LightOptimisationReport optimiseLight(const ProjectData& data, const Look& given, const algo::Positions& shape,
    std::uint64_t generation, int frame, const Camera& camera, int width, int height,
    const LightOptimisationRequest& request, DepthAnalyser& analyser, algo::Progress* progress,
    const std::vector<float>* shadingOffsets)
{
    QElapsedTimer timer;
    timer.start();
    LightOptimisationReport report;
    // The light at the frame (the light track's there), and a look whose single light is the one
    // each analysis below tries.
    Look look = given;
    look.light = given.lightAt(double(frame));
    look.lightTrack = {};
    report.before = look.light;
    report.start = request.start == LightStart::Camera ? cameraLight(look.light, camera) : look.light;
    report.after = report.start;
    report.frame = frame;
    report.width = width;
    report.height = height;
    report.camera = camera;
    if (generation == 0)
        generation = privateGeneration();
    Look lit = look;
    lit.light = report.start;

    FrameAnalysis frameAnalysis;
    analyser.analyse(
        data, lit, shape, generation, frame, camera, width, height, request.analysis, frameAnalysis, shadingOffsets);
    const algo::DepthAnalysis& before = frameAnalysis.analysis;
    report.segmentsBefore = before.stats;
    report.segmentsAfter = before.stats;
    report.mseBefore = report.mseAfter = before.meanSquaredError;
    report.featuresBefore = report.featuresAfter = before.featurePixels;
    // One bar over the whole run: the analysis before, the iterations, the analysis after, and
    // the depth-error search with its analysis when the objective asks for one.
    const bool searches = request.objective != LightObjective::Ratios;
    const std::int64_t iterationSteps = std::int64_t(std::max(0, request.optimiser.iterations));
    const std::int64_t searchSteps = searches ? std::int64_t(std::max(1, request.search.maxEvaluations)) + 1 : 0;
    const std::int64_t steps = iterationSteps + 2 + searchSteps;
    algo::report(progress, 1, steps);
    const auto cancelled = [&] {
        report.run.cancelled = true;
        report.after = report.before;
        report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        return report;
    };
    if (algo::cancelRequested(progress)) {
        report.run.before = report.run.after = poseOf(report.start);
        return cancelled();
    }

    const algo::DepthAnalysisSettings& used = analyser.lastSettings();
    algo::ShadingSamples samples;
    algo::gatherShadingSamples(analyser.gbuffer(), frameAnalysis.passes.normal, before.segments, data.baseMesh->faces,
        used.shadingOffsets, used.toonThreshold, samples);
    // Focal points (paper 3, 6.2): each segment's weight times the mean importance of its faces.
    for (std::size_t s = 0; s < samples.importance.size() && s < before.stats.size(); ++s)
        samples.importance[s] = double(before.stats[s].importance);

    algo::LightOptimisationSettings settings = request.optimiser;
    settings.window = request.analysis.window;
    const Eigen::AlignedBox3d box = algo::boundingBox(shape);
    settings.centre = box.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(box.center());
    settings.scale = box.isEmpty() ? 1.0 : std::max(0.5 * box.diagonal().norm(), 1e-9);

    QElapsedTimer iterations;
    iterations.start();
    algo::LightOptimisationWorkspace workspace;
    algo::ProgressPart iterationsPart(progress, 1, steps);
    report.run = algo::optimiseLight(samples, poseOf(report.start), settings, workspace, &iterationsPart);
    report.optimiseMilliseconds = double(iterations.nsecsElapsed()) / 1e6;
    report.ratiosBefore = report.ratiosAfter = report.run.objectiveBefore;
    if (report.run.cancelled) {
        report.after = report.before;
        report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        return report;
    }
    // The lights the search accepted, the best (by the ratios) last.
    std::vector<Eigen::Vector3d> accepted;
    for (const algo::LightIteration& it : report.run.iterations)
        if (it.accepted)
            accepted.push_back(it.light);
    const bool point = report.start.type == LightType::Point;
    const auto finish = [&] {
        // The ratios' objective of the light kept, over the same samples (the segments follow the
        // shape and the camera, not the light).
        algo::LightEvaluation evaluation;
        algo::evaluateLight(samples, poseOf(report.after), settings, false, evaluation);
        report.ratiosAfter = evaluation.objective;
        report.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        algo::report(progress, steps, steps);
        return report;
    };
    if (accepted.empty() && !searches) // nothing better than the start by the ratios
        return finish();

    // The analysis with the ratios' light: the depth error the artist will see. It may rise where
    // the start light's rim of shadow along the outline gave more features than the new shading
    // line (docs/light-optimisation.md).
    struct Candidate {
        Light light;
        std::vector<algo::SegmentStats> stats;
        double mse = 0.0;
        std::int64_t features = 0;
    };
    Candidate best{report.start, before.stats, before.meanSquaredError, before.featurePixels};
    auto analyseCandidate = [&](const Light& light) {
        Look moved = look;
        moved.light = light;
        analyser.analyse(data, moved, shape, generation, frame, camera, width, height, request.analysis, frameAnalysis,
            shadingOffsets);
        return Candidate{light, frameAnalysis.analysis.stats, frameAnalysis.analysis.meanSquaredError,
            frameAnalysis.analysis.featurePixels};
    };
    Candidate ratios = best;
    if (!accepted.empty())
        ratios = analyseCandidate(lightOf({point, accepted.back()}));
    if (algo::cancelRequested(progress)) // during the analysis after: the light stays as it was
        return cancelled();
    algo::report(progress, iterationSteps + 2, steps);
    const bool keepRatios = request.objective == LightObjective::Ratios
        || (request.objective == LightObjective::Both && ratios.mse <= best.mse);
    if (keepRatios) {
        best = ratios;
    } else {
        // The depth error directly (4.4): a compass search at reduced size from the ratios'
        // answer, then the best it found checked at the analysed size. The start and the ratios'
        // light are candidates too, so the MSE kept is never above the start's.
        if (ratios.mse < best.mse)
            best = ratios;
        const int divisor = std::max(1, request.searchDivisor);
        const int smallWidth = std::min(width, std::max(64, width / divisor));
        const int smallHeight = std::min(height, std::max(64, height / divisor));
        FrameAnalysis small;
        auto mseOf = [&](const algo::LightPose& pose) {
            Look moved = look;
            moved.light = lightOf(pose);
            analyser.analyse(data, moved, shape, generation, frame, camera, smallWidth, smallHeight, request.analysis,
                small, shadingOffsets);
            return small.analysis.meanSquaredError;
        };
        algo::LightSearchSettings search = request.search;
        search.scale = settings.scale;
        algo::ProgressPart searchPart(progress, iterationSteps + 2, steps);
        report.search = algo::searchLight(poseOf(ratios.light), mseOf, search, &searchPart);
        if (report.search.cancelled)
            return cancelled();
        // The start at the small size too: the search's answer must beat it there to be checked.
        const double startSmall = mseOf(poseOf(report.start));
        const Light found = lightOf(report.search.best);
        if (report.search.bestValue < startSmall && !(found == best.light) && !(found == ratios.light)) {
            const Candidate checked = analyseCandidate(found);
            if (algo::cancelRequested(progress))
                return cancelled();
            if (checked.mse < best.mse)
                best = checked;
        }
    }
    report.after = best.light;
    report.segmentsAfter = best.stats;
    report.mseAfter = best.mse;
    report.featuresAfter = best.features;
    return finish();
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

QString lightObjectiveName(LightObjective objective)
{
    switch (objective) {
    case LightObjective::Ratios:
        return QStringLiteral("ratios");
    case LightObjective::DepthError:
        return QStringLiteral("depth-error");
    case LightObjective::Both:
        return QStringLiteral("both");
    }
    return {};
}

bool lightObjectiveFromName(const QString& name, LightObjective& objective)
{
    for (const LightObjective o : {LightObjective::Ratios, LightObjective::DepthError, LightObjective::Both})
        if (name == lightObjectiveName(o)) {
            objective = o;
            return true;
        }
    return false;
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
