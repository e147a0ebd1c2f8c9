// Stylized highlight layers (Anjyo & Hiramitsu 2003, "Making highlight animation"), by layer id
// (doc.highlights()): layers, their keys and operations, and the direct manipulation of a
// highlight in the viewport. Combinations name other layers, so renames and removals carry their
// references along in the same undo step.
#pragma once

#include "celform/model/data/project_data.h"
#include "celform/model/document/document_facade.h"
#include "celform/model/document/gesture.h"
#include "celform/model/document/highlight_drag.h"
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
    // --- direct manipulation in the viewport ------------------------------------------------------
    /// Starts a drag of a layer's highlight at frame (keyed there); the drag holds its own gesture,
    /// so all its steps are one undo step. Throws EditRefused when the layer does not exist.
    [[nodiscard]] HighlightDrag beginHighlightDrag(ObjectId id, double frame);
    /// One step (highlight_drag.h: move, rotate, scale). A layer without an operation of the
    /// step's type gets one in every key first (translation and rotation at the front, scaling at
    /// the end), so its keys keep interpolating. Nothing once ended or when the layer is gone.
    void applyHighlightDrag(HighlightDrag& drag, const HighlightDragStep& step);
    void endHighlightDrag(HighlightDrag& drag);
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
