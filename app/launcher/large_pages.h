// Large pages for the heavy sub-commands (issue 29): a 1920x1080 frame touches about 170 MB of
// fresh buffers, faulted in 4 KB at a time; glibc's malloc asks for transparent huge pages on its
// large allocations only when its tunable glibc.malloc.hugetlb=1 is set at start-up.
#pragma once

namespace celform::app {

/// For `render`, `analyze`, `export`, `optimize-light`, `fit`, `offsets` and `curvature`: when the
/// kernel offers transparent huge pages (not "never"), GLIBC_TUNABLES does not set
/// glibc.malloc.hugetlb yet and the host does not take freed memory back (freedMemoryGoesToHost;
/// CELFORM_LARGE_PAGES=1 restarts all the same), starts this program again (execv of
/// /proc/self/exe, the same arguments) with glibc.malloc.hugetlb=1 added; returns only when it does
/// not (another command, CELFORM_LARGE_PAGES=0, a sanitizer build, or a failed exec). Call first
/// thing in main().
void restartWithLargePagesIfUseful(int argc, char** argv);

/// Whether this system is a virtual machine whose memory balloon reports free pages to the host
/// (a virtio balloon with free page reporting under virtioDevices, /sys/bus/virtio/devices): there
/// huge pages cost more than they save (large_pages.cpp has the figures).
bool freedMemoryGoesToHost(const char* virtioDevices);

} // namespace celform::app
