// The layers of shading offsets and the offsets in effect (shading_layers.h).
#include "celform/model/data/shading_layers.h"

#include "celform/algorithms/blend.h"

#include <QCoreApplication>

#include <cmath>

namespace celform::model {

std::vector<double> shadingFrameWeights(const ProjectData& data, const KeyViewpoint& key, int frame)
{
    const auto& frames = key.shadingOffsetsByFrame;
    if (frames.empty())
        return {};
    if (frames.size() == 1)
        return {1.0};
    std::vector<double> knots;
    knots.reserve(frames.size());
    for (const auto& entry : frames)
        knots.push_back(double(entry.first));
    return algo::splineWeights(knots, double(frame), data.blend.time == TimeInterpolation::PeriodicSpline);
}

void addKeyShadingOffsets(
    const ProjectData& data, const KeyViewpoint& key, int frame, double weight, std::vector<float>& out)
{
    if (key.shadingOffsetsByFrame.empty() || weight == 0.0)
        return;
    // A keyed frame's own values exactly; otherwise the spline over the keyed frames.
    if (const auto it = key.shadingOffsetsByFrame.find(frame); it != key.shadingOffsetsByFrame.end()) {
        const float w = float(weight);
        const std::vector<float>& values = it->second;
        for (std::size_t v = 0; v < out.size() && v < values.size(); ++v)
            out[v] += w * values[v];
        return;
    }
    const std::vector<double> weights = shadingFrameWeights(data, key, frame);
    std::size_t k = 0;
    for (const auto& [keyed, values] : key.shadingOffsetsByFrame) {
        const float w = float(weight * weights[k++]);
        if (w == 0.f)
            continue;
        for (std::size_t v = 0; v < out.size() && v < values.size(); ++v)
            out[v] += w * values[v];
    }
}

void effectiveShadingOffsets(
    const ProjectData& data, const std::vector<KeyShare>& shares, int frame, std::vector<float>& out)
{
    const std::size_t n = data.baseMesh ? std::size_t(data.baseMesh->vertexCount()) : 0;
    bool any = !data.shadingOffsets.empty();
    for (const KeyShare& share : shares)
        if (const KeyViewpoint* key = data.key(share.key); key && share.weight != 0.0)
            any = any || !key->shadingOffsetsByFrame.empty();
    if (!any || n == 0) {
        out.clear();
        return;
    }
    if (data.shadingOffsets.size() == n)
        out.assign(data.shadingOffsets.begin(), data.shadingOffsets.end());
    else
        out.assign(n, 0.f);
    for (const KeyShare& share : shares)
        if (const KeyViewpoint* key = data.key(share.key))
            addKeyShadingOffsets(data, *key, frame, share.weight, out);
}

void effectiveShadingOffsets(const ProjectData& data, const BlendEvaluator& blender,
    const Eigen::Vector3d& viewDirection, int frame, std::vector<float>& out)
{
    bool keyed = false;
    for (const KeyViewpoint& key : data.keys)
        keyed = keyed || (key.enabled && !key.shadingOffsetsByFrame.empty());
    // Without key layers the blend cannot matter: skip the hull walk.
    static const std::vector<KeyShare> none;
    if (!keyed) {
        effectiveShadingOffsets(data, none, frame, out);
        return;
    }
    effectiveShadingOffsets(data, blender.weights(data, viewDirection).shares, frame, out);
}

std::vector<float> targetShadingOffsets(const ProjectData& data, const ShadingTarget& target)
{
    const std::size_t n = data.baseMesh ? std::size_t(data.baseMesh->vertexCount()) : 0;
    std::vector<float> out(n, 0.f);
    if (target.isBase()) {
        if (data.shadingOffsets.size() == n)
            out = data.shadingOffsets;
    } else if (const KeyViewpoint* key = data.key(target.key)) {
        addKeyShadingOffsets(data, *key, target.frame, 1.0, out);
    }
    return out;
}

QString shadingOffsetsProblem(const std::vector<float>& values, std::int64_t vertexCount)
{
    if (std::int64_t(values.size()) != vertexCount)
        return QCoreApplication::translate("celform::model::ShadingLayers", "%1 shading offsets for %2 vertices")
            .arg(values.size())
            .arg(vertexCount);
    for (float v : values)
        if (!std::isfinite(v))
            return QCoreApplication::translate("celform::model::ShadingLayers", "a shading offset is not finite");
    return {};
}

} // namespace celform::model
