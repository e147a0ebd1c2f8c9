// `celform analyze`, `celform curvature` and `celform optimize-light`: the stereo depth analysis
// of a project's picture (paper 3, chapter 4), the per-vertex curvature it starts from, and the
// light moved so that the analysis's segments get shading lines (4.1, 5.0).
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/document/document.h"
#include "celform/model/analysis/light_optimisation.h"
#include "celform/model/analysis/light_track_optimisation.h"
#include "celform/model/analysis/segment_overrides.h"
#include "celform/model/analysis/segment_tracking.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/output_file.h"
#include "celform/model/io/project_file.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"
#include "celform/model/data/blend_evaluator.h"

#include <QFileInfo>
#include <QJsonArray>

namespace celform::app {
namespace {

using RatioWindow = algo::RatioWindow;

/// --window: LO,HI or one of the thesis's presets (5.0.3).
RatioWindow parseWindow(const QString& text)
{
    if (text == QLatin1String("lenient"))
        return {0.2f, 0.8f};
    if (text == QLatin1String("medium"))
        return {0.35f, 0.65f};
    if (text == QLatin1String("strict"))
        return {0.5f, 0.5f};
    const QStringList parts = text.split(QLatin1Char(','));
    bool okLow = false, okHigh = false;
    const double low = parts.size() == 2 ? parts[0].toDouble(&okLow) : 0.0;
    const double high = parts.size() == 2 ? parts[1].toDouble(&okHigh) : 0.0;
    if (!okLow || !okHigh || !(low >= 0.0) || !(high <= 1.0) || !(low <= high))
        throw UsageError{
            Cli::tr("--window takes LO,HI with 0 <= LO <= HI <= 1, or lenient, medium or strict, not “%1”").arg(text)};
    return {float(low), float(high)};
}

/// --window, --depth-threshold and --min-pixels.
model::AnalysisSettings readAnalysisSettings(const Invocation& in)
{
    model::AnalysisSettings settings;
    if (in.isSet("window"))
        settings.window = parseWindow(in.value("window"));
    if (in.isSet("depth-threshold")) {
        settings.depthThreshold = parseNumber("depth-threshold", in.value("depth-threshold"));
        if (!(settings.depthThreshold > 0.0) || settings.depthThreshold > 1.0)
            throw UsageError{Cli::tr("--depth-threshold takes a fraction of the model's size in (0, 1], not “%1”")
                                 .arg(in.value("depth-threshold"))};
    }
    if (in.isSet("min-pixels")) {
        settings.minSegmentPixels = parseInt("min-pixels", in.value("min-pixels"));
        if (settings.minSegmentPixels < 1)
            throw UsageError{
                Cli::tr("--min-pixels takes a whole number of at least 1, not “%1”").arg(in.value("min-pixels"))};
    }
    return settings;
}

QJsonArray windowJson(const RatioWindow& window)
{
    // The window as given (floats printed without their binary tails).
    return QJsonArray{QString::number(double(window.low), 'g', 6).toDouble(),
        QString::number(double(window.high), 'g', 6).toDouble()};
}

/// One analysed frame as `analyze --json` prints it (each element of `frames` with --frames).
/// ids: the segments' stable numbers along the frames (null: their indices).
QJsonObject frameJson(
    int frame, const model::Camera& camera, const model::FrameAnalysis& analysed, const std::vector<int>* ids = nullptr)
{
    const algo::DepthAnalysis& a = analysed.analysis;
    QJsonArray segments;
    for (std::size_t i = 0; i < a.stats.size(); ++i) {
        const algo::SegmentStats& s = a.stats[i];
        segments.append(QJsonObject{{"id", ids && i < ids->size() ? (*ids)[i] : int(i)}, {"pixels", s.pixels},
            {"bright", s.bright}, {"ratio", double(s.ratio)}, {"in_window", s.inWindow},
            {"curvature", s.meanCurvature > 0.f ? "positive" : (s.meanCurvature < 0.f ? "negative" : "flat")},
            {"centroid", QJsonArray{double(s.centroid.x()), double(s.centroid.y())}},
            {"importance", double(s.importance)}});
    }
    return {{"frame", frame},
        {"camera",
            QJsonObject{{"eye", model::vec3Json(camera.eye)}, {"target", model::vec3Json(camera.target)},
                {"up", model::vec3Json(camera.up)}}},
        {"depth_threshold", analysed.depthThreshold}, {"segments", segments},
        {"depth_error",
            QJsonObject{{"mse", a.meanSquaredError}, {"rmse", std::sqrt(a.meanSquaredError)}, {"max", a.maxAbsError},
                {"model_pixels", double(a.modelPixels)}, {"feature_pixels", double(a.featurePixels)}}},
        {"milliseconds", analysed.milliseconds}, {"curvature_milliseconds", analysed.curvatureMilliseconds}};
}

/// `analyze --frames A-B[:STEP]`: every frame in one process through one analyser (issue 26);
/// --json prints {"size", "window", "frames": [...]}, --csv writes a row per frame, --out takes a
/// # pattern (one EXR per frame).
int runAnalyseFrames(const Invocation& in, model::RenderJob job, const model::AnalysisSettings& settings)
{
    const FrameRange range = parseFrameRange("frames", in.value("frames"));
    job.firstFrame = range.first;
    job.lastFrame = range.last;
    job.step = range.step;
    job.output = in.value("out");
    if (in.isSet("out") && !job.output.contains(QLatin1Char('#')))
        throw UsageError{
            Cli::tr("--out with --frames needs a # where the frame number goes, not “%1”").arg(job.output)};
    const QString path = in.argument(0);
    const model::ProjectData data = model::loadProject(path);
    QJsonArray frames;
    QString csv = QStringLiteral("frame,mse,rmse,segments,segments_in_window,milliseconds\n");
    QString text;
    // Stable segment numbers along the frames (issue 26): through the faces each segment covers.
    model::SegmentTracker tracker;
    std::int64_t compared = 0;
    double same = 0.0;
    model::analyseProjectFrames(data, path, job, settings,
        [&](int frame, const model::AnalysisView& view, const model::FrameAnalysis& analysed) {
            if (in.isSet("out"))
                model::writeAnalysisExr(analysed, job.framePath(frame));
            const algo::DepthAnalysis& a = analysed.analysis;
            const int inside = algo::segmentsInWindow(a.stats);
            const std::vector<int>& ids = tracker.track(a.segments, analysed.passes.id);
            compared += tracker.comparedPixels();
            same += tracker.stability() * double(tracker.comparedPixels());
            if (in.isSet("json")) {
                QJsonObject json = frameJson(frame, view.camera, analysed, &ids);
                json.insert("segment_stability", tracker.stability());
                frames.append(json);
            }
            csv += QStringLiteral("%1,%2,%3,%4,%5,%6\n")
                       .arg(frame)
                       .arg(a.meanSquaredError, 0, 'g', 9)
                       .arg(std::sqrt(a.meanSquaredError), 0, 'g', 9)
                       .arg(a.stats.size())
                       .arg(inside)
                       .arg(analysed.milliseconds, 0, 'f', 2);
            text += Cli::tr("frame %1: %2 segments, %3 inside the window; depth error MSE %4 (%5 ms)")
                        .arg(frame)
                        .arg(a.stats.size())
                        .arg(inside)
                        .arg(a.meanSquaredError, 0, 'g', 6)
                        .arg(analysed.milliseconds, 0, 'f', 1)
                + QLatin1Char('\n');
        });
    if (in.isSet("csv")) {
        model::writeWholeFile(in.value("csv"), csv.toUtf8()); // whole or not at all (issue 27)
    }
    if (in.isSet("json")) {
        printJson({{"size", QJsonArray{job.size.width(), job.size.height()}}, {"window", windowJson(settings.window)},
            {"frames", frames}, {"segment_stability", compared > 0 ? same / double(compared) : 1.0}});
        return kExitOk;
    }
    printOut(text);
    return kExitOk;
}

int runAnalyse(const Invocation& in)
{
    if (in.isSet("frame") && in.isSet("frames"))
        throw UsageError{Cli::tr("give either --frame or --frames")};
    if (in.isSet("csv") && !in.isSet("frames"))
        throw UsageError{Cli::tr("--csv goes with --frames")};
    model::RenderJob job;
    readPictureOptions(in, job);
    const model::AnalysisSettings settings = readAnalysisSettings(in);
    const QString out = in.value("out");
    if (in.isSet("out") && QFileInfo(out).suffix().toLower() != QLatin1String("exr"))
        throw UsageError{Cli::tr("--out must end in .exr, not “%1”").arg(out)};
    job.pass = QStringLiteral("segments");
    checkRenderMemory("size", QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height()), job.bytesNeeded());
    if (in.isSet("frames"))
        return runAnalyseFrames(in, job, settings);

