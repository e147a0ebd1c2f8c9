// Document.render() and Document.export(): `celform render` and `celform export` on the open
// document (app/cli/look.cpp runRender, app/cli/export.cpp runExport), with the command line's
// own readers (readRenderJob, readRenderOutputs, readExportJob in cli/options.h) and the model's
// renderFrames / exportProject. Without an output file, render() gives one frame as numpy arrays,
// rendered by renderJobFrame (render_job.h) as renderFrames renders a frame, then the pass.
#include "cli_args.h"
#include "document.h"

#include "cli/options.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/export/export.h"
#include "celform/model/render/frame_schedule.h"
#include "celform/model/render/render_job.h"
#include "celform/model/render/render_output.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <QJsonArray>
#include <QMutex>

namespace celform::python {
namespace {

using app::Cli;
using app::UsageError;

/// A vector handed to numpy without a copy: the array owns it.
template <typename T, typename Element = T> py::array adopt(std::vector<T>&& values, std::vector<py::ssize_t> shape)
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

/// The render options of `celform render` read into a job, with its checks (the command line's
/// readers, look.cpp). toFile: an output is given (else one frame to arrays).
model::RenderJob renderJob(const app::Invocation& in, bool toFile)
{
    model::RenderJob job = app::readRenderJob(in);
    job.output = in.value("out");
    if (!toFile)
        return job;
    app::readRenderOutputs(in, job);
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

py::object renderToFiles(PyDocument& d, const model::RenderJob& job, const py::object& progressCallback)
{
    CallbackProgress progress(progressCallback);
    const PyDocument::Job busy(d);
    FrameList listener;
    const model::ProjectData& data = d->data();
    const QString source = d.source();
    const std::optional<model::RenderFrameError> failed
        = runJob(progress, [&]() -> std::optional<model::RenderFrameError> {
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
    QJsonObject report = app::renderJobJson(job, listener.written, listener.skipped);
    report.insert("cancelled", progress.cancelled());
    return toPython(report);
}

/// One frame's passes as renderFrames renders them (render_job.h, renderJobFrame).
algo::RenderPasses renderPasses(PyDocument& d, const model::RenderJob& job)
{
    const PyDocument::Job busy(d);
    const model::ProjectData& data = d->data();
    const model::ResolvedRenderJob resolved = model::resolveRenderJob(data, d.source(), job);
    py::gil_scoped_release release;
    algo::RenderPasses passes;
    model::renderJobFrame(data, job, resolved, job.firstFrame, passes);
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
        out["beauty"] = adopt(
            std::move(passes.beauty.pixels), {py::ssize_t(passes.beauty.height), py::ssize_t(passes.beauty.width), 4});
        return std::move(out);
    }
    algo::ImageRGBA image;
    if (pass == QLatin1String("beauty"))
        image = std::move(passes.beauty);
    else
        model::passImage(passes, pass, !srgb8, image);
    return arrayOf(std::move(image), srgb8);
}

py::object render(
    PyDocument& d, const py::object& out, const py::object& progress, bool passes, bool srgb8, py::kwargs kwargs)
{
    if (!out.is_none())
        kwargs["out"] = out;
    const CliOptions o(QStringLiteral("render"), kwargs);
    const model::RenderJob job = renderJob(o.in(), !out.is_none());
    if (!out.is_none())
        return renderToFiles(d, job, progress);
    return renderToArrays(d, job, passes, srgb8);
}

/// `celform export` (export.cpp, runExport) on the document.
py::object exportAnimation(PyDocument& d, const py::object& format, const py::object& out,
    const py::object& progressCallback, py::kwargs kwargs)
{
    kwargs["format"] = format;
    kwargs["out"] = out;
    const CliOptions o(QStringLiteral("export"), kwargs);
    const app::Invocation& in = o.in();
    std::optional<app::FrameRange> frames;
    model::ExportJob job = app::readExportJob(in, frames);
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
