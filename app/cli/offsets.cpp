// `celform offsets`: the document's shading-offset operations (paper 3, section 4.3) from the
// command line: automatic per-segment offsets for a view, clearing and smoothing, into the base
// layer or a key's layer, saved in the project.
#include "cli/command.h"
#include "cli/options.h"

#include "celform/model/analysis/auto_offsets.h"
#include "celform/model/document/document.h"
#include "celform/model/data/io_error.h"
#include "celform/model/render/render_job.h"

#include <QJsonArray>

namespace celform::app {
namespace {

/// The target of --key NAME at frame, or the base.
model::ShadingTarget targetOf(const Invocation& in, const model::Document& doc, const QString& path, int frame)
{
    if (!in.isSet("key"))
        return {0, frame};
    const model::KeyViewpoint* key = doc.data().keyByName(in.value("key"));
    if (!key)
        throw model::IoError(path, Cli::tr("has no key named “%1”").arg(in.value("key")));
    return {key->id, frame};
}

int runOffsets(const Invocation& in)
{
    if (in.countSet({"auto", "clear", "smooth"}) != 1)
        throw UsageError{Cli::tr("exactly one of --auto, --clear or --smooth is required")};
    const bool automatic = in.isSet("auto");
    if (!automatic
        && in.countSet({"view", "eye", "target", "up", "size", "aggressiveness", "percentile", "bleed", "segments"})
            > 0)
        throw UsageError{Cli::tr("camera, picture and solve options go with --auto only")};
    // The camera and picture as `celform analyze` takes them; the look is the project's own.
    model::RenderJob job;
    readCameraOptions(in, job);
    model::AutoOffsetsRequest request;
    if (in.isSet("aggressiveness")) {
        request.aggressiveness = float(parseNumber("aggressiveness", in.value("aggressiveness")));
        if (!(request.aggressiveness >= 0.f && request.aggressiveness <= 1.f))
            throw UsageError{Cli::tr("--aggressiveness must be in [0, 1]")};
    }
    if (in.isSet("percentile")) {
        request.percentile = float(parseNumber("percentile", in.value("percentile")));
        if (!(request.percentile >= 0.f && request.percentile <= 1.f))
            throw UsageError{Cli::tr("--percentile must be in [0, 1]")};
    }
    if (in.isSet("bleed")) {
        request.bleed = parseInt("bleed", in.value("bleed"));
        if (request.bleed < 0 || request.bleed > model::kMaxOffsetRounds)
            throw UsageError{Cli::tr("--bleed must be a whole number from 0 to %1").arg(model::kMaxOffsetRounds)};
    }
    if (in.isSet("segments")) {
        const std::pair<const char*, model::OffsetSegments> choices[]
            = {{"outside", model::OffsetSegments::Outside}, {"all", model::OffsetSegments::All}};
        request.segments
            = parseChoice(in.value("segments"), choices, Cli::tr("--segments must be outside or all, not “%1”"));
    }
    int rounds = 0;
    if (in.isSet("smooth")) {
        rounds = parseInt("smooth", in.value("smooth"));
        if (rounds < 1 || rounds > model::kMaxOffsetRounds)
            throw UsageError{Cli::tr("--smooth must be a whole number from 1 to %1").arg(model::kMaxOffsetRounds)};
    }
    // The analysis's own bounds (auto_offsets.cpp) are a usage error here, as every option's range.
    if (automatic
        && (job.size.width() < 16 || job.size.height() < 16 || job.size.width() > 8192 || job.size.height() > 8192))
        throw UsageError{Cli::tr("--size must be between 16x16 and 8192x8192 for --auto, not %1x%2")
                             .arg(job.size.width())
                             .arg(job.size.height())};
    if (automatic)
        checkRenderMemory(
            "size", QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height()), job.bytesNeeded());

