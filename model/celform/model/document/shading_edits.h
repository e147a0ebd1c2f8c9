// Shading offsets (paper 3, section 4.3, eq. 4.3) as doc.shading(): the base layer, or a key's
// layer at a frame, set, cleared, smoothed, solved (analysis/auto_offsets.h) or painted.
#pragma once

#include "celform/model/data/shading_layers.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/offset_stroke.h"

#include <QString>

#include <vector>

namespace celform::model {

class ShadingEdits : public DocumentFacade {
public:
    /// Replaces a target's values (#V, finite) in one undo step. Throws EditRefused (no base
    /// model, no such key, wrong count, a value not finite) and changes nothing then.
    void setShadingOffsets(const ShadingTarget& target, const std::vector<float>& values, const QString& undoText = {});
    /// Removes a target's layer: the base layer, or the key's layer at target.frame (allFrames:
    /// at every frame). One undo step; nothing when there is nothing to clear.
    void clearShadingOffsets(const ShadingTarget& target, bool allFrames = false);
    /// rounds (1 .. kMaxOffsetRounds) of Laplacian smoothing over the mesh's vertex neighbours of
    /// a target's values as seen at its frame. One undo step. Throws EditRefused.
    void smoothShadingOffsets(const ShadingTarget& target, int rounds);
    /// Stores the values model::solveAutoOffsets found for a target (analysis/auto_offsets.h) as
    /// one undo step, "Automatic Shading Offsets (name)". Throws EditRefused as setShadingOffsets.
    void applyAutoOffsets(const ShadingTarget& target, const std::vector<float>& values);

    // --- the offset brush ------------------------------------------------------------------------
    /// Starts painting a target on shape (the shape shown, #V by 3); the stroke holds its own
    /// gesture, so all its dabs are one undo step. Throws EditRefused (no base model or key, bad
    /// brush).
    [[nodiscard]] OffsetStroke beginOffsetStroke(
        const ShadingTarget& target, const OffsetBrush& brush, const algo::Positions& shape);
    /// One dab centred at a point of the shape (model space), with the falloff (1 - d/r)^2 and,
    /// with a mirror plane, around its mirror image too: the vertex of the shape nearest to the
    /// centre's reflection, so approximate symmetry works (stroke.twinMissing when there is none
    /// within 5% of the model's size). Returns the vertices changed (0: none in reach).
    std::size_t applyOffsetStroke(OffsetStroke& stroke, const Eigen::Vector3d& centre);
    void endOffsetStroke(OffsetStroke& stroke);

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
};

} // namespace celform::model
