#pragma once
// The X3D time-dependent node rules (ISO/IEC 19775-1 §8.2.4) as a pure
// function of "now": a node becomes active at startTime, a stopTime later than
// startTime ends it, `loop FALSE` ends it after one cycle, and within a cycle
// the fraction runs from 0 to 1. TimeSensor and every function node's timing
// (cycleInterval, timeSpan, loop, startTime, stopTime) share it.
#include <cstdint>

namespace fl::animation {

struct TimeWindow {
    std::int64_t startNs = 0;
    std::int64_t stopNs = 0; // ignored unless later than startNs
    double cycleSeconds = 1; // > 0
    bool loop = false;
};

// The window of a time-dependent node from its fields, in seconds as SFTime
// gives them (a cycleInterval of 0 or less, refused by the checker, reads as 1).
TimeWindow timeWindowOf(double startTime, double stopTime, double cycleInterval, bool loop);

enum class Phase : std::uint8_t { Before, Active, After };

struct WindowState {
    Phase phase = Phase::Before;
    // In [0, 1]. 1 exactly at the end of a cycle (X3D: a positive whole
    // number of cycles gives 1, not 0). Before the start: 0; after the end:
    // the fraction at the end.
    double fraction = 0;
    std::int64_t cycle = 0;     // whole cycles completed at `now` (or at the end)
    std::int64_t elapsedNs = 0; // since startNs, up to the end when After
    std::int64_t endNs = 0;     // when the window ends (valid when it is bounded)
    bool bounded = false;       // false: loops with no stopTime, never ends
};

WindowState evaluateWindow(const TimeWindow& window, std::int64_t nowNs);

// The fraction of the current cycle after `elapsedNs` (>= 0), exact for any
// elapsed time a 64-bit nanosecond count holds: whole-nanosecond cycles use
// integer remainders, others 64-bit-mantissa floating point.
double cycleFraction(std::int64_t elapsedNs, double cycleSeconds, std::int64_t* cycles = nullptr);

// A function node's t: timeSpan[0] before it starts, then linear over each
// cycle to timeSpan[1], frozen at its last value once it has ended.
double functionTime(const TimeWindow& window, double spanStart, double spanEnd, std::int64_t nowNs);

} // namespace fl::animation
