// The undo command that stores a change of a layer of shading offsets sparsely.
#pragma once

#include "celform/model/data/shading_layers.h"
#include "celform/model/document/document_command.h"

#include <cstdint>
#include <vector>

namespace celform::model {

/// The layer a target names, or null when it holds nothing (the base's empty vector, a key
/// without values at the frame, a key that is gone). Const data gives a const layer.
template <typename Data> auto shadingLayer(Data& data, const ShadingTarget& target) -> decltype(&data.shadingOffsets)
{
    if (target.isBase())
        return data.shadingOffsets.empty() ? nullptr : &data.shadingOffsets;
    auto* key = data.key(target.key);
    if (!key)
        return nullptr;
    const auto it = key->shadingOffsetsByFrame.find(target.frame);
    return it == key->shadingOffsetsByFrame.end() ? nullptr : &it->second;
}

/// Changes some values of a layer of shading offsets (the base, or a key's at a frame), storing
/// before and after values of just those vertices (sparse), and whether the layer existed before
/// and exists after (a layer made here is stored whole: the command then holds every vertex).
/// Steps of one gesture on the same target merge: the union of the vertices, the first "before"
/// and the last "after" of each.
class ShadingOffsetsCommand : public DocumentCommand {
public:
    struct Change {
        std::vector<std::uint32_t> indices; ///< ascending
        std::vector<float> before, after;
        bool existedBefore = false;
        bool existsAfter = true;
    };
    ShadingOffsetsCommand(Document* doc, const QString& text, ShadingTarget target, Change change, GestureId gesture,
        QUndoCommand* parent = nullptr);

    int id() const override { return m_gesture ? kShadingOffsetsMergeId : -1; }
    bool mergeWith(const QUndoCommand* other) override;

protected:
    void apply(bool forward) override;

private:
    ShadingTarget m_target;
    Change m_change;
    GestureId m_gesture;
};

} // namespace celform::model
