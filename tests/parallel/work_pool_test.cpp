// The program's one pool of worker threads: every item is done once
// whatever number of threads is lent, a run() inside a task neither
// deadlocks nor loses work, and a task's exception reaches the caller.
#include "parallel/work_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

using fl::parallel::WorkPool;

namespace {

// Items shared through a counter, as the meshers share theirs.
void countItems(WorkPool& pool, int workers, std::vector<int>& done) {
    std::atomic<std::size_t> next{0};
    pool.run(workers, [&](int) {
        for (std::size_t i = next++; i < done.size(); i = next++)
            ++done[i];
    });
}

} // namespace

TEST(WorkPool, EveryItemIsDoneOnceWhateverTheThreads) {
    for (int threads : {1, 2, 4})
        for (int workers : {1, 2, 3, 8, 100}) {
            WorkPool pool(threads);
            std::vector<int> done(10'000, 0);
            countItems(pool, workers, done);
            EXPECT_EQ(std::accumulate(done.begin(), done.end(), 0), 10'000);
            EXPECT_EQ(*std::max_element(done.begin(), done.end()), 1);
        }
}

TEST(WorkPool, EachWorkerHasItsOwnIndexAndTheCallerIsZero) {
    WorkPool pool(3);
    std::vector<std::atomic<int>> seen(4);
    pool.run(4, [&](int w) { ++seen[std::size_t(w)]; });
    EXPECT_EQ(seen[0].load(), 1); // the caller always runs
    for (const auto& s : seen)
        EXPECT_LE(s.load(), 1);
}

TEST(WorkPool, ARunInsideATaskNeitherDeadlocksNorLosesWork) {
    WorkPool pool(2);
    std::atomic<int> total{0};
    std::atomic<int> next{0};
    pool.run(3, [&](int) {
        for (int i = next++; i < 16; i = next++) {
            std::vector<int> done(500, 0);
            countItems(pool, 3, done);
            total += std::accumulate(done.begin(), done.end(), 0);
        }
    });
    EXPECT_EQ(total.load(), 16 * 500);
}

TEST(WorkPool, ManyCallersShareThePool) {
    WorkPool pool(2);
    std::vector<std::thread> callers;
    std::atomic<int> total{0};
    for (int c = 0; c < 6; ++c)
        callers.emplace_back([&] {
            for (int round = 0; round < 20; ++round) {
                std::vector<int> done(300, 0);
                countItems(pool, 4, done);
                total += std::accumulate(done.begin(), done.end(), 0);
            }
        });
    for (std::thread& t : callers)
        t.join();
    EXPECT_EQ(total.load(), 6 * 20 * 300);
}

// Helpers spin a while before they sleep (work_pool.h): runs that follow
// one another find them spinning, runs after a pause find them asleep, and
// a pool is destroyed at once either way.
TEST(WorkPool, RunsFindHelpersSpinningOrAsleepAndLoseNothing) {
    for (int pause_us : {0, 50, 1000}) {
        WorkPool pool(3);
        int total = 0;
        for (int round = 0; round < 200; ++round) {
            std::vector<int> done(64, 0);
            countItems(pool, 4, done);
            total += std::accumulate(done.begin(), done.end(), 0);
            if (pause_us > 0 && round % 20 == 0)
                std::this_thread::sleep_for(std::chrono::microseconds(pause_us));
        }
        EXPECT_EQ(total, 200 * 64) << "pause " << pause_us << " us";
    }
    // Destroyed while its helpers spin after a run.
    for (int i = 0; i < 20; ++i) {
        WorkPool pool(2);
        std::vector<int> done(8, 0);
        countItems(pool, 3, done);
        EXPECT_EQ(std::accumulate(done.begin(), done.end(), 0), 8);
    }
}

TEST(WorkPool, AnExceptionInATaskReachesTheCaller) {
    WorkPool pool(2);
    EXPECT_THROW(pool.run(3,
                          [](int w) {
                              if (w == 0) throw std::runtime_error("caller's share failed");
                          }),
                 std::runtime_error);
    std::atomic<int> calls{0};
    EXPECT_THROW(pool.run(3,
                          [&](int w) {
                              ++calls;
                              if (w != 0) throw std::runtime_error("a helper failed");
                              while (calls.load() < 2)
                                  std::this_thread::yield();
                          }),
                 std::runtime_error);
    // The pool goes on working afterwards.
    std::vector<int> done(100, 0);
    countItems(pool, 3, done);
    EXPECT_EQ(std::accumulate(done.begin(), done.end(), 0), 100);
}
