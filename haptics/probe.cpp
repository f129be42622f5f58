#include "probe.h"

#include "device/simulated_device.h"
#include "force_limiter.h"

#include <cmath>
#include <cstdio>

namespace fl::haptics {

namespace {

animation::Instant instantAt(double sceneSeconds) {
    const std::int64_t ns = animation::secondsToNanoseconds(sceneSeconds);
    return {ns, ns, 0};
}

void fail(std::string* error, std::string text) {
    if (error) *error = std::move(text);
}

} // namespace

namespace {

bool checkClock(const ProbeOptions& options, std::string* error) {
    if (!(options.rateHz >= 1 && options.rateHz <= 100000)) {
        fail(error, "the servo rate must be between 1 and 100000 Hz");
        return false;
    }
    if (!(options.duration > 0) || !std::isfinite(options.duration) ||
        options.duration * options.rateHz > 1e7) {
        fail(error, "the duration must be positive and at most 10^7 ticks long");
        return false;
    }
    if (!std::isfinite(options.startTime)) {
        fail(error, "the start time must be a number of seconds");
        return false;
    }
    return true;
}

} // namespace

std::optional<ProbeRun> runProbe(const scene::Scene& scene, const ProbeOptions& options,
                                 std::string* error) {
    if (!checkClock(options, error)) return std::nullopt;
    std::string why;
    auto path = PolylinePath::make(options.path, options.duration, &why);
    if (!path) {
        fail(error, "the path: " + why);
        return std::nullopt;
    }
    SimulatedDevice device;
    device.followPath(std::move(*path));
    return runOnSimulatedClock(
        scene, device, [&](double t) { return device.setTime(t); }, options, error);
}

std::optional<ProbeRun> runOnSimulatedClock(const scene::Scene& scene, HapticDevice& device,
                                            const std::function<bool(double)>& setTime,
                                            const ProbeOptions& options, std::string* error) {
    if (!checkClock(options, error)) return std::nullopt;
    const DeviceLimits limits = device.limits();
    ForceModel model(settingsFor(limits, options.rateHz));
    LimiterSettings ls;
    ls.maxForce = limits.maxForce;
    ls.rampSeconds = 0; // the probe starts in contact if it must: no connect ramp
    ForceLimiter limiter(ls);

    const scene::EffectsPlan plan = scene::makeEffectsPlan(scene);
    animation::Animator clock(scene);
    auto snapshotAt = [&](double sceneSeconds) {
        const animation::Instant moment = instantAt(sceneSeconds);
        clock.tick(moment);
        return std::make_shared<const TangibleScene>(makeTangibleScene(scene, plan, clock, moment));
    };
    ProbeRun run;
    run.rateHz = options.rateHz;
    run.maxForce = limits.maxForce;
    auto snapshot = snapshotAt(options.startTime);
    run.notes = snapshot->notes;
    model.setScene(snapshot);
    double lastSnapshot = 0;
    const auto ticks = static_cast<std::int64_t>(std::llround(options.duration * options.rateHz));
    run.ticks.reserve(std::size_t(ticks + 1));
    for (std::int64_t k = 0; k <= ticks; ++k) {
        const double time = double(k) / options.rateHz;
        setTime(time);
        // Only a scene that moves is looked at again; effects that read t take
        // the tick's t themselves.
        if (snapshot->geometryVaries && time - lastSnapshot >= options.snapshotInterval) {
            snapshot = snapshotAt(options.startTime + time);
            model.setScene(snapshot);
            lastSnapshot = time;
        }
        const auto state = device.read();
        if (!state) continue;
        const ForceSample f =
            model.tick({state->position, state->velocity, instantAt(options.startTime + time)});
        const field::Vec3 sent = limiter.limit(f.force, time);
        device.command(sent, {});
        run.ticks.push_back({time * 1000, state->position, f.proxy, sent, f.contact});
    }
    run.reports = model.reports();
    return run;
}

namespace {

std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", v);
    return buffer;
}

std::string triple(const field::Vec3& v) {
    return "[" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + "]";
}

} // namespace

std::string probeJson(const ProbeRun& run) {
    std::string out = "{\"rate_hz\": " + number(run.rateHz) +
                      ", \"max_force\": " + number(run.maxForce) + ", \"ticks\": [";
    for (std::size_t i = 0; i < run.ticks.size(); ++i) {
        const ProbeTick& t = run.ticks[i];
        out += i ? ",\n  " : "\n  ";
        out += "{\"ms\": " + number(t.ms) + ", \"device\": " + triple(t.device) +
               ", \"proxy\": " + triple(t.proxy) + ", \"force\": " + triple(t.force) +
               ", \"contact\": \"" + std::string(contactName(t.contact)) + "\"}";
    }
    out += "\n]}\n";
    return out;
}

} // namespace fl::haptics