    const QString path = in.argument(0);
    const model::ProjectData data = model::loadProject(path);
    const model::FrameAnalysis frame = model::analyseProject(data, path, job, settings);
    if (in.isSet("out"))
        model::writeAnalysisExr(frame, out);

    const algo::DepthAnalysis& a = frame.analysis;
    if (in.isSet("json")) {
        const model::Camera camera = model::renderJobCamera(data, model::renderJobLook(data, job), job, job.firstFrame);
        QJsonObject json = frameJson(job.firstFrame, camera, frame);
        json.insert("size", QJsonArray{job.size.width(), job.size.height()});
        json.insert("window", windowJson(settings.window));
        printJson(json);
        return kExitOk;
    }
    const int inside = algo::segmentsInWindow(a.stats);
    QString text = Cli::tr("segment\tpixels\tratio\tin window") + QLatin1Char('\n');
    for (std::size_t i = 0; i < a.stats.size(); ++i) {
        const algo::SegmentStats& s = a.stats[i];
        text += QStringLiteral("%1\t%2\t%3\t%4\n")
                    .arg(i)
                    .arg(s.pixels)
                    .arg(double(s.ratio), 0, 'f', 3)
                    .arg(s.inWindow ? Cli::tr("yes") : Cli::tr("no"));
    }
    text += Cli::tr("%n segment(s), %1 inside the window %2-%3", nullptr, int(a.stats.size()))
                .arg(inside)
                .arg(double(settings.window.low), 0, 'f', 2)
                .arg(double(settings.window.high), 0, 'f', 2)
        + QLatin1Char('\n');
    text += Cli::tr("depth error: MSE %1, RMSE %2 (model units; %3 of %4 model pixels are features)")
                .arg(a.meanSquaredError, 0, 'g', 6)
                .arg(std::sqrt(a.meanSquaredError), 0, 'g', 6)
                .arg(a.featurePixels)
                .arg(a.modelPixels)
        + QLatin1Char('\n');
    text += Cli::tr("time: %1 ms (curvature %2 ms)")
                .arg(frame.milliseconds, 0, 'f', 1)
                .arg(frame.curvatureMilliseconds, 0, 'f', 1)
        + QLatin1Char('\n');
    printOut(text);
    return kExitOk;
}

int runCurvature(const Invocation& in)
{
    if (!in.isSet("out"))
        throw UsageError{Cli::tr("--out is required")};
    const QString out = in.value("out");
    if (QFileInfo(out).suffix().toLower() != QLatin1String("ply"))
        throw UsageError{Cli::tr("--out must end in .ply, not “%1”").arg(out)};
    const int frame = in.isSet("frame") ? parseFrame("frame", in.value("frame")) : 0;
    const auto view = optionalValue(in, "view", [](const QString& v) { return parseDirection("view", v); });
    const QString path = in.argument(0);
    if (sameFile(path, out))
        throw UsageError{Cli::tr("--out would overwrite the project")};
    const model::ProjectData data = model::loadProject(path);
    if (!data.baseMesh)
        throw model::IoError(path, Cli::tr("has no base model"));
    // The base model, or the view-dependent shape seen from --view at the frame.
    algo::Positions scratch;
    algo::Positions shape = data.basePositions(frame, scratch);
    if (view) {
        model::BlendEvaluator blender;
        QString error;
        if (!blender.update(data, &error))
            throw model::IoError(path, error);
        blender.shape(data, view->normalized(), frame, shape);
    }
    model::DepthAnalyser analyser;
    const algo::Curvatures& curvature = analyser.curvatures(*data.baseMesh, shape, 0);
    model::writeCurvaturePly(shape, data.baseMesh->faces, curvature, out);
    if (in.isSet("json")) {
        double kMin = 0, kMax = 0;
        for (std::size_t i = 0; i < curvature.gaussian.size(); ++i) {
            kMin = i == 0 ? curvature.gaussian[i] : std::min(kMin, double(curvature.gaussian[i]));
            kMax = i == 0 ? curvature.gaussian[i] : std::max(kMax, double(curvature.gaussian[i]));
        }
        printJson({{"vertices", double(shape.rows())}, {"frame", frame}, {"out", out}, {"gaussian_min", kMin},
            {"gaussian_max", kMax}});
    }
    return kExitOk;
}

/// `optimize-light --frames A-B[:STEP]`: a light track over the shot (issue 26), saved as light
/// keys at the sampled frames in one undo step.
int runOptimiseLightTrack(const Invocation& in, model::RenderJob job, const model::LightOptimisationRequest& request)
{
    const FrameRange range = parseFrameRange("frames", in.value("frames"));
    job.firstFrame = range.first;
    job.lastFrame = range.last;
    job.step = range.step;
    model::LightTrackRequest trackRequest;
    trackRequest.light = request;
    if (in.isSet("max-turn")) {
        trackRequest.maxTurnDegrees = parseNumber("max-turn", in.value("max-turn"));
        if (!(trackRequest.maxTurnDegrees > 0.0 && trackRequest.maxTurnDegrees <= 180.0))
            throw UsageError{
                Cli::tr("--max-turn takes degrees per frame in (0, 180], not “%1”").arg(in.value("max-turn"))};
    }
    const QString path = in.argument(0);
    auto doc = openProject(path);
    const model::LightTrackReport report = model::optimiseLightTrack(doc->data(), path, job, trackRequest);
    const bool save = !in.isSet("dry-run") && report.after != report.before;
    if (save) {
        doc->look().applyOptimisedLightTrack(report.before, report.after);
        doc->saveAs(path);
    }
    if (in.isSet("json")) {
        QJsonArray frames;
        for (const model::LightTrackFrame& f : report.frames)
            frames.append(QJsonObject{{"frame", f.frame}, {"light_before", model::lightJson(f.original)},
                {"light_start", model::lightJson(f.start)}, {"light_after", model::lightJson(f.light)},
                {"depth_error",
                    QJsonObject{{"mse_before", f.mseOriginal}, {"mse_start", f.mseStart}, {"mse_after", f.mse}}},
                {"turn_degrees", f.turnDegrees}, {"limited", f.limited}, {"milliseconds", f.milliseconds}});
        printJson({{"size", QJsonArray{report.width, report.height}},
            {"objective", model::lightObjectiveName(request.objective)}, {"max_turn", trackRequest.maxTurnDegrees},
            {"frames", frames},
            {"depth_error",
                QJsonObject{{"mean_mse_before", report.meanMseOriginal()}, {"mean_mse_after", report.meanMse()}}},
            {"largest_turn_degrees", report.largestTurnDegrees()}, {"light_keys", model::lightTrackJson(report.after)},
            {"saved", save}, {"milliseconds", report.milliseconds}});
        return kExitOk;
    }
    QString text;
    for (const model::LightTrackFrame& f : report.frames)
        text += Cli::tr("frame %1: depth error MSE %2 -> %3, turned %4° from the previous key%5")
                    .arg(f.frame)
                    .arg(f.mseOriginal, 0, 'g', 6)
                    .arg(f.mse, 0, 'g', 6)
                    .arg(f.turnDegrees, 0, 'f', 2)
                    .arg(f.limited ? Cli::tr(" (limited)") : QString())
            + QLatin1Char('\n');
    text += Cli::tr("mean depth error MSE: %1 -> %2; largest turn %3° between keys; %4 ms")
                .arg(report.meanMseOriginal(), 0, 'g', 6)
                .arg(report.meanMse(), 0, 'g', 6)
                .arg(report.largestTurnDegrees(), 0, 'f', 2)
                .arg(report.milliseconds, 0, 'f', 0)
        + QLatin1Char('\n');
    if (!save)
        text += (in.isSet("dry-run") ? Cli::tr("not saved (--dry-run)") : Cli::tr("the light track stays as it is"))
            + QLatin1Char('\n');
    printOut(text);
    return kExitOk;
}

int runOptimiseLight(const Invocation& in)
{
    model::RenderJob job;
    readCameraOptions(in, job);
    checkRenderMemory("size", QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height()), job.bytesNeeded());

