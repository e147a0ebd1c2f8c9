// Running the depth analysis on a project (depth_analysis.h).
#include "celform/model/analysis/depth_analysis.h"

#include "celform/algorithms/tri_mesh.h"
#include "celform/model/data/io_error.h"
#include "celform/model/render/render_output.h"
#include "celform/model/render/ridge_depth_prepass.h"
#include "celform/model/render/subdivided_surface.h"
#include "celform/model/data/shading_layers.h"
#include "celform/model/data/blend_evaluator.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace celform::model {

const algo::Curvatures& DepthAnalyser::curvatures(
    const algo::TriMesh& mesh, const algo::Positions& shape, std::uint64_t generation)
{
    if (generation == 0 || generation != m_generation || &mesh != m_mesh
        || std::size_t(shape.rows()) != m_curvatures.gaussian.size()) {
        // Max's normals, computed inside: the area-weighted ones put curvature several percent off.
        algo::computeCurvatures(shape, mesh.faces, m_curvatures);
        // The pictures' scale: the |K| below which 98% of the surface's area lies. Weighting by
        // area keeps small, finely meshed, sharply curved parts (a trunk's tip) from setting it.
        m_byMagnitude.resize(m_curvatures.gaussian.size());
        double total = 0.0;
        for (std::size_t v = 0; v < m_byMagnitude.size(); ++v) {
            const float k = m_curvatures.gaussian[v];
            const float area = v < m_curvatures.pointArea.size() ? m_curvatures.pointArea[v] : 0.f;
            m_byMagnitude[v] = {std::isfinite(k) ? std::abs(k) : 0.f, std::isfinite(area) ? area : 0.f};
            total += m_byMagnitude[v].second;
        }
        std::sort(m_byMagnitude.begin(), m_byMagnitude.end());
        m_curvatureScale = 0.f;
        double below = 0.0;
        for (const auto& [magnitude, area] : m_byMagnitude) {
            below += area;
            m_curvatureScale = magnitude;
            if (below >= 0.98 * total)
                break;
        }
        m_mesh = &mesh;
        m_generation = generation;
    }
    return m_curvatures;
}

void DepthAnalyser::analyse(const ProjectData& data, const Look& look, const algo::Positions& shape,
    std::uint64_t generation, int frame, const Camera& camera, int width, int height, const AnalysisSettings& settings,
    FrameAnalysis& out, const std::vector<float>* shadingOffsets, algo::Progress* progress)
{
    QElapsedTimer timer;
    timer.start();
    out.cancelled = false;
    // Asked between the steps: a step once begun runs to its end.
    const auto stopAfter = [&](int step) {
        algo::report(progress, step, 3);
        out.cancelled = algo::cancelRequested(progress);
        if (out.cancelled)
            out.milliseconds = double(timer.nsecsElapsed()) / 1e6;
        return out.cancelled;
    };
    const algo::TriMesh& mesh = *data.baseMesh;
    const bool cached = generation != 0 && generation == m_generation && &mesh == m_mesh
        && std::size_t(shape.rows()) == m_curvatures.gaussian.size();
    const algo::Curvatures& curvature = curvatures(mesh, shape, generation);
    out.curvatureMilliseconds = cached ? 0.0 : double(timer.nsecsElapsed()) / 1e6;
    if (stopAfter(1))
        return;

    // The centre eye's picture with its G-buffer (thesis 4.5.2: "the camera position when
    // rendering to this G-buffer is in the middle of the two eyes").
    algo::RenderLook renderLook = renderLookFor(data, look, shadingOffsets, frame);
    renderLook.highlights = renderHighlightsFor(data, look, shape, frame, &m_cache, generation);
    const algo::RasterCamera centre = rasterCamera(camera, width, height);
    // With a depth-driven ridge threshold (paper 3, 4.4), a first picture's error sets it.
    prepareDepthAdaptedRidges(mesh, shape, centre, renderLook, m_cache, threadRidgeDepthPrepass());
    algo::renderFrame(shape, mesh, centre, renderLook, m_cache, out.passes, nullptr, &m_gbuffer);
    if (stopAfter(2))
        return;

    algo::DepthAnalysisSettings& s = m_settings;
    s = algo::DepthAnalysisSettings{};
    const Eigen::AlignedBox3d box = algo::boundingBox(shape);
    const double diagonal = box.isEmpty() ? 1.0 : box.diagonal().norm();
    out.depthThreshold = settings.depthThreshold * diagonal;
    s.depthThreshold = float(out.depthThreshold);
    s.minSegmentPixels = settings.minSegmentPixels;
    s.window = settings.window;
    // The bright/dark boundary is the ramp's first threshold: the shadow line (DESIGN.md: "N.L
    // plus the vertex's offset above the toon threshold").
    s.toonThreshold = look.toon.thresholds.empty() ? 0.f : look.toon.thresholds.front();
    s.pointLight = renderLook.pointLight;
    s.light = renderLook.light;
    s.shadingOffsets = renderLook.shadingOffsets;
    // The artist's say (issue 26): focal points and the segment brush's overrides, per face of
    // data's base model (a subdivided surface's stand-in carries them onto its faces).
    const std::int64_t faceCount = mesh.faceCount();
    if (std::int64_t(data.faceImportance.size()) == faceCount)
        s.faceImportance = &data.faceImportance;
    if (std::int64_t(data.segmentOverrides.size()) == faceCount)
        s.segmentOverrides = &data.segmentOverrides;
    algo::analyseDepth(
        m_gbuffer, out.passes.normal, out.passes.beauty, mesh.faces, curvature.gaussian, s, out.analysis);
    out.analysis.curvatureScale = m_curvatureScale;
    out.milliseconds = double(timer.nsecsElapsed()) / 1e6;
    algo::report(progress, 3, 3);
}

