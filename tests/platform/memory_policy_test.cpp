// Freed memory stays mapped (platform/memory_policy.h): a chunk the size of a
// mesh's vertices, freed, is still the process's to reuse, not the kernel's.
#include "platform/memory_policy.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FL_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define FL_ASAN 1
#endif

TEST(MemoryPolicy, AFreedMeshSizedChunkStaysMapped) {
#if !defined(__GLIBC__) || defined(FL_ASAN)
    GTEST_SKIP() << "glibc's own malloc only";
#else
    ASSERT_TRUE(fl::platform::keepFreedMemoryMapped());
    constexpr std::size_t kBytes = 8 << 20; // glibc alone would map it apart and unmap it on free
    void* chunk = std::malloc(kBytes);
    ASSERT_NE(chunk, nullptr);
    std::memset(chunk, 1, kBytes);
    const std::size_t mappedApart = mallinfo2().hblkhd;
    EXPECT_LT(mappedApart, kBytes) << "the chunk came from mmap, not the heap";
    std::free(chunk);
    EXPECT_GE(mallinfo2().fordblks, kBytes) << "the freed chunk went back to the kernel";
#endif
}
