// Buffers backed when they grow (fresh_memory.h, issue 29): their pages are resident before the
// first write, what they held is kept, and ranges too small or not page-aligned are handled.
#include "celform/algorithms/fresh_memory.h"

#include <QTest>

#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

using namespace celform::algo;

namespace {

#if defined(__linux__)
/// How many of the whole pages in [data, data + bytes) are resident (mincore).
std::size_t residentPages(const void* data, std::size_t bytes, std::size_t* pages)
{
    const auto page = std::uintptr_t(::sysconf(_SC_PAGESIZE));
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
    *pages = end > begin ? (end - begin) / page : 0;
    std::vector<unsigned char> flags(*pages);
    if (*pages == 0 || ::mincore(reinterpret_cast<void*>(begin), end - begin, flags.data()) != 0)
        return 0;
    std::size_t resident = 0;
    for (const unsigned char f : flags)
        resident += f & 1u;
    return resident;
}
#endif

} // namespace

class TestFreshMemory : public QObject {
    Q_OBJECT

private slots:
    void grownBufferIsBacked()
    {
        std::vector<float> v = {1.f, 2.f, 3.f};
        const std::size_t n = std::size_t(16) << 20; // 64 MB of floats: a fresh mapping
        reserveBacked(v, n);
        QVERIFY(v.capacity() >= n);
        QCOMPARE(v.size(), std::size_t(3));
        QCOMPARE(v[2], 3.f);
#if defined(__linux__)
        std::size_t pages = 0;
        const std::size_t resident = residentPages(v.data(), n * sizeof(float), &pages);
        // A kernel before 5.14 refuses MADV_POPULATE_WRITE: nothing is backed, which is allowed.
        if (resident == 0)
            QSKIP("this kernel does not populate (MADV_POPULATE_WRITE needs Linux 5.14)");
        QCOMPARE(resident, pages);
#endif
        // Room enough already: nothing moves.
        const float* before = v.data();
        reserveBacked(v, 10);
        QCOMPARE(v.data(), before);
    }

    void oddRangesAreHandled()
    {
        populateForWrite(nullptr, 1 << 20);
        std::vector<unsigned char> small(100);
        populateForWrite(small.data(), small.size());
        std::vector<unsigned char> big(std::size_t(1) << 20);
        populateForWrite(big.data() + 3, big.size() - 7); // not page-aligned at either end
        big[5] = 7;
        QCOMPARE(int(big[5]), 7);
    }
};

QTEST_APPLESS_MAIN(TestFreshMemory)
#include "test_fresh_memory.moc"
