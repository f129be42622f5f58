#pragma once
// The program's one pool of worker threads (issue 31 §2). The meshers used
// to start and join threads of their own for every mesh — for a shape
// re-meshed as a student types, or a viewer's level of detail, the threads
// cost about as much as the work. The pool starts its threads once, on
// first use (one per core, less the caller's), and lends them to whoever
// asks.
//
// run(workers, task) calls task(w) for w = 0 .. workers-1: w = 0 on the
// calling thread, the others on pool threads as they come free, and returns
// when every call has returned. Tasks share their work through their own
// counter (an atomic "next item"), so a helper that starts late finds
// nothing left; one that has not started when the caller is done is not
// waited for at all — which also makes a run() from inside a task safe (it
// can never wait on a thread that waits on it). An exception from a task
// is rethrown to the caller (the first one; the others are dropped).
//
// Waiting spins briefly before it sleeps (kSpin): a mesher's phases come one
// after another, and a sleeping thread takes tens of microseconds to wake
// on a virtual machine (the watermelon's re-mesh at 128 on two threads,
// four phases: p50 10.7 -> 10.4 ms with the spin, alternated runs).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fl::parallel {

class WorkPool {
  public:
    // `threads` pool threads (0: one per core less one, at least one).
    explicit WorkPool(int threads = 0);
    ~WorkPool();
    WorkPool(const WorkPool&) = delete;
    WorkPool& operator=(const WorkPool&) = delete;

    // The program's pool.
    static WorkPool& shared();

    void run(int workers, const std::function<void(int)>& task);
    int threads() const { return int(threads_.size()); }

  private:
    struct Job {
        const std::function<void(int)>* task = nullptr;
        int helpers = 0; // pool calls wanted
        int claimed = 0; // of those, taken by a pool thread
        // Of those, returned: changed under the lock, read without it too
        // (a caller spinning on it).
        std::atomic<int> finished{0};
        std::exception_ptr error;
    };
    void work();
    // Spins up to kSpin until `ready` holds (read without the lock); true if
    // it did, false when it is time to sleep.
    template <class Ready>
    static bool spinUntil(Ready ready);
    static constexpr std::chrono::microseconds kSpin{200};

    std::mutex mutex_;
    std::condition_variable wake_; // pool threads: a job is queued, or stop
    std::condition_variable done_; // callers: a helper has returned
    std::deque<Job*> queue_;       // jobs with unclaimed helpers, oldest first
    std::atomic<int> queued_{0};   // queue_.size(), for spinning without the lock
    std::atomic<bool> stopping_{false};
    std::vector<std::thread> threads_;
};

} // namespace fl::parallel
