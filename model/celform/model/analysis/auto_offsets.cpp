// Automatic per-segment shading offsets (auto_offsets.h; paper 3, section 4.3).
#include "celform/model/analysis/auto_offsets.h"

#include "celform/model/data/blend_evaluator.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("celform::model::Document", text);
}

QString targetName(const ProjectData& data, const ShadingTarget& target)
{
    if (target.isBase())
        return tr("base");
    const KeyViewpoint* key = data.key(target.key);
    return key ? key->name : QString();
}

AutoOffsetsResult cancelledResult(const ShadingTarget& target)
{
    AutoOffsetsResult result;
    result.target = target;
    result.cancelled = true;
    return result;
}

} // namespace

AutoOffsetsResult solveAutoOffsets(const ProjectData& data, const AutoOffsetsRequest& request, algo::Progress* progress)
{
    QElapsedTimer timer;
    timer.start();
    const ShadingTarget& target = request.target;
    if (!data.baseMesh)
        throw EditRefused(tr("Shading offsets need a base model."));
    if (!target.isBase() && !data.key(target.key))
        throw EditRefused(tr("There is no key to hold the automatic shading offsets."));
    if (!(request.aggressiveness >= 0.f && request.aggressiveness <= 1.f))
        throw EditRefused(tr("The aggressiveness must be between 0 and 1."));
    if (!(request.percentile >= 0.f && request.percentile <= 1.f))
        throw EditRefused(tr("The percentile must be between 0 and 1."));
    if (request.bleed < 0 || request.bleed > kMaxOffsetRounds)
        throw EditRefused(tr("Bleeding takes 0 to %1 rounds.").arg(kMaxOffsetRounds));
    if (request.width < 16 || request.height < 16 || request.width > 8192 || request.height > 8192)
        throw EditRefused(tr("The analysis size must be between 16 and 8192 pixels a side."));
    if (!request.camera.isValid())
        throw EditRefused(tr("The analysis needs a valid camera (eye, target and up must differ)."));
    BlendEvaluator blend;
    blend.update(data);
    const int frame = target.frame;
    const Eigen::Vector3d direction = BlendEvaluator::viewDirection(data, request.camera.eye, frame);
    // The target's weight in this view: 1 for the base, the key's blend weight for a key layer.
    double weight = 1.0;
    if (!target.isBase()) {
        weight = 0.0;
        for (const KeyShare& share : blend.weights(data, direction).shares)
            if (share.key == target.key)
                weight = share.weight;
        if (weight < 1e-3)
            throw EditRefused(tr("The key “%1” plays no part in this view: look from nearer its direction.")
                                  .arg(targetName(data, target)));
    }

    algo::Shape shape;
    blend.shape(data, direction, frame, shape.positions);
    shape.touch(); // one generation: the three analyses below share the curvature
    const algo::TriMesh& mesh = *data.baseMesh;
    const std::size_t n = std::size_t(mesh.vertexCount());
    std::vector<float> effective;
    effectiveShadingOffsets(data, blend, direction, frame, effective);
    if (effective.empty())
        effective.assign(n, 0.f);
    const std::vector<float> old = targetShadingOffsets(data, target);
    // What the target does not hold: the solve adds the target's part to it.
    std::vector<float> others(n);
    std::vector<float> field(n);
    for (std::size_t v = 0; v < n; ++v) {
        field[v] = float(weight) * old[v];
        others[v] = effective[v] - field[v];
    }

    AutoOffsetsResult result;
    algo::report(progress, 0, 3);
    DepthAnalyser analyser;
    FrameAnalysis analysed;
    analyser.analyse(data, data.look, shape.positions, shape.generation, frame, request.camera, request.width,
        request.height, request.analysis, analysed, &effective);
    result.before = analysed.analysis.stats;
    result.mseBefore = analysed.analysis.meanSquaredError;
    if (algo::cancelRequested(progress))
        return cancelledResult(target);
    algo::report(progress, 1, 3);
    // The picture again without the target's part: its lambert is N.L + the other layers.
    analyser.analyse(data, data.look, shape.positions, shape.generation, frame, request.camera, request.width,
        request.height, request.analysis, analysed, &others);

    const algo::GBuffer& g = analyser.gbuffer();
    const algo::VertexNeighbours neighbours = algo::buildVertexNeighbours(mesh.faces, std::int32_t(n));
    algo::SegmentOffsetInput input;
    input.width = analysed.analysis.width;
    input.height = analysed.analysis.height;
    input.faceId = g.faceId.data();
    input.barycentric = g.barycentric.data();
    input.baseline = analysed.analysis.lambert.data();
    input.labels = analysed.analysis.segments.labels.data();
    input.segmentCount = std::int32_t(analysed.analysis.stats.size());
    input.faces = &mesh.faces;
    input.neighbours = &neighbours;
    // Thesis 4.3 improves "segments that did not get a desirable bright/dark ratio from the solved
    // light position": by default only those outside the window with the offsets now in effect.
    std::vector<std::uint8_t> solve;
    if (request.segments == OffsetSegments::Outside) {
        // The segments follow curvature and depth, not the shading: both analyses have the same.
        solve.assign(analysed.analysis.stats.size(), 1);
        for (std::size_t s = 0; s < solve.size() && s < result.before.size(); ++s)
            solve[s] = result.before[s].inWindow ? 0 : 1;
        input.solve = solve.data();
    }
    algo::SegmentOffsetSettings settings;
    settings.threshold = data.look.toon.thresholds.empty() ? 0.f : data.look.toon.thresholds.front();
    settings.percentile = request.percentile;
    settings.aggressiveness = request.aggressiveness;
    settings.bleedRounds = request.bleed;
    algo::SegmentOffsetScratch scratch;
    if (!algo::solveSegmentOffsets(input, settings, field, scratch, &result.report))
        throw EditRefused(tr("The automatic shading offsets could not be solved for this picture."));
    // A key layer holds its share divided by the key's weight here; weights reach down to 1e-3, so
    // the quotient is clamped to the solve's own bound (the field then holds what is stored).
    std::vector<float> values(n);
    for (std::size_t v = 0; v < n; ++v) {
        if (target.isBase())
            values[v] = field[v];
        else {
            values[v] = std::clamp(float(double(field[v]) / weight), -settings.limit, settings.limit);
            field[v] = float(weight * double(values[v]));
        }
    }
    const QString problem = shadingOffsetsProblem(values, std::int64_t(n));
    if (!problem.isEmpty())
        throw EditRefused(tr("Shading offsets refused: %1.").arg(problem));
    if (algo::cancelRequested(progress))
        return cancelledResult(target);
    algo::report(progress, 2, 3);

    // The picture with the new values in effect: the other layers plus the target's part.
    for (std::size_t v = 0; v < n; ++v)
        effective[v] = others[v] + field[v];
    analyser.analyse(data, data.look, shape.positions, shape.generation, frame, request.camera, request.width,
        request.height, request.analysis, analysed, &effective);
    result.after = analysed.analysis.stats;
    result.mseAfter = analysed.analysis.meanSquaredError;
    result.target = target;
    result.values = std::move(values);
    result.milliseconds = double(timer.nsecsElapsed()) / 1e6;
    algo::report(progress, 3, 3);
    return result;
}

} // namespace celform::model
