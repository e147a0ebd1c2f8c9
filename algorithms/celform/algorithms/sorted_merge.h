// One walk over two ascending index lists (sparse vertex sets): the merge behind key offsets'
// replacement, undo-step merging and brush selections, written once.
#pragma once

#include <cstddef>

namespace celform::algo {

/// Visits the union of two ascending lists a and b in order: onlyA(i) for a[i] missing from b,
/// onlyB(j) for b[j] missing from a, both(i, j) when a[i] == b[j].
template <typename ListA, typename ListB, typename OnlyA, typename OnlyB, typename Both>
void mergeAscending(const ListA& a, const ListB& b, OnlyA&& onlyA, OnlyB&& onlyB, Both&& both)
{
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        if (j == b.size() || (i < a.size() && a[i] < b[j]))
            onlyA(i++);
        else if (i == a.size() || b[j] < a[i])
            onlyB(j++);
        else
            both(i++, j++);
    }
}

} // namespace celform::algo
