// The undo command that stores a change of a key's deformation at one frame sparsely.
#pragma once

#include "celform/model/document/document_command.h"

#include <cstdint>
#include <vector>

namespace celform::model {

/// Changes some of a key's deformation at one frame, storing before and after values of just
/// those vertices (sparse). Steps of one gesture on the same key and frame merge: the union of the
/// vertices, the first "before" and the last "after" of each.
class KeyDeformationCommand : public DocumentCommand {
public:
    struct Change {
        std::vector<std::uint32_t> indices; ///< ascending
        std::vector<Eigen::Vector3f> before, after;
        std::vector<char> beforePresent, afterPresent;
    };

    KeyDeformationCommand(
        Document* doc, const QString& text, ObjectId key, int frame, Change change, GestureId gesture);

    int id() const override { return m_gesture ? kKeyDeformationMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(bool forward) override;

private:
    ObjectId m_key;
    int m_frame;
    Change m_change;
    GestureId m_gesture;
    bool m_frameExisted; ///< whether the key had a deformation at m_frame before the first step
    ChangeSet m_note; ///< reused for every notification
};

} // namespace celform::model