    model::LightOptimisationRequest request;
    request.analysis = readAnalysisSettings(in);
    if (in.isSet("method") && !model::lightMethodFromName(in.value("method"), request.optimiser.method))
        throw UsageError{Cli::tr("--method must be gradient, annealing or random, not “%1”").arg(in.value("method"))};
    if (in.isSet("weight") && !model::segmentWeightFromName(in.value("weight"), request.optimiser.weight))
        throw UsageError{Cli::tr("--weight must be constant or area, not “%1”").arg(in.value("weight"))};
    if (in.isSet("iterations")) {
        request.optimiser.iterations = parseInt("iterations", in.value("iterations"));
        if (request.optimiser.iterations < 1 || request.optimiser.iterations > 100000)
            throw UsageError{
                Cli::tr("--iterations takes a whole number from 1 to 100000, not “%1”").arg(in.value("iterations"))};
    }
    if (in.isSet("seed")) {
        bool ok = false;
        request.optimiser.seed = in.value("seed").toULongLong(&ok);
        if (!ok)
            throw UsageError{Cli::tr("--seed takes a whole number of at least 0, not “%1”").arg(in.value("seed"))};
    }

    if (in.isSet("objective") && !model::lightObjectiveFromName(in.value("objective"), request.objective))
        throw UsageError{
            Cli::tr("--objective must be ratios, depth-error or both, not “%1”").arg(in.value("objective"))};
    if (in.isSet("start")) {
        const std::pair<const char*, model::LightStart> starts[]
            = {{"current", model::LightStart::Current}, {"camera", model::LightStart::Camera}};
        request.start = parseChoice(in.value("start"), starts, Cli::tr("--start must be current or camera, not “%1”"));
    }
    if (in.isSet("falloff")) {
        request.optimiser.falloff = parseNumber("falloff", in.value("falloff"));
        if (!(request.optimiser.falloff >= 0.0 && request.optimiser.falloff <= 1.0))
            throw UsageError{
                Cli::tr("--falloff takes a ratio width in [0, 1] (0: discrete), not “%1”").arg(in.value("falloff"))};
    }

