#pragma once
// How the process keeps the memory it frees. Meshing after an edit frees and
// allocates tens of megabytes (the blocks' vertices, then the mesh); glibc's
// malloc handed most of it back to the kernel each time (trimmed heaps,
// unmapped chunks), and every page came back as a page fault on first touch:
// about 800 a mesh for the watermelon at 128, 1.2 ms of its 15 ms on 2 cores
// (`bench remesh`, measured with `/usr/bin/time -v`). Freed memory is kept
// mapped up to a bound instead; the peak size is unchanged.
namespace fl::platform {

// Call once at the start of a program, before its threads. Returns whether
// the C library took the setting (false where it has no such control).
bool keepFreedMemoryMapped();

} // namespace fl::platform