AnalysisView resolveAnalysisView(const ProjectData& data, const QString& source, const RenderJob& job)
{
    if (!data.baseMesh)
        throw IoError(source, QCoreApplication::translate("celform::model::RenderJob", "has no base model"));
    AnalysisView view;
    view.look = renderJobLook(data, job);
    view.camera = renderJobCamera(data, view.look, job, job.firstFrame);
    BlendEvaluator blender;
    QString error;
    if (!blender.update(data, &error))
        throw IoError(source, error);
    view.direction = blender.viewDirection(data, view.camera.eye, job.firstFrame);
    view.blend = blender.weights(data, view.direction);
    blender.shape(data, view.direction, job.firstFrame, view.shape);
    effectiveShadingOffsets(data, blender, view.direction, job.firstFrame, view.offsets);
    return view;
}

void analyseProjectFrames(const ProjectData& data, const QString& source, const RenderJob& job,
    const AnalysisSettings& settings,
    const std::function<void(int frame, const AnalysisView& view, const FrameAnalysis& analysis)>& visit,
    algo::Progress* progress)
{
    DepthAnalyser analyser;
    FrameAnalysis out;
    RenderJob one = job;
    algo::Positions last;
    // A generation of this sequence's own: kept while the shape stays the same (a still base seen
    // from the keys' side), so the curvature is computed once; a new one when it moves.
    static std::atomic<std::uint64_t> next{std::uint64_t(3) << 61};
    std::uint64_t generation = 0;
    const int count = job.lastFrame < job.firstFrame ? 0 : (job.lastFrame - job.firstFrame) / std::max(1, job.step) + 1;
    int done = 0;
    for (int frame = job.firstFrame; frame <= job.lastFrame; frame += std::max(1, job.step)) {
        one.firstFrame = one.lastFrame = frame;
        const AnalysisView view = resolveAnalysisView(data, source, one);
        if (generation == 0 || view.shape.rows() != last.rows() || view.shape != last) {
            generation = next++;
            last = view.shape;
        }
        analyser.analyse(data, view.look, view.shape, generation, frame, view.camera, job.size.width(),
            job.size.height(), settings, out, &view.offsets);
        visit(frame, view, out);
        algo::report(progress, std::int64_t(done) + 1, std::int64_t(count));
        if (algo::cancelRequested(progress))
            return;
        ++done;
    }
}

FrameAnalysis analyseProject(const ProjectData& data, const QString& source, const RenderJob& job,
    const AnalysisSettings& settings, std::vector<std::int32_t>* baseFaces)
{
    const AnalysisView view = resolveAnalysisView(data, source, job);
    DepthAnalyser analyser;
    FrameAnalysis out;
    // The analysis sees the render level's surface (issue 25).
    if (const QString problem
        = subdivisionMemoryProblem(*data.baseMesh, view.look.subdivision.level, job.bytesNeeded());
        !problem.isEmpty())
        throw IoError(source, problem);
    if (const auto surface = subdividedSurface(data, view.look.subdivision.level)) {
        algo::Positions shape;
        std::vector<float> offsets;
        surface->apply(view.shape, shape);
        surface->apply(view.offsets, offsets);
        analyser.analyse(surface->display, view.look, shape, 0, job.firstFrame, view.camera, job.size.width(),
            job.size.height(), settings, out, &offsets);
        if (baseFaces) {
            *baseFaces = analyser.gbuffer().faceId;
            const std::vector<std::int32_t>& parent = surface->stencil->parentFace;
            for (std::int32_t& f : *baseFaces)
                f = f >= 0 && std::size_t(f) < parent.size() ? parent[std::size_t(f)] : -1;
        }
        return out;
    }
    analyser.analyse(data, view.look, view.shape, 0, job.firstFrame, view.camera, job.size.width(), job.size.height(),
        settings, out, &view.offsets);
    if (baseFaces)
        *baseFaces = analyser.gbuffer().faceId;
    return out;
}

} // namespace celform::model
