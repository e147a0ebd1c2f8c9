// The undo command that changes some faces' values of a per-face layer: the face importance
// (focal points) or the segment overrides of the depth analysis (issue 26, "the artist's say").
#pragma once

#include "celform/model/document/document_command.h"

#include <cstdint>
#include <vector>

namespace celform::model {

/// Which per-face layer of ProjectData a FaceValuesCommand changes.
enum class FaceLayer {
    Importance, ///< ProjectData::faceImportance (float, default 1)
    SegmentOverrides, ///< ProjectData::segmentOverrides (int32, default kNoSegmentOverride)
};

/// Changes some faces of one per-face layer, storing before and after values of just those faces
/// (a paint dab's cost follows the dab), and whether the layer existed (was not empty) before and
/// exists after: a layer made here is filled with its default first, one taken away is cleared.
/// Steps of one gesture on the same layer merge: the union of the faces, the first "before" and
/// the last "after" of each. Values are floats; override labels are whole numbers, exact in a float
/// up to 2^24 faces (refused beyond by the edits).
class FaceValuesCommand : public DocumentCommand {
public:
    struct Change {
        std::vector<std::int32_t> indices; ///< the faces, ascending
        std::vector<float> before, after;
        bool existedBefore = false;
        bool existsAfter = true;
    };

    FaceValuesCommand(Document* doc, const QString& text, FaceLayer layer, Change change, GestureId gesture);

    [[nodiscard]] const Change& change() const { return m_change; }
    int id() const override { return m_gesture ? kFaceValuesMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(bool forward) override;

private:
    FaceLayer m_layer;
    Change m_change;
    GestureId m_gesture;
};

} // namespace celform::model
