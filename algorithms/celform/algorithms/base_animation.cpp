// Evaluation of an animated base model: morph targets, then linear blend skinning (paper 1,
// section 4.1 takes the animated base as given; glTF 2.0's skinning and morph-target sections fix
// the order: targets displace the rest positions, then the joints move the result).
#include "celform/algorithms/base_animation.h"

#include <algorithm>
#include <cmath>

namespace celform::algo {
namespace {

/// A vertex's skinning matrix: its influences' matrices weighted. An unused influence (weight 0)
/// may name any joint, even one past the joints, so its matrix is never read.
SkinMatrix blendedSkinMatrix(
    const SkinMatrix* matrices, const std::array<std::uint16_t, 4>& joints, const Eigen::Vector4f& weights)
{
    SkinMatrix m = SkinMatrix::Zero();
    for (int i = 0; i < 4; ++i)
        if (weights[i] != 0.0f)
            m.noalias() += weights[i] * matrices[joints[std::size_t(i)]];
    return m;
}

} // namespace

int BaseAnimation::sampleOf(int frame) const
{
    if (frameCount <= 0)
        return 0;
    return std::clamp(frame - firstFrame, 0, frameCount - 1);
}

std::string BaseAnimation::problem(Eigen::Index vertexCount) const
{
    if (frameCount <= 0)
        return "the animation has no frames";
    for (std::size_t t = 0; t < morphTargets.size(); ++t) {
        if (morphTargets[t].rows() != vertexCount)
            return "morph target " + std::to_string(t) + " has " + std::to_string(morphTargets[t].rows())
                + " vertices, the base model " + std::to_string(vertexCount);
        if (!morphTargets[t].allFinite())
            return "morph target " + std::to_string(t) + " has a coordinate that is not a finite number";
    }
    if (hasVertexFrames() || !vertexFrameOfSample.empty()) {
        if (vertexCount <= 0 || vertexFrames.rows() % vertexCount != 0)
            return "the vertex frames do not hold whole frames of " + std::to_string(vertexCount) + " vertices";
        if (vertexFrameOfSample.size() != std::size_t(frameCount))
            return "the vertex frames do not name a stored frame for every sample";
        const Eigen::Index stored = storedFrameCount(vertexCount);
        for (std::size_t s = 0; s < vertexFrameOfSample.size(); ++s)
            if (vertexFrameOfSample[s] < 0 || vertexFrameOfSample[s] >= stored)
                return "sample " + std::to_string(s) + " shows vertex frame " + std::to_string(vertexFrameOfSample[s])
                    + " of " + std::to_string(stored);
        if (!vertexFrames.allFinite())
            return "a vertex frame has a coordinate that is not a finite number";
    }
    if (morphWeights.size() != morphTargets.size() * std::size_t(frameCount))
        return "the morph weights do not cover every target at every frame";
    if (!std::all_of(morphWeights.begin(), morphWeights.end(), [](float w) { return std::isfinite(w); }))
        return "a morph weight is not a finite number";
    if (jointCount < 0)
        return "negative joint count";
    if (jointCount > 0 || !joints.empty()) {
        if (joints.size() != std::size_t(vertexCount) || jointWeights.size() != std::size_t(vertexCount))
            return "the skin does not give joints and weights for every vertex";
        if (skinMatrices.size() != std::size_t(jointCount) * std::size_t(frameCount))
            return "the skin does not give every joint's matrix at every frame";
        for (std::size_t v = 0; v < joints.size(); ++v)
            for (int i = 0; i < 4; ++i)
                if (jointWeights[v][i] != 0.0f && joints[v][std::size_t(i)] >= jointCount)
                    return "vertex " + std::to_string(v) + " names joint " + std::to_string(joints[v][std::size_t(i)])
                        + " of " + std::to_string(jointCount);
        for (const SkinMatrix& m : skinMatrices)
            if (!m.allFinite())
                return "a joint matrix is not finite";
        for (const Eigen::Vector4f& w : jointWeights)
            if (!w.allFinite())
                return "a joint weight is not a finite number";
    }
    return {};
}

void BaseAnimation::evaluate(const Positions& rest, int frame, Positions& out) const
{
    if (out.rows() != rest.rows())
        out.resize(rest.rows(), 3);
    if (frameCount <= 0) {
        out = rest;
        return;
    }
    const std::size_t s = std::size_t(sampleOf(frame));
    const std::size_t targets = morphTargets.size();
    const Eigen::Index n = rest.rows();
    // The sample's stored frame of a vertex sequence, or the rest positions; then the morph
    // targets, whole arrays at a time (only the targets weighted at this sample).
    if (hasVertexFrames())
        out = vertexFrames.middleRows(Eigen::Index(vertexFrameOfSample[s]) * n, n);
    else
        out = rest;
    for (std::size_t t = 0; t < targets; ++t) {
        const float w = morphWeights[s * targets + t];
        if (w == 0.0f)
            continue;
        if (w == 1.0f)
            out.noalias() += morphTargets[t];
        else
            out.noalias() += w * morphTargets[t];
    }
    if (!skinned())
        return;
    // Then each morphed vertex moved by the blend of its joints' matrices, in place. An unused
    // influence (weight 0) may name any joint, even one past jointCount (problem() allows it), so
    // its matrix is never read.
    const SkinMatrix* matrices = skinMatrices.data() + s * std::size_t(jointCount);
    float* data = out.data();
    for (Eigen::Index v = 0; v < n; ++v) {
        const Eigen::Vector4f p(data[3 * v], data[3 * v + 1], data[3 * v + 2], 1.0f);
        const Eigen::Vector3f q = blendedSkinMatrix(matrices, joints[std::size_t(v)], jointWeights[std::size_t(v)]) * p;
        data[3 * v] = q[0];
        data[3 * v + 1] = q[1];
        data[3 * v + 2] = q[2];
    }
}

Eigen::Vector3f BaseAnimation::evaluateVertex(const Positions& rest, int frame, Eigen::Index v) const
{
    if (frameCount <= 0)
        return rest.row(v).transpose();
    const std::size_t s = std::size_t(sampleOf(frame));
    Eigen::Vector3f p = hasVertexFrames()
        ? Eigen::Vector3f(vertexFrames.row(Eigen::Index(vertexFrameOfSample[s]) * rest.rows() + v).transpose())
        : Eigen::Vector3f(rest.row(v).transpose());
    const std::size_t targets = morphTargets.size();
    if (!skinned()) {
        // In evaluate()'s order: the targets added one after another.
        for (std::size_t t = 0; t < targets; ++t)
            if (const float w = morphWeights[s * targets + t]; w != 0.0f)
                p += w == 1.0f ? Eigen::Vector3f(morphTargets[t].row(v).transpose())
                               : Eigen::Vector3f(w * morphTargets[t].row(v).transpose());
        return p;
    }
    Eigen::Vector4f q(p[0], p[1], p[2], 1.0f);
    for (std::size_t t = 0; t < targets; ++t)
        if (const float w = morphWeights[s * targets + t]; w != 0.0f) {
            const float* delta = morphTargets[t].data();
            q[0] += w * delta[3 * v];
            q[1] += w * delta[3 * v + 1];
            q[2] += w * delta[3 * v + 2];
        }
    // As evaluate(): an unused influence's joint (which may be past jointCount) is never read.
    const SkinMatrix* matrices = skinMatrices.data() + s * std::size_t(jointCount);
    return blendedSkinMatrix(matrices, joints[std::size_t(v)], jointWeights[std::size_t(v)]) * q;
}

bool BaseAnimation::operator==(const BaseAnimation& o) const
{
    return firstFrame == o.firstFrame && frameCount == o.frameCount && vertexFrames.rows() == o.vertexFrames.rows()
        && (vertexFrames.rows() == 0 || vertexFrames == o.vertexFrames) && vertexFrameOfSample == o.vertexFrameOfSample
        && morphTargets == o.morphTargets && morphWeights == o.morphWeights && joints == o.joints
        && jointWeights == o.jointWeights && jointCount == o.jointCount && skinMatrices == o.skinMatrices;
}

} // namespace celform::algo
