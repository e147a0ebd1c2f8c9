// What one document change touched (DESIGN.md, "The document": the document emits what changed so
// that listeners do the least work). Commands describe their change; the document gathers the
// changes of one push, undo or redo and emits them once.
#pragma once

#include "celform/model/data/object_id.h"

#include <cstdint>
#include <vector>

namespace celform::model {

/// The parts of the document, as bits of ChangeSet::parts.
enum class Part : std::uint32_t {
    Mesh = 1u << 0, ///< the base model (positions, faces, materials)
    Drawings = 1u << 1,
    Keys = 1u << 2, ///< key viewpoints: cameras, directions, links, offsets
    Blend = 1u << 3, ///< sharpness, unspecified regions, time interpolation
    Look = 1u << 4, ///< shading, lines, light, stereo, render camera (not the highlights)
    Highlights = 1u << 5, ///< the stylized highlight layers
    FaceSets = 1u << 6, ///< the named face sets (highlight patches)
    ShadingOffsets = 1u << 7, ///< per-vertex shading offsets
    Playhead = 1u << 8, ///< the current frame (not undoable)
    CameraPath = 1u << 9, ///< the keyed render cameras (look.cameraPath)
    SceneTime = 1u << 10, ///< frames per second and the frame range
    /// The depth analysis's per-face say: face importance (focal points) and segment overrides
    FaceValues = 1u << 11,
};

struct ChangeSet {
    std::uint32_t parts = 0; ///< bits of Part
    /// The whole document was replaced (open, new): everything changed, every id may be gone.
    bool reset = false;
    /// Objects were added, removed, renamed, reordered, enabled or disabled, or a key's set of
    /// keyed frames changed: lists and trees need rebuilding. False for value edits.
    bool structure = false;
    /// Only the values of key vertex offsets changed (brush steps, imported deformations): shapes
    /// change, nothing else does.
    bool offsetsOnly = false;
    std::vector<ObjectId> ids; ///< objects whose data changed (ascending, no repeats)
    std::vector<int> frames; ///< frames whose keyed data changed (ascending, no repeats)
    /// With offsetsOnly: the vertices whose offsets changed (ascending, no repeats); empty when
    /// any vertex may have changed.
    std::vector<std::uint32_t> vertices;

    [[nodiscard]] bool empty() const { return parts == 0 && !reset; }
    [[nodiscard]] bool has(Part part) const { return reset || (parts & std::uint32_t(part)) != 0; }
    /// Whether only the playhead moved.
    [[nodiscard]] bool onlyPlayhead() const { return !reset && parts == std::uint32_t(Part::Playhead); }
    [[nodiscard]] bool touches(ObjectId id) const;

    /// Adds another change to this one (several commands of one step).
    void merge(const ChangeSet& other);
    /// Empties the set, keeping the vectors' memory (the document reuses one set per step).
    void clear();

    /// A change of one part, optionally of one object.
    static ChangeSet of(Part part, ObjectId id = 0);
};

} // namespace celform::model
