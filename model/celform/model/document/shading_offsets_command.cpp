// ShadingOffsetsCommand: a layer of shading offsets, changed sparsely.
#include "celform/model/document/shading_offsets_command.h"

#include "celform/model/document/sparse_change.h"

namespace celform::model {

ShadingOffsetsCommand::ShadingOffsetsCommand(
    Document* doc, const QString& text, ShadingTarget target, Change change, GestureId gesture, QUndoCommand* parent)
    : DocumentCommand(doc, text, parent)
    , m_target(target)
    , m_change(std::move(change))
    , m_gesture(gesture)
{ }

void ShadingOffsetsCommand::apply(bool forward)
{
    ProjectData& data = mutableData();
    const std::size_t n = data.baseMesh ? std::size_t(data.baseMesh->vertexCount()) : 0;
    KeyViewpoint* key = m_target.isBase() ? nullptr : data.key(m_target.key);
    if (!m_target.isBase() && !key)
        return; // the key is gone
    const bool exists = forward ? m_change.existsAfter : m_change.existedBefore;
    const bool existed = shadingLayer(data, m_target) != nullptr;
    if (!exists) {
        if (key)
            key->shadingOffsetsByFrame.erase(m_target.frame);
        else
            data.shadingOffsets.clear();
    } else {
        std::vector<float>* layer = shadingLayer(data, m_target);
        if (!layer) {
            layer = key ? &key->shadingOffsetsByFrame[m_target.frame] : &data.shadingOffsets;
            layer->assign(n, 0.f);
        }
        const std::vector<float>& values = forward ? m_change.after : m_change.before;
        for (std::size_t k = 0; k < m_change.indices.size(); ++k)
            if (m_change.indices[k] < layer->size())
                (*layer)[m_change.indices[k]] = values[k];
    }
    ChangeSet change = ChangeSet::of(Part::ShadingOffsets, m_target.key);
    if (!m_target.isBase())
        change.frames = {m_target.frame};
    change.structure = key && existed != exists; // a key's set of keyed frames changed
    noteChange(change);
}

bool ShadingOffsetsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const ShadingOffsetsCommand*>(other);
    if (!o || o->m_gesture != m_gesture || o->m_target != m_target)
        return false;
    m_change = mergedSparseChange(m_change, o->m_change);
    return true;
}

} // namespace celform::model
