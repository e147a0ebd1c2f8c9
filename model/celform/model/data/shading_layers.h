// The layers of per-vertex shading offsets (paper 3, section 4.3, eq. 4.3) and the offsets in
// effect at a view and frame: the base layer plus each key's layer at the frame, weighted by the
// key's share in the view blend (the weights the geometry blend uses, paper 1, section 3.2). Every
// consumer (celform render, the viewport, the depth analysis) goes through
// effectiveShadingOffsets, so they cannot disagree.
#pragma once

#include "celform/model/data/project_data.h"
#include "celform/model/data/blend_evaluator.h"

#include <QString>

#include <vector>

namespace celform::model {

/// A layer the document edits: the base (key 0, every frame) or a key's layer at a frame.
struct ShadingTarget {
    ObjectId key = 0;
    int frame = 0;
    [[nodiscard]] bool isBase() const { return key == 0; }
    bool operator==(const ShadingTarget& o) const { return key == o.key && (key == 0 || frame == o.frame); }
    bool operator!=(const ShadingTarget& o) const { return !(*this == o); }
};

/// The weights of a key's shading-offset frames at frame, in keyed-frame order: natural cubic
/// splines (periodic for looping cycles) held outside the keyed range, as key deformations
/// (paper 1, section 4.2; ProjectData::keyFrameWeights). Empty when the key has no layer.
[[nodiscard]] std::vector<double> shadingFrameWeights(const ProjectData& data, const KeyViewpoint& key, int frame);

/// Adds weight * (the key's layer at frame) to out (#V). No-op when the key has no layer.
void addKeyShadingOffsets(
    const ProjectData& data, const KeyViewpoint& key, int frame, double weight, std::vector<float>& out);

/// The offsets in effect: base + sum_i w'_i key_i(frame) over the shares. out is resized to #V,
/// or emptied (meaning all zero) when no layer holds anything; its memory is reused.
void effectiveShadingOffsets(
    const ProjectData& data, const std::vector<KeyShare>& shares, int frame, std::vector<float>& out);
/// The same for a view direction (DESIGN.md convention) through an up-to-date blender.
void effectiveShadingOffsets(const ProjectData& data, const BlendEvaluator& blender,
    const Eigen::Vector3d& viewDirection, int frame, std::vector<float>& out);

/// A target's values as the artist sees them (#V, zeros where the layer is empty): the base layer,
/// or a key's layer at the frame (interpolated between keyed frames).
[[nodiscard]] std::vector<float> targetShadingOffsets(const ProjectData& data, const ShadingTarget& target);

/// The first problem of a layer's values for a model of vertexCount vertices, empty when valid:
/// the count and finite values.
[[nodiscard]] QString shadingOffsetsProblem(const std::vector<float>& values, std::int64_t vertexCount);

/// The most rounds of smoothing or bleeding an edit may ask for.
constexpr int kMaxOffsetRounds = 1000;

} // namespace celform::model
