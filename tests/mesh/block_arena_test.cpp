// The mesher's block arena (block_arena.h): pieces never overlap and are
// aligned as asked, from one thread, from threads with slots of their own
// and from threads without a slot; arrays moved between blocks keep their
// buffers; a slot of one arena never serves another.
#include "mesh/block_arena.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory_resource>
#include <thread>
#include <utility>
#include <vector>

using fl::mesh::BlockArena;

namespace {

struct Piece {
    std::uintptr_t begin, end;
};

// Sizes from a byte to several chunks, with the alignments vectors ask.
std::vector<Piece> takePieces(std::pmr::memory_resource& r, unsigned char mark, unsigned seed) {
    std::vector<Piece> pieces;
    unsigned x = seed;
    for (int i = 0; i < 2000; ++i) {
        x = x * 1103515245u + 12345u;
        const std::size_t bytes = i % 97 == 0 ? 20000 + x % 200000 : 1 + x % 3000;
        const std::size_t alignment = std::size_t(1) << (x >> 8) % 7; // 1 .. 64
        void* p = r.allocate(bytes, alignment);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignment, 0u) << bytes;
        std::memset(p, mark, bytes);
        pieces.push_back(
            {reinterpret_cast<std::uintptr_t>(p), reinterpret_cast<std::uintptr_t>(p) + bytes});
    }
    return pieces;
}

void expectNoOverlap(std::vector<Piece> pieces) {
    std::sort(pieces.begin(), pieces.end(),
              [](const Piece& a, const Piece& b) { return a.begin < b.begin; });
    for (std::size_t i = 1; i < pieces.size(); ++i)
        ASSERT_LE(pieces[i - 1].end, pieces[i].begin) << "pieces " << i - 1 << " and " << i;
}

void expectMarked(const std::vector<Piece>& pieces, unsigned char mark) {
    for (const Piece& p : pieces)
        for (std::uintptr_t a = p.begin; a < p.end; a += 61)
            ASSERT_EQ(*reinterpret_cast<const unsigned char*>(a), mark);
}

} // namespace

TEST(BlockArena, PiecesAreAlignedAndNeverOverlapOnOneThread) {
    BlockArena arena(1);
    const BlockArena::Slot slot(arena, 0);
    const std::vector<Piece> pieces = takePieces(arena, 7, 1);
    expectNoOverlap(pieces);
    expectMarked(pieces, 7);
}

TEST(BlockArena, ThreadsWithSlotsAndWithoutNeverShareMemory) {
    BlockArena arena(3);
    std::vector<std::vector<Piece>> pieces(5);
    std::vector<std::thread> threads;
    for (int t = 0; t < 5; ++t)
        threads.emplace_back([&, t] {
            // threads 0-2 with a slot each, 3 and 4 through the shared one
            if (t < 3) {
                const BlockArena::Slot slot(arena, t);
                pieces[std::size_t(t)] = takePieces(arena, static_cast<unsigned char>(t + 1), t);
            } else {
                pieces[std::size_t(t)] = takePieces(arena, static_cast<unsigned char>(t + 1), t);
            }
        });
    for (std::thread& t : threads)
        t.join();
    std::vector<Piece> all;
    for (std::size_t t = 0; t < pieces.size(); ++t) {
        expectMarked(pieces[t], static_cast<unsigned char>(t + 1)); // no one wrote over them
        all.insert(all.end(), pieces[t].begin(), pieces[t].end());
    }
    expectNoOverlap(all);
}

TEST(BlockArena, ArraysMovedBetweenBlocksKeepTheirBuffers) {
    BlockArena arena(2);
    const BlockArena::Slot slot(arena, 1);
    std::pmr::vector<int> a(&arena);
    a.assign({1, 2, 3, 4});
    const int* data = a.data();
    std::pmr::vector<int> b(&arena);
    b = std::move(a); // the same arena: the buffer moves, not the elements
    EXPECT_EQ(b.data(), data);
    std::pmr::vector<int> c(std::move(b));
    EXPECT_EQ(c.data(), data);
    EXPECT_EQ(c, (std::pmr::vector<int>{1, 2, 3, 4}));
    EXPECT_TRUE(arena.is_equal(arena));
    BlockArena other(1);
    EXPECT_FALSE(arena.is_equal(other));
}

TEST(BlockArena, ASlotOfOneArenaDoesNotServeAnother) {
    BlockArena first(1), second(1);
    const BlockArena::Slot slot(first, 0);
    std::pmr::vector<double> fromFirst(1000, 1.0, &first);
    {
        // Nested slots restore the one before them.
        const BlockArena::Slot inner(second, 0);
        std::pmr::vector<double> fromSecond(1000, 2.0, &second);
        EXPECT_EQ(fromSecond.back(), 2.0);
    }
    std::pmr::vector<double> again(1000, 3.0, &second); // second's shared slot
    std::pmr::vector<double> more(1000, 4.0, &first);
    EXPECT_EQ(fromFirst.front(), 1.0);
    EXPECT_EQ(again.front(), 3.0);
    EXPECT_EQ(more.front(), 4.0);
}

TEST(BlockArena, AnOutOfRangeSlotIsRefusedAndChangesNothing) {
    BlockArena arena(2);
    EXPECT_THROW(BlockArena::Slot(arena, 2), std::out_of_range);
    // The thread has no slot afterwards: it takes from the shared one.
    std::pmr::vector<int> v(100, 5, &arena);
    EXPECT_EQ(v.back(), 5);
}
