// KeyDeformationCommand: a key's deformation at one frame, changed sparsely.
#include "celform/model/document/key_deformation_command.h"

#include "celform/algorithms/sorted_merge.h"

namespace celform::model {

KeyDeformationCommand::KeyDeformationCommand(
    Document* doc, const QString& text, ObjectId key, int frame, Change change, GestureId gesture)
    : DocumentCommand(doc, text)
    , m_key(key)
    , m_frame(frame)
    , m_change(std::move(change))
    , m_gesture(gesture)
{
    const KeyViewpoint* k = doc->data().key(key);
    m_frameExisted = k && k->offsetsByFrame.count(frame) > 0;
    m_note.parts = std::uint32_t(Part::Keys);
    m_note.offsetsOnly = true;
    m_note.ids = {key};
    m_note.frames = {frame};
}

void KeyDeformationCommand::apply(bool forward)
{
    KeyViewpoint* key = mutableData().key(m_key);
    if (!key)
        return;
    const bool existed = key->offsetsByFrame.count(m_frame) > 0;
    SparseOffsets& offsets = key->offsetsByFrame[m_frame];
    offsets.assign(m_change.indices, forward ? m_change.after : m_change.before,
        forward ? m_change.afterPresent : m_change.beforePresent);
    if (!forward && !m_frameExisted && offsets.indices.empty())
        key->offsetsByFrame.erase(m_frame); // undo leaves the key exactly as it was
    m_note.vertices.assign(m_change.indices.begin(), m_change.indices.end());
    m_note.structure = existed != (key->offsetsByFrame.count(m_frame) > 0);
    noteChange(m_note);
}

bool KeyDeformationCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const KeyDeformationCommand*>(other);
    if (!o || o->m_gesture != m_gesture || o->m_key != m_key || o->m_frame != m_frame)
        return false;
    const Change& b = o->m_change;
    if (b.indices == m_change.indices) {
        // The same vertices again (a stroke's steps): take their "after" in place, no allocation.
        m_change.after = b.after;
        m_change.afterPresent = b.afterPresent;
        return true;
    }
    // Union of the two vertex sets: our "before" where we have one, their "after" where they do.
    Change merged;
    const Change& a = m_change;
    auto add = [&merged](const Change& first, std::size_t i, const Change& last, std::size_t j) {
        merged.indices.push_back(first.indices[i]);
        merged.before.push_back(first.before[i]);
        merged.beforePresent.push_back(first.beforePresent[i]);
        merged.after.push_back(last.after[j]);
        merged.afterPresent.push_back(last.afterPresent[j]);
    };
    algo::mergeAscending(
        a.indices, b.indices, [&](std::size_t i) { add(a, i, a, i); }, [&](std::size_t j) { add(b, j, b, j); },
        [&](std::size_t i, std::size_t j) { add(a, i, b, j); });
    m_change = std::move(merged);
    return true;
}

} // namespace celform::model
