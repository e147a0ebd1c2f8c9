// The named face sets, the highlight patches (paper 2, "Highlight operations"), as
// doc.faceSets(): made, painted, renamed and removed by name.
#pragma once

#include "celform/model/data/object_id.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/face_set_stroke.h"
#include "celform/model/document/gesture.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace celform::model {

class FaceSetEdits : public DocumentFacade {
public:
    /// Creates or replaces a face set; faces are sorted and repeats dropped. Steps given one
    /// gesture are one undo step. Throws EditRefused without a base model, for an empty name or
    /// a face out of range.
    void setFaceSet(
        const QString& name, std::vector<std::int32_t> faces, const QString& undoText, GestureId gesture = {});
    // --- the patch brush -------------------------------------------------------------------------
    /// Starts painting the face set named target (made by the first dab when missing); the stroke
    /// holds its own gesture, so all its dabs are one undo step, which stores only the faces the
    /// drag added and took. mirror: also paint each dab's mirror image across that plane of the
    /// base model (Off: none). Throws EditRefused without a base model or for an empty name.
    [[nodiscard]] FaceSetStroke beginFaceSetStroke(const QString& target, MirrorPlane mirror = MirrorPlane::Off);
    /// One dab: adds faces to the set (erase: takes them from it), with their mirror twins when the
    /// stroke mirrors (stroke.twinMissing tells a dab none of whose faces has one). Returns the
    /// faces changed.
    /// Throws EditRefused for a face out of range (nothing changed then).
    std::size_t applyFaceSetStroke(FaceSetStroke& stroke, const std::vector<std::int32_t>& faces, bool erase);
    void endFaceSetStroke(FaceSetStroke& stroke);

    // --- the artist's say over the depth analysis (paper 3, 6.2; issue 26) ----------------------
    /// Starts painting focal points: a dab takes each of its faces (and their mirror twins) from
    /// the importance it had when the stroke began towards value by strength,
    /// new = old + strength (value - old), once per stroke (Ctrl/erase: towards 1). The stroke is
    /// one undo step, as a patch stroke; apply it with applyFaceSetStroke. Throws EditRefused
    /// without a base model, for a value outside [0, 1] or a strength outside (0, 1].
    [[nodiscard]] FaceSetStroke beginImportanceStroke(
        float value, float strength, MirrorPlane mirror = MirrorPlane::Off);
    /// Every face's importance back to 1 (the layer removed), one undo step.
    void clearFaceImportance();
    /// Replaces the segment overrides (empty: none) as one undo step storing only the faces that
    /// change. Throws EditRefused without a base model or for overrides that do not fit it
    /// (segmentOverridesProblem).
    void setSegmentOverrides(std::vector<std::int32_t> overrides, const QString& undoText);

    /// Removes a face set; highlight layers on it go back to all faces in the same undo step.
    void removeFaceSet(const QString& name);
    /// Renames a face set and the highlight layers' references to it (one undo step). Throws
    /// EditRefused for an empty name or one already taken.
    void renameFaceSet(const QString& name, const QString& newName);
    /// A new empty face set for a layer, and the layer moved onto it (one undo step).
    QString newFaceSetForLayer(ObjectId layer, const QString& wanted);
    [[nodiscard]] QString uniqueFaceSetName(const QString& wanted) const;

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
    /// Throws EditRefused without a base model, for an empty name or a face out of range (faces
    /// ascending).
    void refuseFaces(const QString& name, const std::vector<std::int32_t>& faces) const;
    /// Sets up the stroke's mirror (centroids, reach) and gesture.
    void prepareStroke(FaceSetStroke& stroke, MirrorPlane mirror) const;
    /// stroke.dab: faces with their mirror twins, ascending (sets stroke.twinMissing).
    void collectDab(FaceSetStroke& stroke, const std::vector<std::int32_t>& faces) const;
    std::size_t applyImportanceDab(FaceSetStroke& stroke, bool erase);
};

} // namespace celform::model
