// Document.render() and Document.export(): `celform render` and `celform export` on the open
// document (app/cli/look.cpp runRender, app/cli/export.cpp runExport), with the same option
// checks and the model's renderFrames / exportProject. Without an output file, render() gives one
// frame as numpy arrays, rendered by the steps renderFrames takes for a frame (render_job.cpp,
// FrameWorker::render): the job resolved, the frame evaluated, subdivided, its shading offsets,
// renderShape, then the pass.
#include "cli_args.h"
#include "document.h"

#include "cli/options.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/data/shading_layers.h"
#include "celform/model/export/export.h"
#include "celform/model/render/frame_evaluator.h"
#include "celform/model/render/frame_schedule.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"
#include "celform/model/render/subdivided_surface.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QMutex>
#include <QThread>

namespace celform::python {
namespace {

using app::Cli;
using app::UsageError;

/// A vector handed to numpy without a copy: the array owns it.
template <typename T, typename Element = T>
py::array adopt(std::vector<T>&& values, std::vector<py::ssize_t> shape)
{
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    std::vector<py::ssize_t> strides(shape.size());
    py::ssize_t stride = sizeof(Element);
    for (std::size_t i = shape.size(); i-- > 0;) {
        strides[i] = stride;
        stride *= shape[i];
    }
    return py::array(py::dtype::of<Element>(), shape, strides, reinterpret_cast<const Element*>(owned->data()), owner);
}

algo::StereoOutput parseStereo(const QString& text)
{
    // look.cpp's parseStereo (local to it): the same words and message.
    const std::pair<const char*, algo::StereoOutput> modes[]
        = {{"off", algo::StereoOutput::Off}, {"anaglyph", algo::StereoOutput::Anaglyph},
            {"dubois", algo::StereoOutput::Dubois}, {"halfcolor", algo::StereoOutput::HalfColor},
            {"sbs", algo::StereoOutput::SideBySide}, {"tb", algo::StereoOutput::TopBottom}};
    return app::parseChoice(text, modes, Cli::tr("--stereo takes off, anaglyph, dubois, halfcolor, sbs or tb, not “%1”"));
}

/// The render options of `celform render` read into a job, with its checks (look.cpp, runRender
/// and readVectorLineOptions). toFile: an output is given (else one frame to arrays).
model::RenderJob renderJob(const PyDocument& d, const app::Invocation& in, bool toFile)
{
    if (in.isSet("frame") && in.isSet("frames"))
        throw UsageError{Cli::tr("give either --frame or --frames")};
    model::RenderJob job;
    app::readPictureOptions(in, job);
    if (in.isSet("frames")) {
        const app::FrameRange range = app::parseFrameRange("frames", in.value("frames"));
        job.firstFrame = range.first;
        job.lastFrame = range.last;
        job.step = range.step;
    }
    job.threads = QThread::idealThreadCount();
    if (in.isSet("threads")) {
        job.threads = app::parseInt("threads", in.value("threads"));
        if (job.threads < 1)
            throw UsageError{Cli::tr("--threads takes a whole number of at least 1, not “%1”").arg(in.value("threads"))};
    }
    job.skipExisting = in.isSet("skip-existing");
    job.stereo = in.isSet("stereo") ? parseStereo(in.value("stereo")) : algo::StereoOutput::Off;
    job.pass = in.value("pass");
    if (in.isSet("pass") && !model::renderPassNames().contains(job.pass))
        throw UsageError{
            Cli::tr("--pass takes one of %1, not “%2”").arg(model::renderPassNames().join(QStringLiteral(", ")), job.pass)};
    job.output = in.value("out");
    if (!toFile)
        return job;
    if (job.writesVectorLines()) {
        if (!in.isSet("pass"))
            job.pass = QStringLiteral("lines");
        if (job.pass != QLatin1String("lines"))
            throw UsageError{Cli::tr("an .svg output holds the lines pass; give --pass lines, not “%1”").arg(job.pass)};
        const QList<algo::StereoOutput> eyes = {algo::StereoOutput::Off, algo::StereoOutput::SideBySide,
            algo::StereoOutput::TopBottom, algo::StereoOutput::Anaglyph};
        if (!eyes.contains(job.stereo))
            throw UsageError{Cli::tr("an .svg output takes --stereo off, sbs, tb or anaglyph")};
    }
    job.svgTones = in.isSet("svg-tones");
    if (job.svgTones && !job.writesVectorLines())
        throw UsageError{Cli::tr("--svg-tones needs an .svg output")};
    job.strokesOutput = in.value("strokes");
    if (in.isSet("strokes")) {
        if (job.pass != QLatin1String("lines"))
            throw UsageError{Cli::tr("--strokes needs the lines pass (--pass lines)")};
        if (QFileInfo(job.strokesOutput).suffix().toLower() != QLatin1String("json"))
            throw UsageError{Cli::tr("--strokes must end in .json, not “%1”").arg(job.strokesOutput)};
        if (job.stereo != algo::StereoOutput::Off && !job.writesVectorLines())
            throw UsageError{Cli::tr("a stereo render writes its strokes beside an .svg output only")};
    }
    if (job.stereo != algo::StereoOutput::Off && in.isSet("pass") && job.pass != QLatin1String("beauty")
        && !job.writesVectorLines())
        throw UsageError{Cli::tr("a stereo render writes the beauty pass only")};
    if (!model::renderSuffixes().contains(QFileInfo(job.output).suffix().toLower()) && !job.writesVectorLines())
        throw UsageError{Cli::tr("--out must end in .png, .exr, .tif, .jpg or .svg, not “%1”").arg(job.output)};
    auto numbered = [&](const QString& pattern) {
        if (!in.isSet("frames") || pattern.isEmpty() || pattern.contains(QLatin1Char('#')))
            return pattern;
        const QFileInfo out(pattern);
        return out.dir().filePath(out.completeBaseName() + QStringLiteral("_####.") + out.suffix());
    };
    job.output = numbered(job.output);
    job.strokesOutput = numbered(job.strokesOutput);
    const QString size = QStringLiteral("%1x%2").arg(job.size.width()).arg(job.size.height());
    app::checkRenderMemory("size", size, job.bytesNeeded());
    job.threads = model::concurrentFrames(job, model::availableRenderMemory());
    return job;
}

/// The frames written and skipped, as `render --json` lists them.
struct FrameList : model::RenderFrameListener {
    QMutex mutex;
    QJsonArray written, skipped;
    void frameDone(int frame, const QString& file, bool skip) override
    {
        const QMutexLocker lock(&mutex);
        (skip ? skipped : written).append(QJsonObject{{"frame", frame}, {"file", file}});
    }
};

QJsonArray byFrame(const QJsonArray& frames)
{
    std::vector<QJsonValue> sorted(frames.begin(), frames.end());
    std::sort(sorted.begin(), sorted.end(),
        [](const QJsonValue& a, const QJsonValue& b) { return a["frame"].toInt() < b["frame"].toInt(); });
    QJsonArray out;
    for (const QJsonValue& v : sorted)
        out.append(v);
    return out;
}

py::object renderToFiles(PyDocument& d, const model::RenderJob& job, const py::object& progressCallback)
{
    CallbackProgress progress(progressCallback);
    const PyDocument::Job busy(d);
    FrameList listener;
    const model::ProjectData& data = d->data();
    const QString source = d.source();
    const std::optional<model::RenderFrameError> failed = runJob(progress, [&]() -> std::optional<model::RenderFrameError> {
        try {
            model::renderFrames(data, source, job, progress.get(), &listener);
        } catch (const model::RenderFrameError& e) {
            return e;
        }
        return std::nullopt;
    });
    if (failed)
        // As the command line prints it: "frame F: file: problem".
        throwIo(Cli::tr("frame %1: %2").arg(failed->frame()).arg(failed->message()));
    return toPython(QJsonObject{{"first", job.firstFrame}, {"last", job.lastFrame}, {"step", job.step},
        {"count", job.frameCount()}, {"size", QJsonArray{job.size.width(), job.size.height()}},
        {"threads", job.threads}, {"written", byFrame(listener.written)}, {"skipped", byFrame(listener.skipped)},
        {"cancelled", progress.cancelled()}});
}

/// One frame's passes as FrameWorker::render makes them (render_job.cpp).
algo::RenderPasses renderPasses(PyDocument& d, const model::RenderJob& job)
{
    const PyDocument::Job busy(d);
    const model::ProjectData& data = d->data();
    const model::ResolvedRenderJob resolved = model::resolveRenderJob(data, d.source(), job);
    py::gil_scoped_release release;
    model::FrameEvaluator evaluator;
    evaluator.prepare(data);
    const int f = job.firstFrame;
    const model::Camera camera = model::renderJobCamera(data, resolved.look, job, f);
    evaluator.evaluate(data, f, camera.eye);
    const model::SubdividedSurface* surface = resolved.surface.get();
    algo::Shape shape;
    if (surface)
        surface->apply(evaluator.shape(), shape.positions);
    else
        shape.positions = evaluator.shape();
    shape.touch();
    std::vector<float> offsets;
    model::effectiveShadingOffsets(data, evaluator.blender(), evaluator.direction(), f, offsets);
    if (surface) {
        std::vector<float> subdivided;
        surface->apply(offsets, subdivided);
        std::swap(offsets, subdivided);
    }
    const model::ProjectData& shown = surface ? surface->display : data;
    algo::RenderCache cache;
    algo::RenderPasses passes;
    model::renderShape(shown, resolved.look, shape.positions, f, camera, job.size.width(), job.size.height(),
        job.stereo, cache, passes, shape.generation, &offsets);
    return passes;
}

/// An image as an array: its floats, or the 8-bit values a PNG of it holds (sRGB-encoded colour,
/// as renderFrames encodes them).
py::array arrayOf(algo::ImageRGBA&& image, bool srgb8)
{
    if (!srgb8)
        return adopt(std::move(image.pixels), {py::ssize_t(image.height), py::ssize_t(image.width), 4});
    static const std::vector<std::string> rgba = {"R", "G", "B", "A"};
    model::EncodedFrame encoded;
    model::encodeChannels(QStringLiteral("frame.png"), image.width, image.height, rgba, image.pixels.data(),
        image.pixels.size(), true, encoded);
    return adopt(std::move(encoded.bytes), {py::ssize_t(encoded.height), py::ssize_t(encoded.width), 4});
}

py::object renderToArrays(PyDocument& d, const model::RenderJob& job, bool allPasses, bool srgb8)
{
    if (job.isSequence())
        throw UsageError{Cli::tr("a render to an array takes one frame (frame=F), not --frames")};
    const QString pass = job.pass.isEmpty() ? QStringLiteral("beauty") : job.pass;
    if (const auto picture = model::analysisPictureFromName(pass); picture && !allPasses) {
        // The depth analysis's pictures (segments, curvature, depth error), as `celform analyze`
        // analyses the job's view.
        model::FrameAnalysis analysed;
        {
            const PyDocument::Job busy(d);
            py::gil_scoped_release release;
            analysed = model::analyseProject(d->data(), d.source(), job, model::AnalysisSettings{});
        }
        algo::ImageRGBA image = model::analysisImage(analysed.analysis, *picture, !srgb8);
        return arrayOf(std::move(image), srgb8);
    }
    algo::RenderPasses passes = renderPasses(d, job);
    const py::ssize_t w = job.size.width(), h = job.size.height();
    if (allPasses) {
        py::dict out;
        out["lines"] = adopt(std::move(passes.lines), {h, w});
        out["tone"] = adopt(std::move(passes.tone), {h, w});
        out["highlights"] = adopt(std::move(passes.highlights), {h, w});
        out["depth"] = adopt(std::move(passes.depth), {h, w});
        out["normal"] = adopt<Eigen::Vector3f, float>(std::move(passes.normal), {h, w, 3});
        out["id"] = adopt(std::move(passes.id), {h, w});
        out["beauty"] = adopt(std::move(passes.beauty.pixels), {py::ssize_t(passes.beauty.height), py::ssize_t(passes.beauty.width), 4});
        return std::move(out);
    }
    algo::ImageRGBA image;
    if (pass == QLatin1String("beauty"))
        image = std::move(passes.beauty);
    else
        model::passImage(passes, pass, !srgb8, image);
    return arrayOf(std::move(image), srgb8);
}

py::object render(PyDocument& d, const py::object& out, const py::object& progress, bool passes, bool srgb8,
    py::kwargs kwargs)
{
    if (!out.is_none())
        kwargs["out"] = out;
    const CliOptions o(QStringLiteral("render"), kwargs);
    const model::RenderJob job = renderJob(d, o.in(), !out.is_none());
    if (!out.is_none())
        return renderToFiles(d, job, progress);
    return renderToArrays(d, job, passes, srgb8);
}

/// `celform export` (export.cpp, runExport) on the document.
py::object exportAnimation(PyDocument& d, const py::object& format, const py::object& out, const py::object& progressCallback,
    py::kwargs kwargs)
{
    kwargs["format"] = format;
    kwargs["out"] = out;
    const CliOptions o(QStringLiteral("export"), kwargs);
    const app::Invocation& in = o.in();
    const auto fmt = model::exportFormatFromName(in.value("format"));
    if (!fmt)
        throw UsageError{Cli::tr("--format must be gltf, glb, pc2, obj-seq or usda, not “%1”").arg(in.value("format"))};
    model::ExportJob job;
    job.format = *fmt;
    job.output = in.value("out");
    if (job.output.isEmpty())
        throw UsageError{Cli::tr("--out needs a file name")};
    const QString suffix = QFileInfo(job.output).suffix().toLower();
    const QString wanted = *fmt == model::ExportFormat::ObjSequence ? QStringLiteral("obj") : model::exportFormatName(*fmt);
    if (suffix != wanted)
        throw UsageError{Cli::tr("--out must end in .%1 for --format %2, not “%3”")
                             .arg(wanted, model::exportFormatName(*fmt), job.output)};
    std::optional<app::FrameRange> frames;
    if (in.isSet("frames")) {
        frames = app::parseFrameRange("frames", in.value("frames"));
        if (frames->step != 1)
            throw UsageError{Cli::tr("--frames takes A-B for an export, without a step: “%1”").arg(in.value("frames"))};
    }
    if (in.isSet("subdivision"))
        job.subdivision = app::parseSubdivision("subdivision", in.value("subdivision"));
    if (job.subdivision > 0 && (*fmt == model::ExportFormat::Gltf || *fmt == model::ExportFormat::Glb))
        throw UsageError{Cli::tr("--subdivision applies to pc2, obj-seq and usda exports; glTF keeps the base "
                                 "model for its morph targets")};
    job.blendShapes = in.isSet("blend-shapes");
    if (job.blendShapes && *fmt != model::ExportFormat::Usda)
        throw UsageError{Cli::tr("--blend-shapes applies to usda exports (glTF always holds the keys as morph "
                                 "targets)")};
    if (job.blendShapes && job.subdivision > 0)
        throw UsageError{Cli::tr("--blend-shapes holds the keys on the base model and takes no --subdivision")};
    const model::ProjectData& data = d->data();
    if (!data.baseMesh)
        throw model::IoError(d.source(), Cli::tr("has no base model"));
    job.firstFrame = frames ? frames->first : data.time.firstFrame;
    job.lastFrame = frames ? frames->last : data.time.lastFrame;
    CallbackProgress progress(progressCallback);
    const PyDocument::Job busy(d);
    const QString source = d.source();
    const model::ExportResult result
        = runJob(progress, [&] { return model::exportProject(data, source, job, progress.get()); });
    QJsonArray files;
    for (const QString& f : result.files)
        files.append(f);
    return toPython(QJsonObject{{"format", model::exportFormatName(job.format)},
        {"frame_range", QJsonArray{job.firstFrame, job.lastFrame}}, {"frames", result.frames}, {"files", files},
        {"warnings", QJsonArray::fromStringList(result.warnings)}, {"cancelled", result.cancelled}});
}

} // namespace

void bindRender(py::module_& m, py::class_<PyDocument>& document)
{
    (void)m;
    document.def("render", &render, py::kw_only(), py::arg("out") = py::none(), py::arg("progress") = py::none(),
        py::arg("passes") = false, py::arg("srgb8") = false,
        R"(`celform render` on the document.

With out=FILE (or a pattern with #), renders the frames to files as the command line does and returns
what `render --json` prints (written, skipped) with cancelled. Without out, renders one frame and returns
it as a numpy array: H x W x 4 float32 linear RGBA (the pass asked for, raw values as in an EXR), or with
srgb8=True the H x W x 4 uint8 values a PNG holds; passes=True returns every pass in a dict. Keywords: the
options of `celform render` (view or eye/target/up, frame, frames, size, style, lines, ridge_threshold,
light, subdivision, stereo, pass_, svg_tones, strokes, threads, skip_existing). progress(done, total, label)
is called as frames finish; returning False stops the render.)");
    document.def("export", &exportAnimation, py::arg("format"), py::arg("out"), py::kw_only(),
        py::arg("progress") = py::none(),
        "`celform export`: gltf, glb, pc2, obj-seq or usda; keywords frames=(A, B), subdivision, blend_shapes. "
        "Returns what `export --json` prints, with cancelled.");
}

} // namespace celform::python
