// One drag of a stylized highlight in the viewport (Anjyo & Hiramitsu 2003, "Highlight
// operations": translation, rotation, directional scaling), as the document runs it for the
// editor's highlight tool: the layer, the frame keyed and the values at the press.
#pragma once

#include "celform/algorithms/highlights.h"
#include "celform/model/data/object_id.h"
#include "celform/model/document/gesture.h"

#include <Eigen/Core>

#include <vector>

namespace celform::model {

/// What one step of a drag does to the highlight at the drag's frame.
enum class HighlightMotion {
    /// (a, b): the translation along the layer's du and dv as they are before its operations
    /// (HighlightTrack::translationAt) becomes the press's plus (a, b), the cursor's offset since
    /// the press; rotations earlier in the list are undone here.
    Move,
    Rotate, ///< a: degrees more (the rotation kept in [-360, 360])
    Scale, ///< a: added to the directional scaling's delta (kept in [0, 1])
};

struct HighlightDragStep {
    HighlightMotion motion = HighlightMotion::Move;
    double a = 0.0;
    double b = 0.0;
};

/// Made by HighlightEdits::beginHighlightDrag; pass it to applyHighlightDrag for each step.
struct HighlightDrag {
    ObjectId layer = 0;
    double frame = 0.0;
    Gesture gesture; ///< the drag's own: its steps merge into one undo step
    Eigen::Vector2d startTranslation = Eigen::Vector2d::Zero(); ///< translationAt(frame) at the press
    /// Working memory: the keys a step makes (every key gets an operation the drag adds).
    std::vector<algo::HighlightKey> keys;

    [[nodiscard]] bool active() const { return gesture.isOpen(); }
};

} // namespace celform::model
