#pragma once
// The memory of one mesh call's blocks (dual_contouring.cpp): each block
// keeps six small arrays from sampling until its share is copied into the
// mesh, a thousand blocks a re-mesh at resolution 128 — and malloc and free
// took about a twentieth of the mesher's time (perf, watermelon at 128,
// two threads), half of the frees from another thread than the malloc.
// Here a thread takes memory from chunks of its own in bump order, without
// a lock; nothing is given back one piece at a time, everything when the
// arena goes (the mesh call's end: the blocks are gone by then).
//
// A std::pmr::memory_resource, so the blocks' arrays stay std::pmr::vector;
// every array of one mesh uses the one arena, so moving blocks (sorting
// them) moves their arrays' buffers, never the elements. Which chunks a
// thread takes from is set by a Slot while it works on blocks; a thread
// without one takes from a shared slot under a lock.
//
// Built with AddressSanitizer, every piece is its own operator new and
// delete, so the sanitizer still sees each array's bounds (the arena still
// deletes, when it goes, the pieces nobody gave back).
#include <cstddef>
#include <memory>
#include <memory_resource>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fl::mesh {

class BlockArena final : public std::pmr::memory_resource {
  public:
    // Memory for `slots` threads at once (a parallelFor's workers).
    explicit BlockArena(int slots);
    ~BlockArena() override;
    BlockArena(const BlockArena&) = delete;
    BlockArena& operator=(const BlockArena&) = delete;

    // While it lives, the calling thread takes from slot `w` (0 <= w <
    // slots): one thread at a time per slot, as parallelFor's worker index
    // guarantees.
    class Slot {
      public:
        Slot(BlockArena& arena, int w);
        ~Slot();
        Slot(const Slot&) = delete;
        Slot& operator=(const Slot&) = delete;

      private:
        BlockArena* previousArena_;
        void* previousChunks_;
    };

  private:
    // A thread's memory: the chunks it took, and the free end of the last.
    struct alignas(64) Chunks { // threads' slots on separate cache lines
        std::vector<std::unique_ptr<std::byte[]>> owned;
        std::byte* next = nullptr;
        std::size_t left = 0;
    };
    void* do_allocate(std::size_t bytes, std::size_t alignment) override;
    void do_deallocate(void* p, std::size_t bytes, std::size_t alignment) override;
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
        return this == &other;
    }
    static void* take(Chunks& c, std::size_t bytes, std::size_t alignment);

    std::vector<Chunks> slots_;
    Chunks shared_;
    std::mutex sharedMutex_; // shared_, and the sanitizer's pieces
    // Built with AddressSanitizer: each piece not yet given back, with its
    // size and alignment.
    std::unordered_map<void*, std::pair<std::size_t, std::size_t>> pieces_;
};

} // namespace fl::mesh