    if (in.isSet("frame") && in.isSet("frames"))
        throw UsageError{Cli::tr("give either --frame or --frames")};
    if (in.isSet("max-turn") && !in.isSet("frames"))
        throw UsageError{Cli::tr("--max-turn goes with --frames")};
    if (in.isSet("frames"))
        return runOptimiseLightTrack(in, job, request);

    const QString path = in.argument(0);
    auto doc = openProject(path);
    const model::LightOptimisationReport report = model::optimiseLightForJob(doc->data(), path, job, request);
    const bool save = !in.isSet("dry-run") && !(report.after == report.before);
    if (save) {
        // With a light track the light found is keyed at the frame, else it is the single light.
        doc->look().applyOptimisedLight(report.before, report.after, report.frame);
        doc->saveAs(path);
    }

    if (in.isSet("json")) {
        QJsonArray segments;
        for (std::size_t i = 0; i < report.segmentsBefore.size(); ++i) {
            const algo::SegmentStats& b = report.segmentsBefore[i];
            const algo::SegmentStats& a = i < report.segmentsAfter.size() ? report.segmentsAfter[i] : b;
            segments.append(QJsonObject{{"id", int(i)}, {"pixels", b.pixels}, {"ratio_before", double(b.ratio)},
                {"ratio_after", double(a.ratio)}, {"in_window_before", b.inWindow}, {"in_window_after", a.inWindow},
                {"importance", double(b.importance)}});
        }
        QJsonArray iterations;
        for (const algo::LightIteration& it : report.run.iterations) {
            QJsonArray ratios;
            for (float r : it.ratios)
                ratios.append(double(r));
            iterations.append(
                QJsonObject{{"tried", it.tried}, {"objective", it.objective}, {"light", model::vec3Json(it.light)},
                    {"step", it.step}, {"accepted", it.accepted}, {"ratios", ratios}});
        }
        QJsonArray search;
        for (const algo::LightSearchVisit& v : report.search.visits)
            search.append(QJsonObject{
                {"light", model::vec3Json(v.light)}, {"mse", v.value}, {"step", v.step}, {"accepted", v.accepted}});
        printJson({{"frame", report.frame}, {"size", QJsonArray{report.width, report.height}},
            {"camera",
                QJsonObject{{"eye", model::vec3Json(report.camera.eye)},
                    {"target", model::vec3Json(report.camera.target)}, {"up", model::vec3Json(report.camera.up)}}},
            {"method", model::lightMethodName(request.optimiser.method)},
            {"weight", model::segmentWeightName(request.optimiser.weight)},
            {"window",
                QJsonArray{QString::number(double(request.analysis.window.low), 'g', 6).toDouble(),
                    QString::number(double(request.analysis.window.high), 'g', 6).toDouble()}},
            {"seed", QString::number(request.optimiser.seed)},
            {"objective", model::lightObjectiveName(request.objective)},
            {"start", request.start == model::LightStart::Camera ? "camera" : "current"},
            {"falloff", request.optimiser.falloff}, {"light_before", model::lightJson(report.before)},
            {"light_start", model::lightJson(report.start)}, {"light_after", model::lightJson(report.after)},
            {"objective_before", report.ratiosBefore}, {"objective_after", report.ratiosAfter},
            {"objectives",
                QJsonObject{{"ratios", QJsonObject{{"before", report.ratiosBefore}, {"after", report.ratiosAfter}}},
                    {"depth_error", QJsonObject{{"before", report.mseBefore}, {"after", report.mseAfter}}}}},
            {"iterations", iterations}, {"search", search}, {"segments", segments},
            {"segments_in_window",
                QJsonArray{
                    algo::segmentsInWindow(report.segmentsBefore), algo::segmentsInWindow(report.segmentsAfter)}},
            {"depth_error", QJsonObject{{"mse_before", report.mseBefore}, {"mse_after", report.mseAfter}}},
            {"saved", save}, {"milliseconds", report.milliseconds},
            {"optimise_milliseconds", report.optimiseMilliseconds}});
        return kExitOk;
    }
    auto lightText = [](const model::Light& l) {
        return QStringLiteral("%1 (%2, %3, %4)")
            .arg(l.type == model::LightType::Point ? Cli::tr("point") : Cli::tr("directional"))
            .arg(l.vector.x(), 0, 'g', 4)
            .arg(l.vector.y(), 0, 'g', 4)
            .arg(l.vector.z(), 0, 'g', 4);
    };
    QString text
        = Cli::tr("light: %1 -> %2").arg(lightText(report.before), lightText(report.after)) + QLatin1Char('\n');
    text += Cli::tr("segments inside the window: %1 -> %2 of %3")
                .arg(algo::segmentsInWindow(report.segmentsBefore))
                .arg(algo::segmentsInWindow(report.segmentsAfter))
                .arg(report.segmentsBefore.size())
        + QLatin1Char('\n');
    text += Cli::tr("depth error MSE: %1 -> %2").arg(report.mseBefore, 0, 'g', 6).arg(report.mseAfter, 0, 'g', 6)
        + QLatin1Char('\n');
    text += Cli::tr("time: %1 ms (iterations %2 ms)")
                .arg(report.milliseconds, 0, 'f', 1)
                .arg(report.optimiseMilliseconds, 0, 'f', 1)
        + QLatin1Char('\n');
    if (!save)
        text += (in.isSet("dry-run") ? Cli::tr("not saved (--dry-run)") : Cli::tr("the light stays where it is"))
            + QLatin1Char('\n');
    printOut(text);
    return kExitOk;
}

