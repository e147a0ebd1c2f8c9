// `celform outline` and `celform fit`: Fit to Drawing from the command line (docs/fit-to-drawing.md).
// The outline a fit aims at is written as SVG or PNG for a look; the fits run the model's solves
// (model/analysis/drawing_fit.h) and apply them through the document, as the editor does.
#include "cli/command.h"
#include "cli/options.h"
#include "cli/stderr_progress.h"

#include "celform/model/analysis/drawing_fit.h"
#include "celform/model/data/io_error.h"
#include "celform/model/document/document.h"
#include "celform/model/io/output_file.h"
#include "celform/model/io/project_file.h"

#include <QElapsedTimer>
#include <QImage>
#include <QImageWriter>
#include <QJsonArray>
#include <QBuffer>

namespace celform::app {
namespace {

/// The drawing named by --drawing (required when the project holds none linked).
const model::Drawing& namedDrawing(const model::Document& doc, const QString& path, const QString& name)
{
    const model::Drawing* drawing = doc.data().drawingByName(name);
    if (!drawing)
        throw model::IoError(path, Cli::tr("has no drawing named “%1”").arg(name));
    return *drawing;
}

/// --threshold and --closing over the drawing's saved outline settings.
model::DrawingOutline outlineOptions(const Invocation& in, model::DrawingOutline outline)
{
    if (in.isSet("threshold")) {
        const QString t = in.value("threshold");
        if (t == QLatin1String("auto")) {
            outline.threshold = -1.0;
        } else {
            outline.threshold = parseNumber("threshold", t);
            if (outline.threshold < 0.0 || outline.threshold > 1.0)
                throw UsageError{Cli::tr("--threshold takes auto or a number from 0 to 1, not “%1”").arg(t)};
        }
    }
    if (in.isSet("closing")) {
        outline.closingRadius = parseNumber("closing", in.value("closing"));
        if (outline.closingRadius < 0.0 || outline.closingRadius > model::DrawingOutline::kMaxClosingRadius)
            throw UsageError{Cli::tr("--closing takes a radius from 0 to %1 pixels, not “%2”")
                                 .arg(model::DrawingOutline::kMaxClosingRadius)
                                 .arg(in.value("closing"))};
    }
    if (in.isSet("inner-lines"))
        outline.innerLines = parseOnOff("inner-lines", in.value("inner-lines"));
    return outline;
}

QByteArray outlineSvg(const algo::Outline& outline)
{
    QByteArray svg;
    svg += QStringLiteral(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%1\" height=\"%2\" viewBox=\"0 0 %1 %2\">\n")
               .arg(outline.width)
               .arg(outline.height)
               .toUtf8();
    svg += "<path fill=\"none\" stroke=\"#ff00aa\" stroke-width=\"2\" fill-rule=\"evenodd\" d=\"";
    for (const auto& contour : outline.contours) {
        for (std::size_t i = 0; i < contour.size(); ++i)
            svg += QStringLiteral("%1%2 %3 ")
                       .arg(i == 0 ? QLatin1Char('M') : QLatin1Char('L'))
                       .arg(contour[i].x(), 0, 'f', 2)
                       .arg(contour[i].y(), 0, 'f', 2)
                       .toUtf8();
        if (!contour.empty())
            svg += "Z ";
    }
    svg += "\"/>\n</svg>\n";
    return svg;
}

void writeOutline(const algo::Outline& outline, const QString& out)
{
    const QString suffix = out.section(QLatin1Char('.'), -1).toLower();
    QByteArray bytes;
    if (suffix == QLatin1String("svg")) {
        bytes = outlineSvg(outline);
    } else {
        // Encoded in memory, then written whole or not at all (issue 27).
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        QImageWriter writer(&buffer, "png");
        if (!writer.write(model::outlineImage(outline, QColor(255, 0, 170), 2.0)))
            throw model::IoError(out, writer.errorString());
    }
    model::writeWholeFile(out, bytes);
}

int runOutline(const Invocation& in)
{
    if (!in.isSet("drawing") || !in.isSet("out"))
        throw UsageError{Cli::tr("--drawing and --out are required")};
    const QString out = in.value("out");
    const QString suffix = out.section(QLatin1Char('.'), -1).toLower();
    if (suffix != QLatin1String("svg") && suffix != QLatin1String("png"))
        throw UsageError{Cli::tr("--out must name an .svg or .png file, not “%1”").arg(out)};

    const QString path = in.argument(0);
    auto doc = openProject(path);
    const model::Drawing& drawing = namedDrawing(*doc, path, in.value("drawing"));
    const model::ObjectId id = drawing.id;
    const model::DrawingOutline settings = outlineOptions(in, drawing.outline);
    model::Drawing trial = drawing;
    trial.outline = settings;
    const algo::Outline outline = model::drawingOutline(trial);
    if (const QString problem = model::outlineProblem(trial, outline); !problem.isEmpty())
        throw model::IoError(path, problem);
    writeOutline(outline, out);
    // The options are the drawing's settings from now on, as the Properties panel's are.
    if (settings != drawing.outline) {
        doc->drawings().setDrawingOutline(id, settings);
        doc->saveAs(path);
    }
    if (in.isSet("json")) {
        std::size_t points = 0;
        for (const auto& c : outline.contours)
            points += c.size();
        std::int64_t area = 0;
        for (std::uint8_t m : outline.mask)
            area += m;
        printJson({{"drawing", trial.name}, {"width", outline.width}, {"height", outline.height},
            {"threshold", outline.thresholdUsed}, {"used_alpha", outline.usedAlpha},
            {"closing_radius", settings.closingRadius}, {"contours", int(outline.contours.size())},
            {"points", double(points)}, {"area_pixels", double(area)}, {"out", out}});
    }
    return kExitOk;
}

int runFit(const Invocation& in)
{
    if (!in.isSet("key"))
        throw UsageError{Cli::tr("--key is required")};
    if (!in.isSet("camera") && !in.isSet("shape"))
        throw UsageError{Cli::tr("give --camera, --shape or both")};
    model::ShapeFitRequest request;
    request.regionFaceSet = in.value("region");
    request.pinFaceSet = in.value("pin");
    request.mirror = in.isSet("mirror");
    if (in.isSet("iterations")) {
        request.maxRounds = parseInt("iterations", in.value("iterations"));
        if (request.maxRounds < 1 || request.maxRounds > 100)
            throw UsageError{
                Cli::tr("--iterations takes a whole number from 1 to 100, not “%1”").arg(in.value("iterations"))};
    }
    if (in.isSet("strength")) {
        request.strength = parseNumber("strength", in.value("strength"));
        if (request.strength < 0.0 || request.strength > 1.0)
            throw UsageError{Cli::tr("--strength takes a number from 0 to 1, not “%1”").arg(in.value("strength"))};
    }

    const QString path = in.argument(0);
    auto doc = openProject(path);
    const model::KeyViewpoint* key = doc->data().keyByName(in.value("key"));
    if (!key)
        throw model::IoError(path, Cli::tr("has no key named “%1”").arg(in.value("key")));
    const model::ObjectId keyId = key->id;
    model::ObjectId drawingId = 0;
    if (in.isSet("drawing"))
        drawingId = namedDrawing(*doc, path, in.value("drawing")).id;
    try {
        drawingId = model::fitDrawing(doc->data(), *key, drawingId).id;
    } catch (const model::EditRefused& e) {
        throw model::IoError(path, e.message());
    }

    QElapsedTimer clock;
    clock.start();
    QJsonObject json{{"key", key->name}, {"drawing", doc->data().drawing(drawingId)->name}};
    json.insert("camera_before", model::cameraJson(key->camera));
    algo::FitMetrics before, after;
    bool haveBefore = false;
    if (in.isSet("camera")) {
        StderrProgress progress([](std::int64_t done, std::int64_t total) {
            return Cli::tr("fitting the camera: %1 of %2").arg(done).arg(total);
        });
        const model::CameraFit fit = model::fitCameraToDrawing(doc->data(), drawingId, keyId, &progress);
        if (!fit.ok)
            throw model::IoError(path, fit.error);
        doc->keys().applyFittedCamera(drawingId, keyId, fit.after);
        before = fit.metricsBefore;
        after = fit.metricsAfter;
        haveBefore = true;
        json.insert("camera_iterations", fit.iterations);
    }
    if (in.isSet("shape")) {
        StderrProgress progress([](std::int64_t done, std::int64_t total) {
            return Cli::tr("fitting the shape: round %1 of %2").arg(done).arg(total);
        });
        const model::ShapeFit fit = model::fitShapeToDrawing(doc->data(), keyId, drawingId, request, &progress);
        if (!fit.ok)
            throw model::IoError(path, fit.error);
        if (!fit.indices.empty())
            doc->keys().applyFittedShape(keyId, fit.frame, fit.indices, fit.displacements);
        if (!haveBefore)
            before = fit.metricsBefore;
        after = fit.metricsAfter;
        json.insert("rounds", fit.rounds);
        json.insert("moved_vertices", double(fit.indices.size()));
        json.insert("frame", fit.frame);
    }
    doc->saveAs(path);
    const double milliseconds = double(clock.nsecsElapsed()) / 1e6;

    json.insert("camera_after", model::cameraJson(doc->data().key(keyId)->camera));
    json.insert("iou_before", before.iou);
    json.insert("iou_after", after.iou);
    json.insert("chamfer_px_before", before.valid ? before.chamferPx : -1.0);
    json.insert("chamfer_px_after", after.valid ? after.chamferPx : -1.0);
    json.insert("milliseconds", milliseconds);
    if (in.isSet("json")) {
        printJson(json);
    } else {
        printOut(Cli::tr("silhouette IoU %1 -> %2, chamfer distance %3 -> %4 px (%5 ms)\n")
                     .arg(before.iou, 0, 'f', 3)
                     .arg(after.iou, 0, 'f', 3)
                     .arg(before.chamferPx, 0, 'f', 2)
                     .arg(after.chamferPx, 0, 'f', 2)
                     .arg(milliseconds, 0, 'f', 0));
    }
    return kExitOk;
}

} // namespace

std::vector<SubCommand> fitCommands()
{
    return {
        {"outline",
            {"celform outline P --drawing NAME [--threshold T|auto] [--closing PX] [--inner-lines on|off] "
             "[--json] --out FILE.svg|FILE.png"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Writes the outline Fit to Drawing reads from a drawing; the options become the drawing's "
                "outline settings."),
            {{"P", kProjectArgument}},
            {{"drawing", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "The drawing.")},
                {"threshold", "T",
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Ink where the luminance is below T (0 black to 1 white); auto: Otsu's threshold.")},
                {"closing", "PX",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Radius in pixels that closes gaps in open line art.")},
                {"inner-lines", "on|off",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Keep the holes inner lines enclose (default off).")},
                {"json", nullptr, kJsonOption},
                {"out", "FILE", QT_TRANSLATE_NOOP("celform::app::Cli", "The SVG or PNG file to write.")}},
            runOutline},
        {"fit",
            {"celform fit P --key NAME [--drawing NAME] [--camera] [--shape] [--region FACESET] [--pin FACESET] "
             "[--mirror] [--iterations N] [--strength S] [--json]"},
            QT_TRANSLATE_NOOP("celform::app::Cli",
                "Fits a key's camera (--camera) and shape (--shape) to its drawing's outline, and saves the "
                "project."),
            {{"P", kProjectArgument}},
            {{"key", "NAME", QT_TRANSLATE_NOOP("celform::app::Cli", "The key to fit.")},
                {"drawing", "NAME",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Which of the key's linked drawings (default: the first).")},
                {"camera", nullptr,
                    QT_TRANSLATE_NOOP("celform::app::Cli",
                        "Fit the camera: rotation, position and field of view (orthographic: height).")},
                {"shape", nullptr,
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Fit the key's shape at the drawing's frame (after the camera).")},
                {"region", "FACESET",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Only these painted faces may move (default: all).")},
                {"pin", "FACESET", QT_TRANSLATE_NOOP("celform::app::Cli", "The vertices of these faces stay put.")},
                {"mirror", nullptr,
                    QT_TRANSLATE_NOOP(
                        "celform::app::Cli", "Keep the shape symmetric across the project's mirror plane.")},
                {"iterations", "N",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Rounds of the shape fit at most (default 10).")},
                {"strength", "S",
                    QT_TRANSLATE_NOOP("celform::app::Cli", "Fraction of the fitted deformation applied (default 1).")},
                {"json", nullptr, kJsonOption}},
            runFit},
    };
}

} // namespace celform::app
