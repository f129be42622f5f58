#include "memory_policy.h"

#include <cstdlib> // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace fl::platform {

bool keepFreedMemoryMapped() {
#if defined(__GLIBC__)
    // Chunks below 32 MiB (glibc's largest mmap threshold) come from the
    // heaps, which are trimmed only when 256 MiB lie free at their top.
    constexpr int kMapAbove = 32 << 20;
    constexpr int kTrimAbove = 256 << 20;
    return mallopt(M_MMAP_THRESHOLD, kMapAbove) == 1 && mallopt(M_TRIM_THRESHOLD, kTrimAbove) == 1;
#else
    return false;
#endif
}

} // namespace fl::platform
