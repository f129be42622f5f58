#include "time_window.h"

#include "clock.h"

#include <cmath>

namespace fl::animation {

double cycleFraction(std::int64_t elapsedNs, double cycleSeconds, std::int64_t* cycles) {
    if (elapsedNs <= 0 || !(cycleSeconds > 0)) {
        if (cycles) *cycles = 0;
        return 0;
    }
    const long double cycleNs = static_cast<long double>(cycleSeconds) * kNanosecondsPerSecond;
    std::int64_t whole = 0;
    double fraction = 0;
    if (cycleNs >= 1 && cycleNs < 4e18L && cycleNs == std::floor(cycleNs)) {
        const auto c = static_cast<std::int64_t>(cycleNs);
        whole = elapsedNs / c;
        fraction = double(elapsedNs % c) / double(c);
    } else {
        const long double e = static_cast<long double>(elapsedNs);
        const long double q = std::floor(e / cycleNs);
        whole = q > 9e18L ? INT64_MAX : static_cast<std::int64_t>(q);
        fraction = double((e - q * cycleNs) / cycleNs);
        if (fraction >= 1) fraction = 0, ++whole; // rounding at a cycle boundary
        if (fraction < 0) fraction = 0;
    }
    if (fraction == 0 && whole > 0) {
        // X3D: the end of a cycle reads 1, not the start of the next.
        fraction = 1;
        --whole;
    }
    if (cycles) *cycles = whole;
    return fraction;
}

TimeWindow timeWindowOf(double startTime, double stopTime, double cycleInterval, bool loop) {
    return {secondsToNanoseconds(startTime), secondsToNanoseconds(stopTime),
            cycleInterval > 0 ? cycleInterval : 1, loop};
}

WindowState evaluateWindow(const TimeWindow& w, std::int64_t nowNs) {
    WindowState s;
    const bool stopCounts = w.stopNs > w.startNs;
    std::int64_t end = 0;
    if (!w.loop) {
        end = w.startNs + secondsToNanoseconds(w.cycleSeconds);
        s.bounded = true;
    }
    if (stopCounts && (!s.bounded || w.stopNs < end)) {
        end = w.stopNs;
        s.bounded = true;
    }
    s.endNs = end;
    if (nowNs < w.startNs) return s; // Before: fraction 0
    const bool ended = s.bounded && nowNs >= end;
    s.phase = ended ? Phase::After : Phase::Active;
    s.elapsedNs = saturatingSubtract(ended ? end : nowNs, w.startNs);
    s.fraction = cycleFraction(s.elapsedNs, w.cycleSeconds, &s.cycle);
    return s;
}

double functionTime(const TimeWindow& window, double spanStart, double spanEnd,
                    std::int64_t nowNs) {
    const WindowState s = evaluateWindow(window, nowNs);
    return spanStart + s.fraction * (spanEnd - spanStart);
}

} // namespace fl::animation
