#include "time_sensor.h"

#include "clock.h"

namespace fl::animation {
namespace {

double seconds(std::int64_t ns) {
    return double(ns) / double(kNanosecondsPerSecond);
}

TimeWindow windowOf(const TimeSensorFields& f) {
    return timeWindowOf(f.startTime, f.stopTime, f.cycleInterval, f.loop);
}

void sendProgress(const WindowState& s, std::int64_t nowNs, const TimeSensorSink& sink) {
    sink("fraction_changed", s.fraction);
    sink("elapsedTime", seconds(s.elapsedNs));
    sink("time", seconds(nowNs));
}

} // namespace

void advanceTimeSensor(TimeSensorState& st, const TimeSensorFields& f, std::int64_t nowNs,
                       std::int64_t previousNs, bool firstTick, const TimeSensorSink& sink) {
    if (!f.enabled) {
        if (st.active) {
            st.active = st.paused = false;
            sink("isActive", 0);
        }
        return;
    }
    if (!st.active) {
        const TimeWindow w = windowOf(f);
        const WindowState s = evaluateWindow(w, nowNs);
        if (s.phase == Phase::Before) return;
        // A window that ended before this tick only counts when it opened
        // after the previous one (never at load).
        if (s.phase == Phase::After && (firstTick || w.startNs <= previousNs)) return;
        st.active = true;
        st.paused = false;
        st.window = w;
        st.cycle = s.cycle;
        sink("isActive", 1);
        sink("cycleTime", seconds(nowNs));
        sendProgress(s, nowNs, sink);
        if (s.phase == Phase::After) {
            st.active = false;
            sink("isActive", 0);
        }
        return;
    }
    // Active: loop and stopTime changes apply; startTime and cycleInterval
    // stay as they were at activation.
    st.window.loop = f.loop;
    const std::int64_t stop = secondsToNanoseconds(f.stopTime);
    st.window.stopNs = stop > st.window.startNs ? stop : 0;

    const std::int64_t pauseNs = secondsToNanoseconds(f.pauseTime);
    const std::int64_t resumeNs = secondsToNanoseconds(f.resumeTime);
    if (!st.paused && f.pauseTime > f.resumeTime && nowNs >= pauseNs) {
        st.paused = true;
        st.pausedAtNs = nowNs;
        sink("isPaused", 1);
        return;
    }
    if (st.paused) {
        if (!(f.resumeTime > f.pauseTime && nowNs >= resumeNs)) return;
        // Paused time does not count: shift the window by the pause.
        const std::int64_t pausedFor = saturatingSubtract(nowNs, st.pausedAtNs);
        st.window.startNs += pausedFor;
        if (st.window.stopNs) st.window.stopNs += pausedFor;
        st.paused = false;
        sink("isPaused", 0);
    }
    const WindowState s = evaluateWindow(st.window, nowNs);
    if (s.phase == Phase::After) {
        sendProgress(s, nowNs, sink);
        st.active = false;
        sink("isActive", 0);
        return;
    }
    if (s.cycle != st.cycle) {
        st.cycle = s.cycle;
        sink("cycleTime", seconds(nowNs));
    }
    sendProgress(s, nowNs, sink);
}

} // namespace fl::animation
