// FaceSetCommand: one face set changed by the faces added and taken.
#include "celform/model/document/face_set_command.h"

#include <algorithm>
#include <iterator>

namespace celform::model {
namespace {

using Faces = std::vector<std::int32_t>;

Faces unionOf(const Faces& a, const Faces& b)
{
    Faces out;
    out.reserve(a.size() + b.size());
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

Faces minus(const Faces& a, const Faces& b)
{
    Faces out;
    out.reserve(a.size());
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

algo::FaceSet* findSet(std::vector<algo::FaceSet>& sets, const std::string& name)
{
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const algo::FaceSet& s) { return s.name == name; });
    return it == sets.end() ? nullptr : &*it;
}

} // namespace

FaceSetCommand::FaceSetCommand(Document* doc, const QString& text, std::string name, Change change, GestureId gesture)
    : DocumentCommand(doc, text)
    , m_name(std::move(name))
    , m_change(std::move(change))
    , m_gesture(gesture)
{ }

FaceSetCommand::Change FaceSetCommand::changeTo(
    const ProjectData& data, const std::string& name, const std::vector<std::int32_t>& faces)
{
    Change change;
    const auto it = std::find_if(
        data.faceSets.begin(), data.faceSets.end(), [&](const algo::FaceSet& s) { return s.name == name; });
    change.created = it == data.faceSets.end();
    const Faces none;
    const Faces& before = change.created ? none : it->faces;
    change.added = minus(faces, before);
    change.removed = minus(before, faces);
    return change;
}

void FaceSetCommand::apply(bool forward)
{
    std::vector<algo::FaceSet>& sets = mutableData().faceSets;
    algo::FaceSet* set = findSet(sets, m_name);
    ChangeSet change = ChangeSet::of(Part::FaceSets);
    change.structure = m_change.created;
    if (!forward && m_change.created) {
        if (set)
            sets.erase(sets.begin() + (set - sets.data()));
        noteChange(change);
        return;
    }
    if (!set) {
        // Created here (a redo re-creates it last, where it was made: the history is linear).
        sets.push_back({m_name, {}});
        set = &sets.back();
    }
    const Faces& add = forward ? m_change.added : m_change.removed;
    const Faces& take = forward ? m_change.removed : m_change.added;
    set->faces = minus(unionOf(set->faces, add), take);
    noteChange(change);
}

bool FaceSetCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const FaceSetCommand*>(other);
    if (!o || o->m_gesture != m_gesture || o->m_name != m_name || o->m_change.created)
        return false;
    // The net change of both: a face added then taken (or taken then added back) is no change.
    const Change& b = o->m_change;
    Change net;
    net.created = m_change.created;
    net.added = unionOf(minus(m_change.added, b.removed), minus(b.added, m_change.removed));
    net.removed = unionOf(minus(m_change.removed, b.added), minus(b.removed, m_change.added));
    m_change = std::move(net);
    // A drag that ends where it began leaves no step behind (Qt drops obsolete commands).
    setObsolete(!m_change.created && m_change.added.empty() && m_change.removed.empty());
    return true;
}

} // namespace celform::model
