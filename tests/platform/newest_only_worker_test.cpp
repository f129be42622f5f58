// The one "newest job only" worker (platform/newest_only_worker.h): requests
// made while a job runs collapse to the newest, results come back on the
// owner's thread in the order the jobs ran, a running job can be asked to
// stop, and destroying the worker stops and waits for it.
#include "platform/newest_only_worker.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QObject>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace {

QCoreApplication& app() {
    static int argc = 1;
    static char name[] = "newest_only_worker_test";
    static char* argv[] = {name, nullptr};
    static QCoreApplication a(argc, argv);
    return a;
}

// Runs the owner's event loop until `done` or 10 s.
template <class Done>
bool spinUntil(Done done) {
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < 10'000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return done();
}

} // namespace

TEST(NewestOnlyWorker, RequestsWhileAJobRunsCollapseToTheNewest) {
    app();
    QObject owner;
    std::atomic<bool> release{false};
    std::vector<int> ran, delivered;
    fl::platform::NewestOnlyWorker<int, int> worker(
        &owner,
        [&](const int& n) {
            while (n == 1 && !release) // the first job waits to be let go
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            return n * 10;
        },
        [&](const int& n, int result) {
            ran.push_back(n);
            delivered.push_back(result);
        });
    worker.request(1);
    for (int n = 2; n <= 5; ++n)
        worker.request(n); // 2, 3 and 4 are stale before they start
    EXPECT_TRUE(worker.busy());
    release = true;
    ASSERT_TRUE(spinUntil([&] { return !worker.busy() && delivered.size() == 2; }));
    EXPECT_EQ(ran, (std::vector<int>{1, 5}));
    EXPECT_EQ(delivered, (std::vector<int>{10, 50}));
}

TEST(NewestOnlyWorker, ARunningJobCanBeAskedToStopAndTheNextStartsUncancelled) {
    app();
    QObject owner;
    std::vector<bool> stoppedEarly;
    fl::platform::NewestOnlyWorker<int, bool>* self = nullptr;
    fl::platform::NewestOnlyWorker<int, bool> worker(
        &owner,
        [&](const int& n) {
            // Job 1 runs until told to stop; job 2 must not see job 1's stop.
            QElapsedTimer t;
            t.start();
            while (!self->cancelFlag()->load() && t.elapsed() < (n == 1 ? 10'000 : 50))
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            return self->cancelFlag()->load();
        },
        [&](const int&, bool cancelled) { stoppedEarly.push_back(cancelled); });
    self = &worker;
    worker.request(1);
    worker.request(2);
    worker.cancel();
    ASSERT_TRUE(spinUntil([&] { return stoppedEarly.size() == 2; }));
    EXPECT_EQ(stoppedEarly, (std::vector<bool>{true, false}));
}

TEST(NewestOnlyWorker, DestroyingItStopsTheJobAndDropsItsResult) {
    app();
    int delivered = 0;
    std::atomic<bool> sawStop{false};
    {
        QObject owner;
        fl::platform::NewestOnlyWorker<int, int>* self = nullptr;
        fl::platform::NewestOnlyWorker<int, int> worker(
            &owner,
            [&](const int&) {
                while (!self->cancelFlag()->load())
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                sawStop = true;
                return 0;
            },
            [&](const int&, int) { ++delivered; });
        self = &worker;
        worker.request(1);
    } // joins: would hang here if the job were not told to stop
    QCoreApplication::processEvents();
    EXPECT_TRUE(sawStop);
    EXPECT_EQ(delivered, 0);
}
