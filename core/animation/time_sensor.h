#pragma once
// The X3D TimeSensor (ISO/IEC 19775-1 §8.4.1) as a state machine over ticks:
// which events it sends at each moment. Events go to a sink so the animator
// can route them; the state is plain data so tests can drive it directly.
#include "time_window.h"

#include <cstdint>
#include <functional>
#include <string_view>

namespace fl::animation {

// The sensor's inputOutput fields as they are at this tick (after events).
struct TimeSensorFields {
    bool enabled = true;
    bool loop = false;
    double cycleInterval = 1;
    double startTime = 0; // X3D seconds (UTC since 1970)
    double stopTime = 0;
    double pauseTime = 0;
    double resumeTime = 0;
};

struct TimeSensorState {
    bool active = false;
    bool paused = false;
    TimeWindow window; // startTime and cycleInterval as they were at activation
    std::int64_t pausedAtNs = 0;
    std::int64_t cycle = -1; // cycles completed at the last tick
};

// field: "isActive", "isPaused", "cycleTime", "fraction_changed", "time",
// "elapsedTime"; value: the number (booleans 0/1, times in X3D seconds).
using TimeSensorSink = std::function<void(std::string_view field, double value)>;

// One tick at `nowNs` (UTC nanoseconds). `previousNs` is the last tick's time
// (a window that opened and closed between two ticks still sends its start
// and end); `firstTick` is true at load, where windows already past stay
// silent.
void advanceTimeSensor(TimeSensorState& state, const TimeSensorFields& fields, std::int64_t nowNs,
                       std::int64_t previousNs, bool firstTick, const TimeSensorSink& sink);

// Whether a set_startTime (or set_cycleInterval) event is ignored now: X3D
// ignores it while the sensor is active.
inline bool ignoresTimingChange(const TimeSensorState& state) {
    return state.active;
}

} // namespace fl::animation
