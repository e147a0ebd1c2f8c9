// Merging change descriptions: sorted unions, so that a listener can binary-search them.
#include "celform/model/document/change_set.h"

#include <algorithm>
#include <iterator>

namespace celform::model {
namespace {

/// a := a ∪ b for ascending vectors without repeats.
template <typename T> void unite(std::vector<T>& a, const std::vector<T>& b)
{
    if (b.empty())
        return;
    if (a.empty()) {
        a = b;
        return;
    }
    if (a.back() < b.front()) {
        a.insert(a.end(), b.begin(), b.end());
        return;
    }
    std::vector<T> merged;
    merged.reserve(a.size() + b.size());
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(merged));
    a = std::move(merged);
}

} // namespace

bool ChangeSet::touches(ObjectId id) const
{
    return reset || std::binary_search(ids.begin(), ids.end(), id);
}

void ChangeSet::merge(const ChangeSet& other)
{
    if (other.empty())
        return;
    if (empty()) {
        // The common case of one command per step: a plain copy, into this set's memory.
        parts = other.parts;
        reset = other.reset;
        structure = other.structure;
        offsetsOnly = other.offsetsOnly;
        ids.assign(other.ids.begin(), other.ids.end());
        frames.assign(other.frames.begin(), other.frames.end());
        vertices.assign(other.vertices.begin(), other.vertices.end());
        return;
    }
    const bool bothOffsets = offsetsOnly && other.offsetsOnly;
    // "Any vertex" on either side stays "any vertex".
    const bool anyVertex = vertices.empty() || other.vertices.empty();
    parts |= other.parts;
    reset = reset || other.reset;
    structure = structure || other.structure;
    unite(ids, other.ids);
    unite(frames, other.frames);
    offsetsOnly = bothOffsets;
    if (!bothOffsets || anyVertex)
        vertices.clear();
    else
        unite(vertices, other.vertices);
}

void ChangeSet::clear()
{
    parts = 0;
    reset = false;
    structure = false;
    offsetsOnly = false;
    ids.clear();
    frames.clear();
    vertices.clear();
}

ChangeSet ChangeSet::of(Part part, ObjectId id)
{
    ChangeSet c;
    c.parts = std::uint32_t(part);
    if (id != 0)
        c.ids.push_back(id);
    return c;
}

} // namespace celform::model
