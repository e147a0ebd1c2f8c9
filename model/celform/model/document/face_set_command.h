// The undo command that changes one face set (a highlight patch) by the faces it adds and takes.
#pragma once

#include "celform/model/document/document_command.h"

#include <cstdint>
#include <string>
#include <vector>

namespace celform::model {

/// Adds faces to and takes faces from one named face set, creating it when it is missing. It
/// stores only those faces, not the set (a paint dab's cost follows the dab); the dabs of one
/// gesture on the same set merge into the net change of the drag.
class FaceSetCommand : public DocumentCommand {
public:
    struct Change {
        std::vector<std::int32_t> added; ///< ascending, none of them in the set before
        std::vector<std::int32_t> removed; ///< ascending, all of them in the set before
        bool created = false; ///< the set did not exist before (undo removes it)
    };

    FaceSetCommand(Document* doc, const QString& text, std::string name, Change change, GestureId gesture);

    /// The change that turns the set named name (missing: empty) into faces (ascending, unique).
    [[nodiscard]] static Change changeTo(
        const ProjectData& data, const std::string& name, const std::vector<std::int32_t>& faces);

    /// What the step stores: the faces added and taken, not the set.
    [[nodiscard]] const Change& change() const { return m_change; }

    int id() const override { return m_gesture ? kFaceSetMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(bool forward) override;

private:
    std::string m_name;
    Change m_change;
    GestureId m_gesture;
};

} // namespace celform::model