/// "A,B,..." of --merge and --release: segment numbers.
std::vector<int> parseSegmentList(const char* option, const QString& text)
{
    std::vector<int> out;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int s = part.trimmed().toInt(&ok);
        if (!ok || s < 0)
            throw UsageError{Cli::tr("--%1 takes segment numbers like 3,7, not “%2”").arg(QLatin1String(option), text)};
        out.push_back(s);
    }
    if (out.empty())
        throw UsageError{Cli::tr("--%1 takes segment numbers like 3,7, not “%2”").arg(QLatin1String(option), text)};
    return out;
}

/// "X,Y,X,Y,..." of --stroke: two or more points in the analysed picture's pixels.
std::vector<Eigen::Vector2d> parseStroke(const QString& text)
{
    const QStringList parts = text.split(QLatin1Char(','));
    std::vector<Eigen::Vector2d> points;
    bool ok = parts.size() >= 4 && parts.size() % 2 == 0;
    for (int i = 0; ok && i + 1 < parts.size(); i += 2) {
        bool okX = false, okY = false;
        const double x = parts[i].toDouble(&okX), y = parts[i + 1].toDouble(&okY);
        ok = okX && okY && std::isfinite(x) && std::isfinite(y);
        points.emplace_back(x, y);
    }
    if (!ok)
        throw UsageError{Cli::tr("--stroke takes two or more pixel positions X,Y,X,Y,..., not “%1”").arg(text)};
    return points;
}

