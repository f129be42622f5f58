#include "block_arena.h"

#include <algorithm>
#include <new>

namespace fl::mesh {

namespace {

// Chunks of 64 KiB (a block's arrays take a few KiB); a piece above a
// quarter of that gets a chunk of its own, so a chunk never wastes more
// than a quarter.
constexpr std::size_t kChunkBytes = std::size_t(64) << 10;

// The slot the calling thread takes from, and whose arena it is.
thread_local BlockArena* currentArena = nullptr;
thread_local void* currentChunks = nullptr;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kEachPieceItsOwn = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kEachPieceItsOwn = true;
#else
constexpr bool kEachPieceItsOwn = false;
#endif
#else
constexpr bool kEachPieceItsOwn = false;
#endif

} // namespace

BlockArena::BlockArena(int slots) : slots_(std::size_t(std::max(slots, 1))) {}

BlockArena::~BlockArena() {
    // Unsized deletes: clang (14) declares the sized aligned one only with
    // -fsized-deallocation, which the fuzz build does not pass.
    for (const auto& [p, shape] : pieces_)
        ::operator delete(p, std::align_val_t(shape.second));
}

BlockArena::Slot::Slot(BlockArena& arena, int w)
    : previousArena_(currentArena), previousChunks_(currentChunks) {
    Chunks& chunks = arena.slots_.at(std::size_t(w)); // (may throw: nothing set yet)
    currentArena = &arena;
    currentChunks = &chunks;
}

BlockArena::Slot::~Slot() {
    currentArena = previousArena_;
    currentChunks = previousChunks_;
}

void* BlockArena::take(Chunks& c, std::size_t bytes, std::size_t alignment) {
    if (bytes > kChunkBytes / 4) { // its own chunk, keeping the current one
        const std::size_t size = bytes + alignment;
        c.owned.push_back(std::make_unique_for_overwrite<std::byte[]>(size));
        void* p = c.owned.back().get();
        std::size_t space = size;
        return std::align(alignment, bytes, p, space);
    }
    void* p = c.next;
    std::size_t space = c.left;
    if (!c.next || !std::align(alignment, bytes, p, space)) {
        c.owned.push_back(std::make_unique_for_overwrite<std::byte[]>(kChunkBytes));
        p = c.owned.back().get();
        space = kChunkBytes;
        std::align(alignment, bytes, p, space); // a new chunk is aligned for any piece
    }
    c.next = static_cast<std::byte*>(p) + bytes;
    c.left = space - bytes;
    return p;
}

void* BlockArena::do_allocate(std::size_t bytes, std::size_t alignment) {
    if constexpr (kEachPieceItsOwn) {
        void* p = ::operator new(bytes, std::align_val_t(alignment));
        std::lock_guard lock(sharedMutex_);
        pieces_.emplace(p, std::pair{bytes, alignment});
        return p;
    }
    if (currentArena == this) return take(*static_cast<Chunks*>(currentChunks), bytes, alignment);
    std::lock_guard lock(sharedMutex_);
    return take(shared_, bytes, alignment);
}

void BlockArena::do_deallocate([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes,
                               [[maybe_unused]] std::size_t alignment) {
    // Given back with the arena; only the sanitizer's pieces go one by one.
    if constexpr (kEachPieceItsOwn) {
        {
            std::lock_guard lock(sharedMutex_);
            pieces_.erase(p);
        }
        ::operator delete(p, std::align_val_t(alignment));
    }
}

} // namespace fl::mesh
