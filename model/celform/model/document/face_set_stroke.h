// One drag of the patch brush (paper 2 shapes each highlight on one patch): the face set painted
// into, as the document runs it for the editor's patch tool and `celform patch` alike, and the
// working memory its dabs reuse, so a drag allocates once.
#pragma once

#include "celform/model/document/gesture.h"

#include <QString>

#include <cstdint>
#include <string>
#include <vector>

namespace celform::model {

/// Made by FaceSetEdits::beginFaceSetStroke; pass it to applyFaceSetStroke for each dab.
struct FaceSetStroke {
    QString target; ///< the face set's name; the first dab makes it when missing
    std::string name; ///< target, as the face sets store it
    Gesture gesture; ///< the stroke's own: its dabs merge into one undo step
    QString undoText;
    // Working memory of the dabs.
    std::vector<std::int32_t> dab; ///< the dab's faces, ascending, repeats dropped
    std::vector<std::int32_t> changed; ///< the faces the dab adds (or takes)

    [[nodiscard]] bool active() const { return gesture.isOpen(); }
};

} // namespace celform::model
