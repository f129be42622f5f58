#include "work_pool.h"

#include <algorithm>

namespace fl::parallel {

WorkPool::WorkPool(int threads) {
    if (threads <= 0) threads = std::max(1, int(std::thread::hardware_concurrency()) - 1);
    threads = std::min(threads, 256);
    for (int i = 0; i < threads; ++i)
        threads_.emplace_back([this] { work(); });
}

WorkPool::~WorkPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_)
        t.join();
}

WorkPool& WorkPool::shared() {
    static WorkPool pool;
    return pool;
}

template <class Ready>
bool WorkPool::spinUntil(Ready ready) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (unsigned i = 1;; ++i) {
        if (ready()) return true;
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause(); // the core's other thread runs meanwhile
#endif
        if (i % 64 == 0 && std::chrono::steady_clock::now() > until) return false;
    }
}

void WorkPool::work() {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (queue_.empty() && !stopping_) {
            lock.unlock();
            spinUntil([this] { return queued_.load() != 0 || stopping_.load(); });
            lock.lock();
        }
        wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (stopping_) return;
        Job* job = queue_.front();
        const int w = 1 + job->claimed++;
        if (job->claimed == job->helpers) {
            queue_.pop_front();
            --queued_;
        }
        lock.unlock();
        std::exception_ptr error;
        try {
            (*job->task)(w);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        if (error && !job->error) job->error = error;
        ++job->finished;
        done_.notify_all();
    }
}

void WorkPool::run(int workers, const std::function<void(int)>& task) {
    Job job;
    job.task = &task;
    job.helpers = std::clamp(workers - 1, 0, threads());
    if (job.helpers > 0) {
        {
            std::lock_guard lock(mutex_);
            queue_.push_back(&job);
            ++queued_;
        }
        if (job.helpers == 1)
            wake_.notify_one();
        else
            wake_.notify_all();
    }
    std::exception_ptr error;
    try {
        task(0);
    } catch (...) {
        error = std::current_exception();
    }
    if (job.helpers > 0) {
        std::unique_lock lock(mutex_);
        // Helpers no thread has taken yet are not waited for: the work is done.
        if (job.claimed < job.helpers) {
            queued_ -= int(std::erase(queue_, &job));
            job.helpers = job.claimed;
        }
        if (job.finished != job.helpers) {
            lock.unlock();
            const int helpers = job.helpers;
            spinUntil([&] { return job.finished.load() == helpers; });
            lock.lock();
        }
        done_.wait(lock, [&] { return job.finished == job.helpers; });
        if (!error) error = job.error;
    }
    if (error) std::rethrow_exception(error);
}

} // namespace fl::parallel
