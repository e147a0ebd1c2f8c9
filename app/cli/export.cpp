// `celform export`: the view-dependent model's animation for other tools:
// a glTF scene (text or binary) with key morph targets, their weights and the camera path, a PC2
// point cache, one OBJ mesh per frame, or a time-sampled USD layer. The model's exporters do the work (export.h).
#include "cli/command.h"
#include "cli/options.h"
#include "cli/stderr_progress.h"

#include "celform/model/export/export.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/project_file.h"

#include <QFileInfo>
#include <QJsonArray>

namespace celform::app {
namespace {

// An unqualified return type: lupdate misreads a qualified one as the context of Cli::tr() strings.
using model::ExportJob;

int runExport(const Invocation& in)
{
    if (!in.isSet("format") || !in.isSet("out"))
        throw UsageError{Cli::tr("--format and --out are required")};
    std::optional<FrameRange> frames;
    model::ExportJob job = readExportJob(in, frames);

    const QString path = in.argument(0);
    const model::ProjectData data = model::loadProject(path, model::DrawingImages::Skip);
    if (!data.baseMesh)
        throw model::IoError(path, Cli::tr("has no base model"));
    job.firstFrame = frames ? frames->first : data.time.firstFrame;
    job.lastFrame = frames ? frames->last : data.time.lastFrame;

    // Progress on stderr once an export has run a second, at most once a second.
    StderrProgress progress(
        [](std::int64_t done, std::int64_t total) { return Cli::tr("export: frame %1 of %2").arg(done).arg(total); });
    const model::ExportResult result = model::exportProject(data, path, job, &progress);
    for (const QString& w : result.warnings)
        printErr(Cli::tr("warning: %1: %2").arg(path, w));
    if (in.isSet("json")) {
        QJsonArray files;
        for (const QString& f : result.files)
            files.append(f);
        printJson({{"format", model::exportFormatName(job.format)},
            {"frame_range", QJsonArray{job.firstFrame, job.lastFrame}}, {"frames", result.frames}, {"files", files},
            {"warnings", QJsonArray::fromStringList(result.warnings)}});
    }
    return kExitOk;
}

} // namespace

ExportJob readExportJob(const Invocation& in, std::optional<FrameRange>& frames)
{
    const auto format = model::exportFormatFromName(in.value("format"));
    if (!format)
        throw UsageError{Cli::tr("--format must be gltf, glb, pc2, obj-seq or usda, not “%1”").arg(in.value("format"))};
    model::ExportJob job;
    job.format = *format;
    job.output = in.value("out");
    if (job.output.isEmpty())
        throw UsageError{Cli::tr("--out needs a file name")};
    const QString suffix = QFileInfo(job.output).suffix().toLower();
    const QString wanted
        = *format == model::ExportFormat::ObjSequence ? QStringLiteral("obj") : model::exportFormatName(*format);
    if (suffix != wanted)
        throw UsageError{Cli::tr("--out must end in .%1 for --format %2, not “%3”")
                             .arg(wanted, model::exportFormatName(*format), job.output)};
    if (in.isSet("frames")) {
        frames = parseFrameRange("frames", in.value("frames"));
        // Every format holds consecutive frames (a cache's sample rate, glTF's times).
        if (frames->step != 1)
            throw UsageError{Cli::tr("--frames takes A-B for an export, without a step: “%1”").arg(in.value("frames"))};
    }

    if (in.isSet("subdivision"))
        job.subdivision = parseSubdivision("subdivision", in.value("subdivision"));
    if (job.subdivision > 0 && (*format == model::ExportFormat::Gltf || *format == model::ExportFormat::Glb))
        throw UsageError{Cli::tr("--subdivision applies to pc2, obj-seq and usda exports; glTF keeps the base "
                                 "model for its morph targets")};
    job.blendShapes = in.isSet("blend-shapes");
    if (job.blendShapes && *format != model::ExportFormat::Usda)
        throw UsageError{Cli::tr("--blend-shapes applies to usda exports (glTF always holds the keys as morph "
                                 "targets)")};
    if (job.blendShapes && job.subdivision > 0)
        throw UsageError{Cli::tr("--blend-shapes holds the keys on the base model and takes no --subdivision")};
    return job;
}

std::vector<SubCommand> exportCommands()
{
    return {
        {"export",
            {"celform export P --format gltf|glb|pc2|obj-seq|usda [--frames A-B] [--subdivision N] [--blend-shapes] "
             "--out FILE [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Exports the animation as seen through the camera path: a glTF scene with the keys as morph "
                "targets, a PC2 point cache, an OBJ per frame or a USD layer with time-sampled points and camera."),
            {{"P", kProjectArgument}},
            {{"format", "F",
                 QT_TRANSLATE_NOOP("celform::app::Cli",
                     "gltf or glb (keys as morph targets, weights and camera animated), pc2 (point cache) or "
                     "obj-seq (one OBJ per frame) or usda (USD text: time-sampled mesh and camera).")},
                {"frames", "A-B",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Frames to export, A-B inclusive (default the project's).")},
                {"subdivision", "N",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Loop subdivision level of the exported surface, 0 to 3, for pc2, obj-seq and usda (default "
                        "0: the base model's vertices, in its order).")},
                {"blend-shapes", nullptr,
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "usda: the enabled keys as UsdSkel blend shapes with animated weights; the points then hold "
                        "the shape without them.")},
                {"out", "FILE",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "The file; for obj-seq a pattern where a run of # is the frame number (else _FFFF goes "
                        "before .obj).")},
                {"json", nullptr, kJsonOption}},
            runExport},
    };
}

} // namespace celform::app
