#include "servo_loop.h"

#include "measure/percentiles.h"

#include <algorithm>
#include <cmath>
#include <pthread.h>
#include <sched.h>

namespace fl::haptics {

JitterFigures jitterOf(std::vector<double> e) {
    JitterFigures j;
    j.samples = e.size();
    const measure::Spread s = measure::spreadOf(std::move(e));
    j.p50 = s.p50;
    j.p99 = s.p99;
    j.p999 = s.p999;
    j.max = s.max;
    return j;
}

ServoLoop::ServoLoop(HapticDevice& device, ServoOptions options)
    : device_(device), options_(options) {
    options_.rateHz = std::clamp(options_.rateHz, 1.0, 10000.0);
}

ServoLoop::~ServoLoop() {
    stop();
}

void ServoLoop::start() {
    if (running_) return;
    stop_ = false;
    running_ = true;
    thread_ = std::thread([this] { run(); });
}

void ServoLoop::stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    running_ = false;
}

void ServoLoop::setScene(std::shared_ptr<const TangibleScene> scene, bool playing) {
    std::lock_guard lock(handOver_);
    pending_ = std::move(scene);
    pendingPlaying_ = playing;
    hasPending_ = true;
}

ServoStatus ServoLoop::status() const {
    std::lock_guard lock(publish_);
    ServoStatus s = status_;
    s.running = running_;
    return s;
}

JitterFigures ServoLoop::jitter() const {
    std::lock_guard lock(publish_);
    return jitterOf(periodErrors_);
}

std::vector<field::Vec3> ServoLoop::recentForces() const {
    std::lock_guard lock(publish_);
    const std::size_t keep = std::size_t(options_.rateHz);
    return {forces_.size() > keep ? forces_.end() - std::ptrdiff_t(keep) : forces_.begin(),
            forces_.end()};
}

std::vector<std::string> ServoLoop::reports() const {
    std::lock_guard lock(publish_);
    return reports_;
}

namespace {

// A real-time priority where the system grants one (a user in the `realtime`
// group, or with CAP_SYS_NICE); elsewhere the loop runs as it can.
bool askForRealTime() {
#ifdef __linux__
    sched_param p{};
    p.sched_priority = 20;
    return pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
#else
    return false;
#endif
}

} // namespace

void ServoLoop::run() {
    using Clock = std::chrono::steady_clock;
    const bool realTime = askForRealTime();
    const DeviceLimits limits = device_.limits();
    // Stiffness and damping are per scene unit: the workspace scale divides them.
    ForceSettings settings = settingsFor(limits, options_.rateHz);
    const double scale = options_.workspace.scale > 0 ? options_.workspace.scale : 1;
    settings.stiffness /= scale;
    settings.damping /= scale;
    settings.contactDamping /= scale;
    ForceModel model(settings);
    LimiterSettings ls;
    ls.maxForce = limits.maxForce;
    ls.rampSeconds = options_.rampSeconds;
    ls.maxChangePerTick = limits.maxForce / 4; // about OpenHaptics' impulse limit at 8 N
    ls.staleSeconds = std::max(0.005, 5 / options_.rateHz);
    ForceLimiter limiter(ls);

    const auto period = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(1 / options_.rateHz));
    const auto spinMargin = std::min<Clock::duration>(std::chrono::microseconds(150), period / 4);
    const auto begin = Clock::now();
    auto seconds = [&](Clock::time_point t) {
        return std::chrono::duration<double>(t - begin).count();
    };
    limiter.restartRamp(0); // a device connects
    animation::Instant sceneMoment{};
    bool playing = false;
    Clock::time_point sceneSince = begin;
    Clock::time_point deadline = begin, previous = begin;
    double lastFresh = 0;
    std::uint64_t ticks = 0, late = 0, stale = 0;
    std::vector<double> errors;                            // since the last publication
    std::vector<field::Vec3> forces;                       // since the last publication
    const std::size_t keep = std::size_t(options_.rateHz); // about a second
    errors.reserve(1024);
    forces.reserve(1024);
    ServoStatus local;

    while (!stop_) {
        deadline += period;
        // Sleep until just before the deadline, then spin to it: the kernel
        // wakes a sleeper tens of microseconds late, a spinning thread is on
        // time (at the cost of a sliver of one core).
        std::this_thread::sleep_until(deadline - spinMargin);
        while (Clock::now() < deadline) {
        }
        const auto now = Clock::now();
        const bool isLate = now - deadline > period / 2;
        if (ticks > 0) {
            const double error = std::abs(
                std::chrono::duration<double, std::micro>((now - previous) - period).count());
            errors.push_back(error);
        }
        previous = now;
        if (isLate) {
            ++late;
            deadline = now; // do not burst to catch up
        }
        // A new snapshot, if the hand-over is not in use this instant.
        if (hasPending_) {
            std::unique_lock lock(handOver_, std::try_to_lock);
            if (lock) {
                auto scene = std::move(pending_);
                hasPending_ = false;
                playing = pendingPlaying_;
                lock.unlock();
                if (scene) sceneMoment = scene->moment;
                sceneSince = now;
                model.setScene(std::move(scene));
                limiter.restartRamp(seconds(now));
            }
        }
        const auto state = device_.read();
        if (state)
            lastFresh = seconds(now);
        else
            ++stale;
        const double age = seconds(now) - lastFresh;
        field::Vec3 sent{};
        ForceSample f;
        if (state) {
            animation::Instant moment = sceneMoment;
            if (playing) {
                const auto ns =
                    std::chrono::duration_cast<std::chrono::nanoseconds>(now - sceneSince).count();
                moment.sceneNs += ns;
                moment.utcNs += ns;
            }
            const field::Vec3 tool = options_.workspace.toScene(state->position);
            f = model.tick({tool, field::scaled(state->velocity, scale), moment});
            sent = limiter.limit(f.force, seconds(now), age, isLate);
            local.tool = tool;
        } else {
            sent = limiter.limit({}, seconds(now), age, isLate);
        }
        device_.command(sent, {});
        ++ticks;
        forces.push_back(sent);
        // Publish, unless a reader holds the lock this instant.
        std::unique_lock lock(publish_, std::try_to_lock);
        if (lock) {
            local.ticks = ticks;
            local.realTime = realTime;
            local.proxy = f.proxy;
            local.force = sent;
            local.contact = f.contact;
            local.cut = limiter.lastCut();
            local.lateTicks = late;
            local.staleReads = stale;
            const double elapsed = seconds(now);
            local.measuredRateHz = elapsed > 0 ? double(ticks) / elapsed : 0;
            status_ = local;
            // What happened since the last publication is handed over, then dropped here.
            if (periodErrors_.size() < (1u << 20))
                periodErrors_.insert(periodErrors_.end(), errors.begin(), errors.end());
            errors.clear();
            forces_.insert(forces_.end(), forces.begin(), forces.end());
            forces.clear();
            if (forces_.size() > 2 * keep)
                forces_.erase(forces_.begin(), forces_.end() - std::ptrdiff_t(keep));
            if (model.reports().size() != reports_.size()) reports_ = model.reports();
        }
    }
    device_.command({}, {}); // let go
}

} // namespace fl::haptics