/// `celform segments`: the segment brush from the command line (issue 26): merges, splits and
/// releases by the segment numbers `analyze --json` prints for the same frame, camera and size,
/// stored as per-face overrides in one undo step.
int runSegments(const Invocation& in)
{
    const int actions = in.countSet({"list", "merge", "split", "release", "clear"});
    if (actions != 1)
        throw UsageError{
            Cli::tr("give one of --list, --merge A,B, --split S --stroke X,Y,X,Y, --release S or --clear")};
    if (in.isSet("split") != in.isSet("stroke"))
        throw UsageError{Cli::tr("--split and --stroke go together")};
    const QString path = in.argument(0);
    if (in.isSet("list")) {
        const model::ProjectData data = model::loadProject(path);
        const std::vector<std::int64_t> sizes = model::segmentOverrideSizes(data.segmentOverrides);
        QJsonArray groups;
        QString text;
        for (std::size_t l = 0; l < sizes.size(); ++l) {
            groups.append(QJsonObject{{"label", int(l)}, {"faces", double(sizes[l])}});
            text += Cli::tr("override %1	%2 faces").arg(l).arg(sizes[l]) + QLatin1Char('\n');
        }
        if (in.isSet("json")) {
            QJsonObject json = segmentOverridesJson(data);
            json.insert("overrides", groups);
            json.insert("face_importance", faceImportanceJson(data));
            printJson(json);
        } else {
            printOut(text.isEmpty() ? Cli::tr("no segment overrides") + QLatin1Char('\n') : text);
        }
        return kExitOk;
    }
    model::RenderJob job;
    readCameraOptions(in, job);
    job.pass = QStringLiteral("segments");
    const model::AnalysisSettings settings = readAnalysisSettings(in);
    checkRenderMemory("size", QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height()), job.bytesNeeded());
    const std::vector<int> chosen = in.isSet("merge") ? parseSegmentList("merge", in.value("merge"))
        : in.isSet("release")                         ? parseSegmentList("release", in.value("release"))
        : in.isSet("split")                           ? parseSegmentList("split", in.value("split"))
                                                      : std::vector<int>{};
    if (in.isSet("split") && chosen.size() != 1)
        throw UsageError{Cli::tr("--split takes one segment number, not “%1”").arg(in.value("split"))};
    const std::vector<Eigen::Vector2d> stroke
        = in.isSet("stroke") ? parseStroke(in.value("stroke")) : std::vector<Eigen::Vector2d>{};
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    int before = -1, after = -1;
    if (in.isSet("clear")) {
        doc->faceSets().setSegmentOverrides({}, Cli::tr("Clear Segment Overrides"));
    } else {
        model::SegmentPicture picture;
        const model::FrameAnalysis analysed = model::analyseProject(doc->data(), path, job, settings, &picture.faces);
        picture.segments = analysed.analysis.segments;
        before = int(picture.segments.sizes.size());
        model::voteSegmentFaces(picture, std::int32_t(doc->data().baseMesh->faceCount()));
        std::vector<std::int32_t> overrides;
        QString undoText;
        if (in.isSet("merge")) {
            overrides = model::mergedSegmentOverrides(doc->data(), picture, chosen);
            undoText = Cli::tr("Merge Segments");
        } else if (in.isSet("release")) {
            overrides = model::releasedSegmentOverrides(doc->data(), picture, chosen);
            undoText = Cli::tr("Release Segments");
        } else {
            const model::AnalysisView view = model::resolveAnalysisView(doc->data(), path, job);
            overrides = model::splitSegmentOverrides(doc->data(), picture, chosen.front(), stroke, view.shape,
                model::rasterCamera(view.camera, job.size.width(), job.size.height()));
            undoText = Cli::tr("Split Segment");
        }
        doc->faceSets().setSegmentOverrides(std::move(overrides), undoText);
        after = int(model::analyseProject(doc->data(), path, job, settings).analysis.segments.sizes.size());
    }
    doc->saveAs(path);
    if (in.isSet("json")) {
        QJsonObject json = segmentOverridesJson(doc->data());
        if (before >= 0) {
            json.insert("frame", job.firstFrame);
            json.insert("size", QJsonArray{job.size.width(), job.size.height()});
            json.insert("segments_before", before);
            json.insert("segments_after", after);
        }
        printJson(json);
    } else if (before >= 0) {
        printOut(
            Cli::tr("segments at frame %1: %2 -> %3").arg(job.firstFrame).arg(before).arg(after) + QLatin1Char('\n'));
    }
    return kExitOk;
}

} // namespace

