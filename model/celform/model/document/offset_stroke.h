// One stroke of the shading-offset brush (paper 3, section 4.3: O_v painted by hand), as the
// document runs it for the editor's tool.
#pragma once

#include "celform/algorithms/brush.h"
#include "celform/algorithms/shading_offsets.h"
#include "celform/model/data/camera.h"
#include "celform/model/data/mirror_plane.h"
#include "celform/model/data/shading_layers.h"
#include "celform/model/document/gesture.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace celform::model {

/// What a dab does to the offsets under it, weighted by the falloff f = (1 - d/r)^2.
enum class OffsetPaintMode {
    Add, ///< O += strength f
    Subtract, ///< O -= strength f
    Smooth, ///< O += f / 2 (mean of the neighbours - O)
    Erase, ///< O *= 1 - f (towards zero)
};

struct OffsetBrush {
    OffsetPaintMode mode = OffsetPaintMode::Add;
    double radius = 0.1; ///< model units, on the shape painted on
    double strength = 0.05; ///< offset added at the centre by one dab (Add, Subtract)
    /// Also paint the mirror image across this plane (ProjectData::mirrorPlane, or Off).
    MirrorPlane mirror = MirrorPlane::Off;
};

/// Made by ShadingEdits::beginOffsetStroke; pass it to applyOffsetStroke for each dab.
struct OffsetStroke {
    ShadingTarget target;
    OffsetBrush brush;
    Gesture gesture; ///< the stroke's own: its steps merge into one undo step
    QString undoText;
    algo::Positions shape; ///< the shape painted on (the one shown), #V by 3
    algo::VertexGrid grid; ///< over shape
    algo::VertexNeighbours neighbours; ///< for Smooth
    std::vector<float> values; ///< the target's values as the stroke left them (#V)
    std::optional<algo::AxisPlane> mirrorPlane; ///< the brush's plane on the base model
    double mirrorReach = 0.0; ///< how far from the reflected centre its twin may lie
    /// The last dab asked for a mirror image but the model has none there (say so).
    bool twinMissing = false;
    // Working memory of the dabs.
    std::vector<std::uint32_t> indices, mirrorIndices, merged;
    std::vector<float> distances, mirrorDistances, falloff, after;

    [[nodiscard]] bool active() const { return gesture.isOpen(); }
};

} // namespace celform::model
