// Stylized highlight layers (Anjyo & Hiramitsu 2003, "Making highlight animation"), by layer id
// (doc.highlights()): layers, their keys and operations, and the direct manipulation of a
// highlight in the viewport. Combinations name other layers, so renames and removals carry their
// references along in the same undo step.
#pragma once

#include "celform/model/data/project_data.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/gesture.h"
#include "celform/model/document/highlight_presets.h"

#include <QString>

#include <utility>
#include <vector>

namespace celform::model {

class HighlightEdits : public DocumentFacade {
public:
    /// Adds layers in one undo step (undoText), after the others; gives each a new id. Names must
    /// be unique and the tracks valid (highlightTracksProblem), else EditRefused and no change.
    std::vector<ObjectId> addHighlightLayers(std::vector<HighlightTrack> tracks, const QString& undoText);
    /// Adds one layer named name (made unique) with a plain key at frame. Returns its id.
    ObjectId addHighlightLayer(const QString& name, int frame);
    /// Adds a preset's layers (highlight_presets.h) at frame, on the patch, guide and smoothing of
    /// base (0: all faces) with names made unique; one undo step. Returns the ids, the visible
    /// layer last.
    std::vector<ObjectId> addHighlightPreset(HighlightPreset preset, ObjectId base, int frame);
    /// Removes a layer and its use in other layers' combinations (one undo step).
    void removeHighlightLayer(ObjectId id);
    /// Renames a layer, other layers' combinations following. Throws EditRefused for an empty or
    /// taken name.
    void renameHighlightLayer(ObjectId id, const QString& name);
    /// Sets (replaces or inserts) the key at frame. The undo text names what changed (size,
    /// colour, cut, operations). Throws EditRefused for parameters out of the paper's range.
    void setHighlightKey(ObjectId id, double frame, const algo::HighlightLayer& layer, GestureId gesture = {});
    /// Replaces all keys at once (structure edits of the operations, which every key follows).
    void setHighlightKeys(
        ObjectId id, std::vector<algo::HighlightKey> keys, const QString& undoText, GestureId gesture = {});
    /// Operations are the same list in every key (so that keys interpolate): these change the list
    /// of every key at once. Add appends a neutral operation of the type; move shifts one by delta
    /// places; remove drops one.
    void addHighlightOperation(ObjectId id, algo::HighlightOperationType type);
    void moveHighlightOperation(ObjectId id, int index, int delta);
    void removeHighlightOperation(ObjectId id, int index);
    /// Removes the key at frame; a layer keeps at least one key (no change then).
    void removeHighlightKey(ObjectId id, double frame);
    /// Direct manipulation of a highlight at frame: Translation moves it by (a, b) along the
    /// layer's du and dv as they are before its operations (rotations earlier in the list turn
    /// the frame; they are undone here), Rotation turns it by a degrees, DirectionalScaling adds a
    /// to delta (clamped to [0, 1]). A layer without an operation of that type gets one in every
    /// key first (translation and rotation at the front, scaling at the end), so its keys keep
    /// interpolating. Steps given one gesture (a drag) are one undo step.
    void nudgeHighlight(
        ObjectId id, double frame, algo::HighlightOperationType type, double a, double b = 0.0, GestureId gesture = {});
    /// Moves a highlight at frame so that its translation along the unturned du and dv is
    /// (alpha, beta) (HighlightTrack::translationAt); the "Move Highlight" step of a drag.
    void setHighlightTranslation(ObjectId id, double frame, double alpha, double beta, GestureId gesture = {});
    void setHighlightPatch(ObjectId id, const QString& patch, GestureId gesture = {});
    void setHighlightGuide(ObjectId id, const Eigen::Vector3f& guide, GestureId gesture = {});
    void setHighlightSmoothing(ObjectId id, int rounds, GestureId gesture = {});
    void setHighlightVisible(ObjectId id, bool visible);
    void setHighlightCombinations(
        ObjectId id, std::vector<std::pair<algo::HighlightBoolean, QString>> combinations, GestureId gesture = {});
    [[nodiscard]] QString uniqueHighlightName(const QString& wanted) const;

private:
    friend class Document;
    using DocumentFacade::DocumentFacade;
    [[nodiscard]] const HighlightTrack& highlightOrThrow(ObjectId id) const;
    /// Checks the tracks as they would be after an edit; throws EditRefused with the problem.
    void refuseInvalidTracks(const std::vector<HighlightTrack>& tracks) const;
};

} // namespace celform::model
