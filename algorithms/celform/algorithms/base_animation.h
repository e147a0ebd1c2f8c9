// An animated base model (paper 1, section 4.1): the base mesh's vertices moved over time by
// morph targets and linear blend skinning, sampled at whole frames. A vertex sequence (OBJ/PLY
// frames) is stored as what it is: one position array per stored frame, and per sample the frame
// it shows, so that memory is linear in the sequence's length (issue 27).
#pragma once

#include "celform/algorithms/tri_mesh.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace celform::algo {

/// A joint's skinning matrix at a frame: its global transform times its inverse bind matrix, in
/// the base model's space (3 rows by 4 columns; the last row of the affine matrix is implied).
using SkinMatrix = Eigen::Matrix<float, 3, 4>;

struct BaseAnimation {
    int firstFrame = 0; ///< the project frame of sample 0
    int frameCount = 0; ///< samples; frames outside [firstFrame, firstFrame + frameCount) hold the ends

    /// A vertex sequence: the base's positions at each stored frame, frame after frame (#frames * #V
    /// rows); empty when the base is not a sequence. When present, a sample starts from its frame's
    /// positions instead of the rest positions (morph targets and skinning then apply as usual).
    Positions vertexFrames;
    /// Per sample, the stored frame it shows (frameCount entries when vertexFrames is not empty;
    /// a missing file number of a sequence holds the frame before it).
    std::vector<std::int32_t> vertexFrameOfSample;

    /// Dense per-vertex deltas of each morph target (#V by 3 each).
    std::vector<Positions> morphTargets;
    /// Weights per sample, sample-major: morphWeights[s * morphTargets.size() + t].
    std::vector<float> morphWeights;

    /// Linear blend skinning: up to four influences per vertex (weights summing to 1; unused
    /// influences have weight 0). Empty when the base is not skinned.
    std::vector<std::array<std::uint16_t, 4>> joints;
    std::vector<Eigen::Vector4f> jointWeights;
    int jointCount = 0;
    /// Skinning matrices per sample, sample-major: skinMatrices[s * jointCount + j].
    std::vector<SkinMatrix, Eigen::aligned_allocator<SkinMatrix>> skinMatrices;

    [[nodiscard]] bool empty() const { return frameCount <= 0; }
    [[nodiscard]] int lastFrame() const { return firstFrame + frameCount - 1; }
    [[nodiscard]] bool skinned() const { return jointCount > 0 && !joints.empty(); }
    [[nodiscard]] bool hasVertexFrames() const { return vertexFrames.rows() > 0; }
    /// The stored frames of a vertex sequence, for a base of vertexCount vertices.
    [[nodiscard]] Eigen::Index storedFrameCount(Eigen::Index vertexCount) const
    {
        return vertexCount > 0 ? vertexFrames.rows() / vertexCount : 0;
    }
    /// The sample a frame reads (held at the ends).
    [[nodiscard]] int sampleOf(int frame) const;

    /// The first inconsistency for a base of vertexCount vertices, empty when valid: sizes,
    /// finite values, joint indices below jointCount.
    [[nodiscard]] std::string problem(Eigen::Index vertexCount) const;

    /// The base's vertices at a frame: (start + sum_t w_t * delta_t), then skinned, where start is
    /// the sample's stored frame for a vertex sequence and the rest positions otherwise. out is resized
    /// only when its size differs (no allocation per frame otherwise).
    void evaluate(const Positions& rest, int frame, Positions& out) const;
    /// One vertex of evaluate()'s result, computed alone (the same floats).
    [[nodiscard]] Eigen::Vector3f evaluateVertex(const Positions& rest, int frame, Eigen::Index vertex) const;

    bool operator==(const BaseAnimation& o) const;
};

} // namespace celform::algo
