#pragma once
// One job at a time on a worker thread, for panels that compute from the
// scene or a frame without making the interface wait: a request while a job
// runs becomes the one pending request (a newer one replaces it — stale work
// is dropped, never queued), and each result is handed to `done` on the
// owner's thread, in the order the jobs ran. A long job may be asked to stop
// (cancel(); the job reads cancelFlag()); the next job starts uncancelled.
// Destroying the worker cancels and waits for the running job; a result that
// arrives after the owner is gone is dropped. The one such worker of the
// program: the live parser, the scene player and the panels use it.
#include <QMetaObject>
#include <QObject>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace fl::platform {

template <class Input, class Result>
class NewestOnlyWorker {
  public:
    NewestOnlyWorker(QObject* owner, std::function<Result(const Input&)> work,
                     std::function<void(const Input&, Result)> done)
        : owner_(owner), work_(std::move(work)), done_(std::move(done)) {}
    ~NewestOnlyWorker() {
        *alive_ = false;
        cancel_ = true;
        if (thread_.joinable()) thread_.join();
    }
    NewestOnlyWorker(const NewestOnlyWorker&) = delete;
    NewestOnlyWorker& operator=(const NewestOnlyWorker&) = delete;

    void request(Input input) {
        std::lock_guard lock(mutex_);
        if (working_) {
            pending_ = std::move(input);
            return;
        }
        working_ = true;
        start(std::move(input));
    }

    // Working, or a request waiting.
    bool busy() const {
        std::lock_guard lock(mutex_);
        return working_ || pending_.has_value();
    }

    // Asks the running job to stop early; its result still comes to `done`.
    void cancel() { cancel_ = true; }
    // What a job reads to know it should stop (MeshOptions::cancel, say).
    const std::atomic<bool>* cancelFlag() const { return &cancel_; }

  private:
    // Called with the mutex held, or from the owner's thread after a job.
    void start(Input input) {
        if (thread_.joinable()) thread_.join(); // the last job has ended
        cancel_ = false;
        thread_ = std::thread([this, input = std::move(input), alive = alive_]() mutable {
            Result result = work_(input);
            QMetaObject::invokeMethod(
                owner_,
                [this, input = std::move(input), result = std::move(result), alive]() mutable {
                    if (!*alive) return;
                    std::optional<Input> next;
                    {
                        std::lock_guard lock(mutex_);
                        next = std::move(pending_);
                        pending_.reset();
                        working_ = next.has_value();
                    }
                    done_(input, std::move(result));
                    if (next) start(std::move(*next));
                },
                Qt::QueuedConnection);
        });
    }

    QObject* owner_;
    std::function<Result(const Input&)> work_;
    std::function<void(const Input&, Result)> done_;
    mutable std::mutex mutex_;
    std::thread thread_;
    bool working_ = false;
    std::optional<Input> pending_;
    std::atomic<bool> cancel_{false};
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace fl::platform
