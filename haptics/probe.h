#pragma once
// `functionlab haptics probe` (issue 16 §4; docs/haptics.md): the simulated
// device's tool point walks a polyline in scene coordinates at constant speed
// while the servo loop runs at its rate on the simulated clock — the same
// force model and limits as with a real device, deterministic, no waiting for
// real time, no connect ramp.
#include "force_model.h"

#include "scene/scene.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fl::haptics {

struct ProbeOptions {
    std::vector<field::Vec3> path; // at least one point
    double duration = 1;           // s to walk it
    double startTime = 0;          // scene time at the first tick
    double rateHz = 1000;          // servo rate
    // A snapshot of a scene whose geometry moves is made again this often
    // (s of simulated time), as the application's snapshot thread would.
    double snapshotInterval = 0.01;
};

struct ProbeTick {
    double ms = 0;
    field::Vec3 device{}, proxy{}, force{};
    ContactKind contact = ContactKind::None;
};

struct ProbeRun {
    double rateHz = 0;
    double maxForce = 0; // the device's
    std::vector<ProbeTick> ticks;
    std::vector<std::string> notes;   // tangible shapes not felt, and why
    std::vector<std::string> reports; // formulas that were not finite, once each
};

// None, with `error`, for options that cannot run (an empty path, a duration
// or rate out of range, more than 10^7 ticks).
std::optional<ProbeRun> runProbe(const scene::Scene& scene, const ProbeOptions& options,
                                 std::string* error = nullptr);

// The same servo loop on the simulated clock with any device whose clock the
// caller sets (`setTime(seconds from the start)`): a replayed log (`haptics
// replay`), a recorder round a simulated device (`haptics record`). The
// options' path is not used; ticks where the device says nothing are left out.
std::optional<ProbeRun> runOnSimulatedClock(const scene::Scene& scene, HapticDevice& device,
                                            const std::function<bool(double)>& setTime,
                                            const ProbeOptions& options,
                                            std::string* error = nullptr);

// The run as the one JSON object `--json` prints.
std::string probeJson(const ProbeRun& run);

} // namespace fl::haptics
