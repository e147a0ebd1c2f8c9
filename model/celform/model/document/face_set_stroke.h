// One drag of the patch brush (paper 2 shapes each highlight on one patch): the face set painted
// into, as the document runs it for the editor's patch tool and `celform patch` alike, and the
// working memory its dabs reuse, so a drag allocates once.
#pragma once

#include "celform/model/data/mirror_plane.h"
#include "celform/model/document/gesture.h"

#include "celform/algorithms/brush.h"
#include "celform/algorithms/symmetry.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace celform::model {

/// Made by FaceSetEdits::beginFaceSetStroke; pass it to applyFaceSetStroke for each dab.
struct FaceSetStroke {
    /// What a dab paints: faces into the face set, or (focal points, issue 26) the faces'
    /// importance towards value by strength, each face once per stroke.
    enum class Mode { Patch, Importance };
    Mode mode = Mode::Patch;
    float value = 1.f; ///< Importance: the importance painted towards, [0, 1]
    float strength = 1.f; ///< Importance: the share of the way there a dab takes a face, (0, 1]
    std::vector<char> touched; ///< Importance: per face, painted by this stroke already
    QString target; ///< the face set's name; the first dab makes it when missing
    std::string name; ///< target, as the face sets store it
    Gesture gesture; ///< the stroke's own: its dabs merge into one undo step
    QString undoText;
    /// Also paint the mirror image across this plane (the brush's; issue 24 item 5): each dab face's
    /// twin is the face whose centroid lies nearest the reflection of its centroid, so a model that
    /// is only roughly symmetric mirrors too.
    std::optional<algo::AxisPlane> mirrorPlane;
    algo::VertexGrid centroids; ///< the base model's face centroids, when mirroring
    double mirrorReach = 0.0; ///< how far from a reflected centroid its twin may lie
    /// The last dab asked for a mirror image but found no twin of any of its faces (say so).
    bool twinMissing = false;
    // Working memory of the dabs.
    std::vector<std::int32_t> dab; ///< the dab's faces, ascending, repeats dropped
    std::vector<std::int32_t> changed; ///< the faces the dab adds (or takes)

    [[nodiscard]] bool active() const { return gesture.isOpen(); }
};

} // namespace celform::model
