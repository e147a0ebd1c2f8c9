// Shading offsets (paper 3, section 4.3, eq. 4.3): setting, clearing, smoothing, painting and the
// automatic per-segment offsets of a layer (the base, or a key's at a frame).
#include "celform/model/document/shading_edits.h"

#include "celform/algorithms/sorted_merge.h"
#include "celform/model/document/document_commands.h"
#include "celform/model/document/shading_offsets_command.h"
#include "celform/model/data/io_error.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

/// The change from a layer's current state to values (#V): only the vertices that differ when
/// the layer exists, every vertex when it does not (the command then makes it whole).
ShadingOffsetsCommand::Change changeTo(
    const ProjectData& data, const ShadingTarget& target, const std::vector<float>& values)
{
    ShadingOffsetsCommand::Change change;
    const std::vector<float>* old = shadingLayer(data, target);
    change.existedBefore = old != nullptr;
    change.existsAfter = true;
    for (std::size_t v = 0; v < values.size(); ++v) {
        const float was = old && v < old->size() ? (*old)[v] : 0.f;
        if (old && was == values[v])
            continue;
        change.indices.push_back(std::uint32_t(v));
        change.before.push_back(was);
        change.after.push_back(values[v]);
    }
    return change;
}

/// The target's frame for a key, the analysed frame for the base.
QString targetName(const ProjectData& data, const ShadingTarget& target)
{
    if (target.isBase())
        return QCoreApplication::translate("celform::model::Document", "base");
    const KeyViewpoint* key = data.key(target.key);
    return key ? key->name : QString();
}

} // namespace

// --- set, clear, smooth -----------------------------------------------------------------------------

void ShadingEdits::setShadingOffsets(
    const ShadingTarget& target, const std::vector<float>& values, const QString& undoText)
{
    if (!data().baseMesh)
        throw EditRefused(tr("Shading offsets need a base model."));
    if (!target.isBase() && !data().key(target.key))
        throw EditRefused(tr("There is no key to hold these shading offsets."));
    const QString problem = shadingOffsetsProblem(values, data().baseMesh->vertexCount());
    if (!problem.isEmpty())
        throw EditRefused(tr("Shading offsets refused: %1.").arg(problem));
    ShadingOffsetsCommand::Change change = changeTo(data(), target, values);
    if (change.indices.empty() && change.existedBefore)
        return; // nothing changes
    push(new ShadingOffsetsCommand(m_doc,
        undoText.isEmpty() ? tr("Set Shading Offsets (%1)").arg(targetName(data(), target)) : undoText, target,
        std::move(change), {}));
}

void ShadingEdits::clearShadingOffsets(const ShadingTarget& target, bool allFrames)
{
    if (!target.isBase() && !data().key(target.key))
        throw EditRefused(tr("There is no key to clear shading offsets from."));
    std::vector<ShadingTarget> targets;
    if (!target.isBase() && allFrames) {
        for (const auto& entry : data().key(target.key)->shadingOffsetsByFrame)
            targets.push_back({target.key, entry.first});
    } else if (shadingLayer(data(), target)) {
        targets.push_back(target);
    }
    if (targets.empty())
        return;
    auto* step = new CompositeCommand(m_doc, tr("Clear Shading Offsets (%1)").arg(targetName(data(), target)));
    for (const ShadingTarget& t : targets) {
        const std::vector<float>& old = *shadingLayer(data(), t);
        ShadingOffsetsCommand::Change change;
        change.existedBefore = true;
        change.existsAfter = false;
        for (std::size_t v = 0; v < old.size(); ++v) {
            change.indices.push_back(std::uint32_t(v));
            change.before.push_back(old[v]);
            change.after.push_back(0.f);
        }
        new ShadingOffsetsCommand(m_doc, {}, t, std::move(change), {}, step);
    }
    push(step);
}

