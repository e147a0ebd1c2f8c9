#include "celform/algorithms/fresh_memory.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace celform::algo {

void populateForWrite(void* data, std::size_t bytes)
{
#if defined(__linux__)
    constexpr std::size_t kSmallest = std::size_t(64) << 10;
#ifndef MADV_POPULATE_WRITE
    constexpr int MADV_POPULATE_WRITE = 23; // Linux 5.14; older headers lack it
#endif
    if (!data || bytes < kSmallest)
        return;
    static const auto page = std::uintptr_t(::sysconf(_SC_PAGESIZE));
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
    if (end > begin)
        (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE); // EINVAL before 5.14
#else
    (void)data;
    (void)bytes;
#endif
}

} // namespace celform::algo
