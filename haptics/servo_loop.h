#pragma once
// The servo loop (DESIGN §6; docs/haptics.md, "The servo loop"): its own
// thread at 1 kHz (up to 10 kHz), reading the device, computing the force
// against the newest snapshot of the tangible scene and sending it through
// the limits. It never waits on the window, meshing or disk: snapshots are
// handed over by pointer (taken only when the handing thread is not in the
// middle of it), status and traces are published the same way.
//
// The device frame maps into the scene by a workspace mapping: scene =
// centre + scale · device; forces keep their direction and size (newtons).
#include "force_limiter.h"
#include "force_model.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace fl::haptics {

struct WorkspaceMapping {
    field::Vec3 centre{}; // the scene point at the device's centre
    double scale = 1;     // scene units per metre of device motion
    field::Vec3 toScene(const field::Vec3& device) const {
        return field::plus(centre, field::scaled(device, scale));
    }
};

struct ServoOptions {
    double rateHz = 1000; // 1 to 10000
    WorkspaceMapping workspace;
    double rampSeconds = 2;
};

// Percentiles of the loop's period error |period - nominal| in microseconds.
struct JitterFigures {
    double p50 = 0, p99 = 0, p999 = 0, max = 0;
    std::size_t samples = 0;
};
JitterFigures jitterOf(std::vector<double> errorsMicroseconds);

struct ServoStatus {
    bool running = false;
    std::uint64_t ticks = 0;
    double measuredRateHz = 0;
    field::Vec3 tool{}, proxy{}, force{}; // scene coordinates; N
    ContactKind contact = ContactKind::None;
    ForceLimiter::Cut cut = ForceLimiter::Cut::None;
    std::uint64_t lateTicks = 0;  // ticks that started over half a period late
    std::uint64_t staleReads = 0; // ticks the device said nothing new
    bool realTime = false;        // the system granted the thread a real-time priority
};

class ServoLoop {
  public:
    ServoLoop(HapticDevice& device, ServoOptions options);
    ~ServoLoop(); // stops the thread
    ServoLoop(const ServoLoop&) = delete;
    ServoLoop& operator=(const ServoLoop&) = delete;

    void start();
    void stop();
    bool running() const { return running_; }
    double rateHz() const { return options_.rateHz; }

    // A new snapshot, from any thread; the loop takes it at its next tick and
    // ramps its forces up again (a changed scene must not jolt the hand).
    // `playing`: the scene's time runs on from the snapshot's moment with
    // real time; else it stands still there.
    void setScene(std::shared_ptr<const TangibleScene> scene, bool playing = false);

    ServoStatus status() const;
    // The loop's period errors so far (µs), for the panel and the benchmark.
    JitterFigures jitter() const;
    // Forces of the last second or so, oldest first (the panel's graph).
    std::vector<field::Vec3> recentForces() const;
    // Formulas that were not finite, once each.
    std::vector<std::string> reports() const;

  private:
    void run();

    HapticDevice& device_;
    ServoOptions options_;
    std::thread thread_;
    std::atomic<bool> running_{false}, stop_{false};

    mutable std::mutex handOver_; // the pending snapshot; the loop only try_locks it
    std::shared_ptr<const TangibleScene> pending_;
    bool pendingPlaying_ = false;
    std::atomic<bool> hasPending_{false};

    mutable std::mutex publish_; // what the loop publishes; it only try_locks it
    ServoStatus status_;
    std::vector<double> periodErrors_;
    std::vector<field::Vec3> forces_;
    std::vector<std::string> reports_;
};

} // namespace fl::haptics