void ShadingEdits::smoothShadingOffsets(const ShadingTarget& target, int rounds)
{
    if (!data().baseMesh)
        throw EditRefused(tr("Shading offsets need a base model."));
    if (!target.isBase() && !data().key(target.key))
        throw EditRefused(tr("There is no key whose shading offsets to smooth."));
    if (rounds < 1 || rounds > kMaxOffsetRounds)
        throw EditRefused(tr("Smoothing takes 1 to %1 rounds, not %2.").arg(kMaxOffsetRounds).arg(rounds));
    std::vector<float> values = targetShadingOffsets(data(), target);
    const algo::TriMesh& mesh = *data().baseMesh;
    const algo::VertexNeighbours neighbours = algo::buildVertexNeighbours(mesh.faces, std::int32_t(mesh.vertexCount()));
    std::vector<float> scratch;
    algo::smoothVertexValues(neighbours, rounds, nullptr, values, scratch);
    ShadingOffsetsCommand::Change change = changeTo(data(), target, values);
    if (change.indices.empty() && change.existedBefore)
        return;
    push(new ShadingOffsetsCommand(
        m_doc, tr("Smooth Shading Offsets (%1)").arg(targetName(data(), target)), target, std::move(change), {}));
}

// --- painting ------------------------------------------------------------------------------------

OffsetStroke ShadingEdits::beginOffsetStroke(
    const ShadingTarget& target, const OffsetBrush& brush, const algo::Positions& shape)
{
    if (!data().baseMesh)
        throw EditRefused(tr("Shading offsets need a base model."));
    if (!target.isBase() && !data().key(target.key))
        throw EditRefused(tr("Choose a key to paint shading offsets into first."));
    if (!(brush.radius > 0.0) || !std::isfinite(brush.radius) || !std::isfinite(brush.strength) || brush.strength < 0.0)
        throw EditRefused(tr("The brush needs a positive radius and a strength of zero or more."));
    const algo::TriMesh& mesh = *data().baseMesh;
    if (shape.rows() != mesh.vertexCount())
        throw EditRefused(tr("The shape painted on does not have the base model's vertices."));
    OffsetStroke stroke;
    stroke.target = target;
    stroke.brush = brush;
    stroke.shape = shape;
    stroke.grid = algo::VertexGrid(stroke.shape);
    if (brush.mode == OffsetPaintMode::Smooth)
        stroke.neighbours = algo::buildVertexNeighbours(mesh.faces, std::int32_t(mesh.vertexCount()));
    stroke.values = targetShadingOffsets(data(), target);
    stroke.mirrorPlane = mirrorGeometry(mesh, brush.mirror);
    stroke.mirrorReach = 0.05 * algo::boundingBox(mesh.vertices).diagonal().norm();
    stroke.undoText = tr("Paint Shading Offsets (%1)").arg(targetName(data(), target));
    stroke.gesture = m_doc->beginGesture();
    return stroke;
}

