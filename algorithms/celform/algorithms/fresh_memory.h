// Buffers that a sequence of frames keeps (issue 29) meet their pages once, in the first frame; on
// a virtual machine each page's first touch is a trap into the kernel costing about 2 us. Asking
// the kernel to back a new buffer's pages in one call (MADV_POPULATE_WRITE, Linux 5.14) spares
// the traps.
#pragma once

#include <cstddef>
#include <vector>

namespace celform::algo {

/// Backs the whole pages of [data, data + bytes) with memory now, as writing them would; does
/// nothing where the kernel cannot (before Linux 5.14, other systems) or for less than 64 KB.
void populateForWrite(void* data, std::size_t bytes);

/// Gives v room for n elements, its new pages backed at once (populateForWrite) when it grows.
template <typename T, typename A> void reserveBacked(std::vector<T, A>& v, std::size_t n)
{
    if (v.capacity() >= n)
        return;
    v.reserve(n);
    populateForWrite(v.data(), n * sizeof(T));
}

} // namespace celform::algo
