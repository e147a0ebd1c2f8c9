// Measured on the dragon at 1920x1080 (farm-bench, medians): a single-frame `celform render` 456 ->
// 352 ms, ten frames with --threads 2 1.65 -> 1.49 s; the restart itself costs about 9 ms (a whole
// `celform --version`). Page faults were 26 % of the single frame's profile.
#include "launcher/large_pages.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

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

} // namespace

void restartWithLargePagesIfUseful(int argc, char** argv)
{
#ifdef CELFORM_SANITIZED
    (void)argc;
    (void)argv;
#else
    if (argc < 2 || !isHeavyCommand(argv[1]))
        return;
    if (const char* opt = std::getenv("CELFORM_LARGE_PAGES"); opt && std::strcmp(opt, "0") == 0)
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