    const QString path = in.argument(0);
    auto doc = openProject(path);
    if (!doc->hasMesh())
        throw model::IoError(path, Cli::tr("has no base model"));
    const model::ShadingTarget target = targetOf(in, *doc, path, job.firstFrame);
    const QString targetName = in.isSet("key") ? in.value("key") : QStringLiteral("base");
    QJsonObject json{{"target", targetName}, {"frame", job.firstFrame}};
    if (automatic) {
        const model::Look look = model::renderJobLook(doc->data(), job);
        request.target = target;
        request.camera = model::renderJobCamera(doc->data(), look, job, job.firstFrame);
        request.width = job.size.width();
        request.height = job.size.height();
        const model::AutoOffsetsResult result = model::solveAutoOffsets(doc->data(), request);
        doc->shading().applyAutoOffsets(result.target, result.values);
        QJsonArray segments;
        for (std::size_t s = 0; s < result.after.size(); ++s)
            segments.append(QJsonObject{{"id", int(s)}, {"pixels", result.after[s].pixels},
                {"ratio_before", s < result.before.size() ? double(result.before[s].ratio) : 0.0},
                {"ratio_after", double(result.after[s].ratio)},
                {"covered", s < result.report.covered.size() && result.report.covered[s] != 0}});
        json.insert("operation", "auto");
        json.insert("aggressiveness", double(request.aggressiveness));
        json.insert("percentile", double(request.percentile));
        json.insert("bleed", request.bleed);
        json.insert("segments_solved", request.segments == model::OffsetSegments::All ? "all" : "outside");
        json.insert("segments", segments);
        json.insert("depth_error_mse", QJsonObject{{"before", result.mseBefore}, {"after", result.mseAfter}});
        json.insert("iterations", result.report.iterations);
        json.insert("converged", result.report.converged);
        json.insert("milliseconds", result.milliseconds);
        if (!in.isSet("json")) {
            const int inWindowBefore = algo::segmentsInWindow(result.before);
            const int inWindowAfter = algo::segmentsInWindow(result.after);
            printOut(Cli::tr("%1 segments, %2 inside the ratio window before, %3 after; depth error MSE %4 before, "
                             "%5 after (%6 ms)")
                         .arg(result.after.size())
                         .arg(inWindowBefore)
                         .arg(inWindowAfter)
                         .arg(result.mseBefore, 0, 'g', 6)
                         .arg(result.mseAfter, 0, 'g', 6)
                         .arg(result.milliseconds, 0, 'f', 0)
                + QLatin1Char('\n'));
        }
    } else if (in.isSet("clear")) {
        // --clear on a key without --frame clears every frame of its layer.
        doc->shading().clearShadingOffsets(target, !target.isBase() && !in.isSet("frame"));
        json.insert("operation", "clear");
    } else {
        doc->shading().smoothShadingOffsets(target, rounds);
        json.insert("operation", "smooth");
        json.insert("rounds", rounds);
    }
    doc->saveAs(path);
    if (in.isSet("json"))
        printJson(json);
    return kExitOk;
}

} // namespace

std::vector<SubCommand> offsetsCommands()
{
    std::vector<OptionSpec> options = camera_options::specs();
    const std::vector<OptionSpec> more = {
        {"auto", nullptr,
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Automatic per-segment offsets for the view: each segment of the depth analysis outside the "
                "ratio window 0.35-0.65 (or every segment, --segments all) gets the ratio 1 - Q.")},
        {"segments", "outside|all",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Which segments --auto solves: outside the window (the default, thesis 4.3) or all.")},
        {"clear", nullptr, QT_TRANSLATE_NOOP("celform::app::Cli", "Remove the target's offsets.")},
        {"smooth", "N",
            QT_TRANSLATE_NOOP("celform::app::Cli", "N rounds of smoothing over the mesh's vertex neighbours.")},
        {"frame", "F",
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Frame analysed, and the key layer's frame (default 0; --clear on a key without it clears every "
                "frame).")},
        {"size", "WxH", QT_TRANSLATE_NOOP("celform::app::Cli", "Analysed picture size (default 1280x720).")},
        {"aggressiveness", "A",
            QT_TRANSLATE_NOOP("celform::app::Cli", "How far towards the solved offsets, in [0, 1] (default 1).")},
        {"percentile", "Q",
            QT_TRANSLATE_NOOP("celform::app::Cli", "Fraction of each segment left dark, in [0, 1] (default 0.5).")},
        {"bleed", "N",
            QT_TRANSLATE_NOOP("celform::app::Cli", "Rounds the offsets bleed to neighbouring vertices (default 2).")},
        {"key", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "Edit this key's layer instead of the base layer.")},
        {"json", nullptr, kJsonOption}};
    options.insert(options.end(), more.begin(), more.end());
    return {
        {"offsets",
            {"celform offsets P --auto [--view X,Y,Z | --eye X,Y,Z --target X,Y,Z --up X,Y,Z] [--frame F] "
             "[--size WxH] [--aggressiveness A] [--percentile Q] [--bleed N] [--segments outside|all] [--key NAME] "
             "[--json]",
                "celform offsets P --clear [--key NAME] [--frame F] [--json]",
                "celform offsets P --smooth N [--key NAME] [--frame F] [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Shading offsets (paper 3, section 4.3): automatic per segment, cleared or smoothed; saved in the "
                "project."),
            {{"P", kProjectArgument}}, options, runOffsets},
    };
}

} // namespace celform::app
