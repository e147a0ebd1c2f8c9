// One stroke of the falloff brush (paper 1, section 3.1.2) as the document runs it for the
// editor's brush tool and `celform brush` alike: the selection made at the press, and the working
// memory its steps reuse, so a drag allocates once.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/model/data/object_id.h"
#include "celform/model/document/gesture.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace celform::model {

/// What one step of a stroke does to the selection (amounts in world units and radians).
enum class BrushMotion {
    Drag, ///< a: along the camera's right, b: along its up (the image plane, depth kept)
    Push, ///< a: along the viewing direction, positive away from the camera
    Rotate, ///< a: angle in the image plane about the picked vertex, counter-clockwise on screen
    Scale, ///< a: factor in the image plane about the picked vertex
    Smooth, ///< a: strength in [0, 1] of a step towards the one-ring average
    Relax, ///< as Smooth, in each vertex's tangent plane only: the shape (and silhouette) stays
};

struct BrushStep {
    BrushMotion motion = BrushMotion::Drag;
    double a = 0.0;
    double b = 0.0;
};

/// Made by KeyEdits::beginBrushStroke; pass it to applyBrushStroke for each step.
struct BrushStroke {
    ObjectId key = 0;
    int frame = 0;
    Gesture gesture; ///< the stroke's own: its steps merge into one undo step
    algo::ImageFrame imageFrame; ///< the camera's right, true up and forward
    algo::BrushSelection selection;
    algo::BrushSelection mirrorSelection; ///< the mirror twins; empty without mirroring
    int mirrorAxis = -1; ///< the mirror plane's axis (0-2), -1 without mirroring
    /// Mirroring was asked for but the picked vertex has no mirror image on the model (say so).
    bool twinMissing = false;
    /// The key's shape at the frame as the stroke left it (#V by 3): rotate, scale and smooth
    /// work on it, and each step updates the rows it moved.
    algo::Positions shape;
    QString undoText;
    // Working memory of the steps.
    std::vector<std::uint32_t> indices; ///< the union of both selections, ascending
    /// Where each of indices comes from: k >= 0 selection row k, k < 0 mirror row -1 - k.
    std::vector<std::int32_t> sources;
    algo::Positions moves, twinMoves, steps;
    std::vector<std::int32_t> scratch;

    [[nodiscard]] bool active() const { return gesture.isOpen() && !selection.indices.empty(); }
};

} // namespace celform::model