std::vector<SubCommand> analysisCommands()
{
    // The analysis settings `analyze` and `optimize-light` share (readAnalysisSettings).
    const OptionSpec window{"window", "LO,HI",
        QT_TRANSLATE_NOOP("celform::app::Cli",
            "Bright/dark ratio window a segment should be in: LO,HI, lenient (0.2-0.8), medium (0.35-0.65, "
            "the default) or strict (0.5).")};
    const OptionSpec depthThreshold{"depth-threshold", "FRACTION",
        QT_TRANSLATE_NOOP("celform::app::Cli",
            "Neighbouring pixels whose depths differ by this fraction of the model's bounding-box diagonal "
            "or more are in different segments (default 0.02).")};
    const OptionSpec minPixels{"min-pixels", "N",
        QT_TRANSLATE_NOOP("celform::app::Cli", "Segments smaller than this are dropped as noise (default 64).")};

    std::vector<OptionSpec> analyseOptions = camera_options::specs();
    const std::vector<OptionSpec> picture
        = {{"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame to analyse (default 0).")},
            {"frames", "A-B[:STEP]",
                QT_TRANSLATE_NOOP("celform::app::Cli",
                    "Frames to analyse, A-B inclusive, every STEP-th (default 1), through the shot camera unless a "
                    "camera is given; --json lists them under \"frames\", --out needs a # for the frame number.")},
            {"csv", "FILE",
                QT_TRANSLATE_NOOP("celform::app::Cli",
                    "With --frames: a row per frame (frame, mse, rmse, segments, segments_in_window, "
                    "milliseconds).")},
            {"size", "WxH", QT_TRANSLATE_NOOP("celform::app::Cli", "Picture size (default 1280x720).")}};
    const std::vector<OptionSpec> look = lookOverrideSpecs();
    const std::vector<OptionSpec> analysis = {window, depthThreshold, minPixels, {"json", nullptr, kJsonOption},
        {"out", "FILE.exr",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Write the picture and the buffers (curvature, segment ids, depth, depth error, features, N.L and "
                "the light gradient) as EXR "
                "channels.")}};
    for (const auto* part : {&picture, &look, &analysis})
        analyseOptions.insert(analyseOptions.end(), part->begin(), part->end());

    std::vector<OptionSpec> optimiseOptions = camera_options::specs();
    const std::vector<OptionSpec> optimiseMore = {
        {"frame", "F",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Frame to optimise for (default 0); with a light track the light found is keyed there.")},
        {"frames", "A-B[:STEP]",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Optimise a light track: the light at frames A-B every STEP-th (default 1) through the shot camera, "
                "each frame starting from the previous one's light, saved as light keys.")},
        {"max-turn", "DEG",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "With --frames: the most a key turns from the previous one per frame, in degrees (default 3).")},
        {"size", "WxH", QT_TRANSLATE_NOOP("celform::app::Cli", "Size of the analysed picture (default 1280x720).")},
        window,
        {"weight", "constant|area",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "How much each segment counts: all alike (constant, the default: small dents count as much as the "
                "body) or by its size (area).")},
        {"method", "gradient|annealing|random",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "gradient (the default: moves the light from where it is along the shading's derivative), "
                "annealing (shrinking random steps) or random (independent random lights, the best kept).")},
        {"iterations", "N", QT_TRANSLATE_NOOP("celform::app::Cli", "Iterations (default 64).")},
        {"seed", "S", QT_TRANSLATE_NOOP("celform::app::Cli", "Seed of the annealing and random methods (default 1).")},
        {"objective", "ratios|depth-error|both",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "ratios (the thesis's, may raise the depth error), depth-error (a search minimising the depth "
                "error from the ratios' answer) or both (the default: the ratios' light unless it raises the depth "
                "error, else the best depth error met; never above the start's).")},
        {"start", "current|camera",
            QT_TRANSLATE_NOOP(
                "celform::app::Cli", "Start from the project's light (current, the default) or at the camera.")},
        {"falloff", "W",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Width of figure 5.8's linear fall-off outside the window (default 0.1; 0: discrete).")},
        depthThreshold, minPixels,
        {"dry-run", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Report the light found without saving it.")},
        {"json", nullptr, kJsonOption}};
    optimiseOptions.insert(optimiseOptions.end(), optimiseMore.begin(), optimiseMore.end());

    std::vector<OptionSpec> segmentOptions = camera_options::specs();
    const std::vector<OptionSpec> segmentMore = {
        {"list", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "List the override groups and their faces.")},
        {"merge", "A,B[,C...]",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Make these segments (the numbers `analyze --json` gives for the same frame, camera and size) one.")},
        {"split", "S", QT_TRANSLATE_NOOP("celform::app::Cli", "Split this segment in two along --stroke.")},
        {"stroke", "X,Y,X,Y[,...]",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "With --split: the stroke's points in the analysed picture's pixels (x right, y down).")},
        {"release", "S[,T...]",
            QT_TRANSLATE_NOOP(
                "celform::app::Cli", "Give these segments' faces back to the analysis's own segmentation.")},
        {"clear", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Remove every segment override.")},
        {"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame the segments are numbered at (default 0).")},
        {"size", "WxH", QT_TRANSLATE_NOOP("celform::app::Cli", "Size of the analysed picture (default 1280x720).")},
        window, depthThreshold, minPixels, {"json", nullptr, kJsonOption}};
    segmentOptions.insert(segmentOptions.end(), segmentMore.begin(), segmentMore.end());
    return {
        {"analyze",
            {"celform analyze P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F | --frames "
             "A-B[:STEP]] "
             "[--size WxH] "
             "[--style toon|gooch|comic|lambert] [--lines on|off|KIND,...] [--light point:X,Y,Z|directional:X,Y,Z] "
             "[--ridge-threshold T] [--ridges snakes|raw] [--ridge-depth K] [--subdivision N] [--window "
             "LO,HI|lenient|medium|strict] "
             "[--depth-threshold FRACTION] [--min-pixels N] [--json] [--csv FILE] [--out FILE.exr]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Stereo depth analysis of the picture: segments with their bright/dark ratios, and the depth error."),
            {{"P", kProjectArgument}}, analyseOptions, runAnalyse},
        {"curvature", {"celform curvature P [--frame F] [--view X,Y,Z] [--json] --out FILE.ply"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Writes the per-vertex principal curvatures k1, k2 and the Gaussian curvature K as PLY properties."),
            {{"P", kProjectArgument}},
            {{"frame", "F", QT_TRANSLATE_NOOP("celform::app::Cli", "Frame of the shape (default 0).")},
                {"view", "X,Y,Z",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "The view-dependent shape seen from this direction (default: the base model).")},
                {"json", nullptr, kJsonOption},
                {"out", "FILE.ply", QT_TRANSLATE_NOOP("celform::app::Cli", "The PLY file to write.")}},
            runCurvature},
        {"optimize-light",
            {"celform optimize-light P [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] "
             "[--frame F | --frames A-B[:STEP] [--max-turn DEG]] [--size WxH] [--window LO,HI|lenient|medium|strict] "
             "[--weight constant|area] "
             "[--method gradient|annealing|random] [--iterations N] [--seed S] "
             "[--objective ratios|depth-error|both] [--start current|camera] [--falloff W] "
             "[--depth-threshold FRACTION] [--min-pixels N] [--dry-run] [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Moves the key light so that every segment's bright/dark ratio gets into the window, and saves "
                "the project."),
            {{"P", kProjectArgument}}, optimiseOptions, runOptimiseLight},
        {"segments",
            {"celform segments P --list [--json]",
                "celform segments P (--merge A,B[,C...] | --split S --stroke X,Y,X,Y[,...] | --release S[,T...]) "
                "[--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F] [--size WxH] "
                "[--window LO,HI|lenient|medium|strict] [--depth-threshold FRACTION] [--min-pixels N] [--json]",
                "celform segments P --clear [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "The segment brush: merges segments of the depth analysis, splits one along a stroke, or gives "
                "them back to the analysis, saved as per-face overrides."),
            {{"P", kProjectArgument}}, segmentOptions, runSegments},
    };
}

} // namespace celform::app