std::size_t ShadingEdits::applyOffsetStroke(OffsetStroke& stroke, const Eigen::Vector3d& centre)
{
    if (!stroke.active() || !data().baseMesh || !centre.allFinite()
        || stroke.values.size() != std::size_t(data().baseMesh->vertexCount()))
        return 0;
    if (!stroke.target.isBase() && !data().key(stroke.target.key))
        return 0;
    const OffsetBrush& brush = stroke.brush;
    stroke.grid.radiusQuery(centre, brush.radius, stroke.indices, stroke.distances);
    stroke.mirrorIndices.clear();
    stroke.mirrorDistances.clear();
    stroke.twinMissing = false;
    if (stroke.mirrorPlane) {
        // The reflected centre, moved onto the surface: its nearest vertex (on a model that is only
        // roughly symmetric the reflection floats off the surface).
        const Eigen::Vector3d reflected = algo::reflect(*stroke.mirrorPlane, centre);
        const std::int64_t twin = stroke.grid.nearest(reflected, stroke.mirrorReach);
        stroke.twinMissing = twin < 0;
        if (twin >= 0)
            stroke.grid.radiusQuery(stroke.shape.row(twin).transpose().cast<double>(), brush.radius,
                stroke.mirrorIndices, stroke.mirrorDistances);
    }
    // The union of both dabs, ascending; where both reach a vertex the stronger falloff counts.
    stroke.merged.clear();
    stroke.falloff.clear();
    auto weight = [&brush](float d) {
        const double t = std::max(0.0, 1.0 - double(d) / brush.radius);
        return float(t * t); // paper 1, section 3.1.2's (1 - d/r)^2, reused for painting
    };
    algo::mergeAscending(
        stroke.indices, stroke.mirrorIndices,
        [&](std::size_t i) {
            stroke.merged.push_back(stroke.indices[i]);
            stroke.falloff.push_back(weight(stroke.distances[i]));
        },
        [&](std::size_t j) {
            stroke.merged.push_back(stroke.mirrorIndices[j]);
            stroke.falloff.push_back(weight(stroke.mirrorDistances[j]));
        },
        [&](std::size_t i, std::size_t j) {
            stroke.merged.push_back(stroke.indices[i]);
            stroke.falloff.push_back(std::max(weight(stroke.distances[i]), weight(stroke.mirrorDistances[j])));
        });
    if (stroke.merged.empty())
        return 0;
    // New values of the dab's vertices, all read from the values before the dab (Jacobi).
    stroke.after.resize(stroke.merged.size());
    const float strength = float(brush.strength);
    for (std::size_t k = 0; k < stroke.merged.size(); ++k) {
        const std::uint32_t v = stroke.merged[k];
        const float f = stroke.falloff[k];
        const float now = stroke.values[v];
        float next = now;
        switch (brush.mode) {
        case OffsetPaintMode::Add:
            next = now + strength * f;
            break;
        case OffsetPaintMode::Subtract:
            next = now - strength * f;
            break;
        case OffsetPaintMode::Erase:
            next = now * (1.f - f);
            break;
        case OffsetPaintMode::Smooth: {
            const auto& nb = stroke.neighbours;
            const std::int32_t b = nb.start[v], e = nb.start[std::size_t(v) + 1];
            if (e > b) {
                float sum = 0.f;
                for (std::int32_t i = b; i < e; ++i)
                    sum += stroke.values[std::size_t(nb.neighbours[std::size_t(i)])];
                next = now + 0.5f * f * (sum / float(e - b) - now);
            }
            break;
        }
        }
        stroke.after[k] = next;
    }
    // The command: the dab's vertices, or the whole layer when the dab makes it.
    ShadingOffsetsCommand::Change change;
    change.existsAfter = true;
    change.existedBefore = shadingLayer(data(), stroke.target) != nullptr;
    if (!change.existedBefore) {
        change.indices.resize(stroke.values.size());
        change.before.assign(stroke.values.size(), 0.f);
        for (std::size_t v = 0; v < stroke.values.size(); ++v)
            change.indices[v] = std::uint32_t(v);
        for (std::size_t k = 0; k < stroke.merged.size(); ++k)
            stroke.values[stroke.merged[k]] = stroke.after[k];
        change.after = stroke.values;
    } else {
        change.indices = stroke.merged;
        change.before.resize(stroke.merged.size());
        for (std::size_t k = 0; k < stroke.merged.size(); ++k) {
            change.before[k] = stroke.values[stroke.merged[k]];
            stroke.values[stroke.merged[k]] = stroke.after[k];
        }
        change.after = stroke.after;
    }
    push(new ShadingOffsetsCommand(m_doc, stroke.undoText, stroke.target, std::move(change), stroke.gesture));
    return stroke.merged.size();
}

void ShadingEdits::endOffsetStroke(OffsetStroke& stroke)
{
    stroke.gesture.end();
}

// --- automatic per-segment offsets: solved by model::solveAutoOffsets (analysis/auto_offsets.h) ---

void ShadingEdits::applyAutoOffsets(const ShadingTarget& target, const std::vector<float>& values)
{
    setShadingOffsets(target, values, tr("Automatic Shading Offsets (%1)").arg(targetName(data(), target)));
}

} // namespace celform::model
