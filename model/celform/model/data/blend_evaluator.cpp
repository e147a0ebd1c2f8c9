// Blend evaluation over the document's keys.
#include "celform/model/data/blend_evaluator.h"

#include "celform/algorithms/blend.h"

#include <QCoreApplication>

namespace celform::model {
namespace {

algo::UnspecifiedRegions toAlgo(UnspecifiedMode mode)
{
    switch (mode) {
    case UnspecifiedMode::Cosine:
        return algo::UnspecifiedRegions::Cosine;
    case UnspecifiedMode::Cosine2:
        return algo::UnspecifiedRegions::Cosine2;
    case UnspecifiedMode::Dummy:
        break;
    }
    return algo::UnspecifiedRegions::Dummy;
}

} // namespace

bool BlendEvaluator::update(const ProjectData& data, QString* error)
{
    std::vector<ObjectId> ids;
    std::vector<Eigen::Vector3d> directions;
    for (const auto& key : data.keys) {
        if (!key.enabled)
            continue;
        if (!key.direction.allFinite() || !(key.direction.norm() > 0.0)) {
            // Named here: the view sphere knows keys only by their index.
            if (error)
                *error = QCoreApplication::translate(
                    "celform::model::BlendEvaluator", "The key “%1” has no view direction (zero or not finite).")
                             .arg(key.name);
            m_built = false;
            m_sphere.reset();
            return false;
        }
        ids.push_back(key.id);
        directions.push_back(key.direction);
    }
    if (m_built && ids == m_keyIds && directions == m_directions && m_mode == data.blend.unspecified)
        return m_sphere.has_value();
    m_keyIds = std::move(ids);
    m_directions = std::move(directions);
    m_mode = data.blend.unspecified;
    m_built = true;
    std::string message;
    m_sphere = algo::ViewSphere::build(m_directions, toAlgo(m_mode), &message);
    if (!m_sphere && error)
        *error = QString::fromStdString(message);
    return m_sphere.has_value();
}

BlendResult BlendEvaluator::weights(const ProjectData& data, const Eigen::Vector3d& viewDirection) const
{
    BlendResult result;
    weights(data, viewDirection, result);
    return result;
}

void BlendEvaluator::weights(const ProjectData& data, const Eigen::Vector3d& viewDirection, BlendResult& result) const
{
    result.shares.clear();
    result.baseShare = 1.0;
    if (!m_sphere) {
        result.raw = algo::ViewBlend{};
        return;
    }
    m_sphere->blend(viewDirection, data.blend.sharpness, result.raw);
    for (const auto& kw : result.raw.weights) {
        if (kw.weight <= 0.0)
            continue;
        result.shares.push_back({m_keyIds[std::size_t(kw.key)], kw.weight});
        result.baseShare -= kw.weight;
    }
}

void BlendEvaluator::shape(const ProjectData& data, const Eigen::Vector3d& viewDirection, int frame,
    algo::Positions& out, const algo::Positions* base) const
{
    Q_ASSERT(data.baseMesh);
    algo::Positions scratch;
    shapeFor(data, weights(data, viewDirection), frame, base ? *base : data.basePositions(frame, scratch), out);
}

void BlendEvaluator::shapeFor(const ProjectData& data, const BlendResult& blend, int frame, const algo::Positions& base,
    algo::Positions& out, BlendScratch* scratch) const
{
    BlendScratch local;
    BlendScratch& buffers = scratch ? *scratch : local;
    std::vector<algo::WeightedOffsets>& parts = buffers.parts;
    parts.clear();
    // Each key's offsets at the frame (stored, or interpolated over time and held here); the
    // buffers only grow, so a caller's scratch keeps its storage between frames.
    if (buffers.atFrame.size() < blend.shares.size())
        buffers.atFrame.resize(blend.shares.size());
    std::size_t used = 0;
    for (const KeyShare& share : blend.shares) {
        const KeyViewpoint* key = data.key(share.key);
        if (!key)
            continue;
        ProjectData::FrameOffsets& slot = buffers.atFrame[used++];
        ProjectData::offsetsAt(*key, frame, data.blend.time, slot);
        const SparseOffsets* offsets = slot.get();
        if (!offsets || offsets->indices.empty())
            continue;
        algo::OffsetsView view;
        view.indices = offsets->indices.data();
        view.offsets = offsets->deltas.front().data();
        view.count = offsets->indices.size();
        view.dense = view.count == std::size_t(base.rows());
        parts.push_back({view, float(share.weight)});
    }
    algo::blendShape(base, parts, out);
}

Eigen::Vector3d BlendEvaluator::viewDirection(const ProjectData& data, const Eigen::Vector3d& eye, int frame)
{
    return viewDirectionFromEye(data, eye, frame);
}

Eigen::Vector3d viewDirectionFromEye(const ProjectData& data, const Eigen::Vector3d& eye, int frame)
{
    // A still base's centroid is computed once per base model and kept with it.
    return viewDirectionFromCentre(data.baseCentre(frame), eye);
}

Eigen::Vector3d viewDirectionFromCentre(const Eigen::Vector3d& centre, const Eigen::Vector3d& eye)
{
    const Eigen::Vector3d d = eye - centre;
    const double n = d.norm();
    return n > 0 && std::isfinite(n) ? Eigen::Vector3d(d / n) : Eigen::Vector3d::Zero();
}

} // namespace celform::model
