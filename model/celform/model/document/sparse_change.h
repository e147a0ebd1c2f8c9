// The merge of two sparse value changes of one gesture (shading offsets per vertex, face values
// per face), written once: the union of the indices, the first "before" and the last "after".
#pragma once

#include "celform/algorithms/sorted_merge.h"

#include <cstddef>

namespace celform::model {

/// Change has ascending indices with before and after values at the same places, and flags of
/// existence (existedBefore, existsAfter): the merge takes the first's before and the last's after.
template <typename Change> Change mergedSparseChange(const Change& a, const Change& b)
{
    Change merged;
    const std::size_t reserve = a.indices.size() + b.indices.size();
    merged.indices.reserve(reserve);
    merged.before.reserve(reserve);
    merged.after.reserve(reserve);
    auto add = [&merged](auto index, float before, float after) {
        merged.indices.push_back(index);
        merged.before.push_back(before);
        merged.after.push_back(after);
    };
    // Our "before" where we have one, their "after" where they do.
    algo::mergeAscending(
        a.indices, b.indices, [&](std::size_t i) { add(a.indices[i], a.before[i], a.after[i]); },
        [&](std::size_t j) { add(b.indices[j], b.before[j], b.after[j]); },
        [&](std::size_t i, std::size_t j) { add(a.indices[i], a.before[i], b.after[j]); });
    merged.existedBefore = a.existedBefore;
    merged.existsAfter = b.existsAfter;
    return merged;
}

} // namespace celform::model
