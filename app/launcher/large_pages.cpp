// Measured on the dragon at 1920x1080 (farm-bench, medians), where the host keeps the guest's
// memory: a single-frame `celform render` 456 -> 352 ms, ten frames with --threads 2 1.65 -> 1.49
// s; the restart itself costs about 9 ms (a whole `celform --version`). Page faults were 26 % of the
// single frame's profile. Where the host takes freed memory back, the huge pages are left alone
// (freedMemoryGoesToHost).
#include "launcher/large_pages.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <dirent.h>
#include <unistd.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define CELFORM_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CELFORM_SANITIZED 1
#endif

namespace celform::app {
namespace {

bool isHeavyCommand(const char* name)
{
    static const char* const kHeavy[]
        = {"render", "analyze", "export", "optimize-light", "fit", "offsets", "curvature"};
    for (const char* heavy : kHeavy)
        if (std::strcmp(name, heavy) == 0)
            return true;
    return false;
}

/// Whether the kernel gives transparent huge pages to a region that asks (always or madvise).
bool kernelOffersHugePages()
{
    std::FILE* f = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f)
        return false;
    char text[128] = {};
    const std::size_t n = std::fread(text, 1, sizeof(text) - 1, f);
    std::fclose(f);
    text[n] = '\0';
    return std::strstr(text, "[always]") != nullptr || std::strstr(text, "[madvise]") != nullptr;
}

/// The first line of a small file, empty when it cannot be read.
std::string firstLine(const std::string& path)
{
    std::string text;
    if (std::FILE* f = std::fopen(path.c_str(), "r")) {
        char buffer[256] = {};
        if (std::fgets(buffer, sizeof(buffer), f))
            text = buffer;
        std::fclose(f);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
        text.pop_back();
    return text;
}

} // namespace

bool freedMemoryGoesToHost(const char* virtioDevices)
{
    // A virtio memory balloon (device id 5) with free page reporting (feature bit 5,
    // VIRTIO_BALLOON_F_REPORTING, in the virtio 1.2 specification, 5.5.3) whose driver is bound:
    // the guest hands its free blocks of 2^page_reporting_order pages back to the host, which
    // unmaps them. A transparent huge page is such a block, so it comes unbacked nearly every time,
    // and the host faults its 512 small pages in while the guest clears it. Measured on a
    // virtual machine with it (farm-bench, pairs of runs, the dragon at 1920x1080): 10 frames with
    // --threads 1 took 1.78 s without the huge pages against 2.66 s with them, system time 0.15 s
    // against 1.02 s; with --threads 2, 1.11 s against 1.17 s (0.95-1.46 s); one frame 0.29 s
    // against 0.24 s.
    DIR* dir = ::opendir(virtioDevices);
    if (!dir)
        return false;
    bool found = false;
    while (const dirent* entry = ::readdir(dir)) {
        if (entry->d_name[0] == '.')
            continue;
        const std::string device = std::string(virtioDevices) + "/" + entry->d_name;
        if (firstLine(device + "/device") != "0x0005")
            continue;
        const std::string features = firstLine(device + "/features");
        char driver[256] = {};
        const bool bound = ::readlink((device + "/driver").c_str(), driver, sizeof(driver) - 1) > 0;
        if (bound && features.size() > 5 && features[5] == '1') {
            found = true;
            break;
        }
    }
    ::closedir(dir);
    return found;
}

void restartWithLargePagesIfUseful(int argc, char** argv)
{
#ifdef CELFORM_SANITIZED
    (void)argc;
    (void)argv;
#else
    if (argc < 2 || !isHeavyCommand(argv[1]))
        return;
    // CELFORM_LARGE_PAGES: 0 never, 1 always (where the kernel offers them), unset: unless the
    // host takes freed memory back.
    const char* opt = std::getenv("CELFORM_LARGE_PAGES");
    if (opt && std::strcmp(opt, "0") == 0)
        return;
    const bool forced = opt && std::strcmp(opt, "1") == 0;
    if (!forced && freedMemoryGoesToHost("/sys/bus/virtio/devices"))
        return;
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr)
        return; // already set, by the user or by the restart
    if (!kernelOffersHugePages())
        return;
    std::string value = tunables && *tunables ? std::string(tunables) + ":" : std::string();
    value += "glibc.malloc.hugetlb=1";
    if (::setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0)
        return;
    ::execv("/proc/self/exe", argv);
    // The exec failed (no /proc): go on as we are, without the tunable in the environment.
    if (tunables)
        ::setenv("GLIBC_TUNABLES", tunables, 1);
    else
        ::unsetenv("GLIBC_TUNABLES");
#endif
}

} // namespace celform::app
