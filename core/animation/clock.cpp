#include "clock.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>

namespace fl::animation {

WallTime SystemWallClock::now() const {
    const auto since = std::chrono::system_clock::now().time_since_epoch();
    const std::int64_t ns = std::chrono::duration_cast<std::chrono::nanoseconds>(since).count();
    const std::time_t seconds = std::time_t(ns / kNanosecondsPerSecond);
    std::tm local{};
    WallTime t{ns, 0};
    // tm_gmtoff is the offset in force at that moment (daylight saving included).
    if (localtime_r(&seconds, &local)) t.localOffsetSeconds = std::int32_t(local.tm_gmtoff);
    return t;
}

std::optional<TimeBase> parseTimeBase(std::string_view text) {
    if (text == "scene") return TimeBase::Scene;
    if (text == "local") return TimeBase::Local;
    if (text == "utc") return TimeBase::Utc;
    return std::nullopt;
}

std::int64_t Instant::nanosecondsOn(TimeBase base) const {
    switch (base) {
    case TimeBase::Scene:
        return sceneNs;
    case TimeBase::Utc:
        return utcNs;
    case TimeBase::Local:
        return saturatingSubtract(utcNs, -std::int64_t(localOffsetSeconds) * kNanosecondsPerSecond);
    }
    return sceneNs;
}

std::int64_t secondsToNanoseconds(double seconds) {
    // ±9.2e9 s fits in int64 nanoseconds; beyond that (or NaN) saturate.
    constexpr double limit = 9.2e18;
    const double ns = seconds * double(kNanosecondsPerSecond);
    if (std::isnan(ns)) return 0;
    if (ns >= limit) return std::int64_t(limit);
    if (ns <= -limit) return -std::int64_t(limit);
    // Whole seconds and the rest apart: seconds * 1e9 in one double would
    // round today's times to 256 ns.
    const double whole = std::floor(seconds);
    return std::int64_t(whole) * kNanosecondsPerSecond +
           std::llround((seconds - whole) * double(kNanosecondsPerSecond));
}

std::int64_t saturatingSubtract(std::int64_t a, std::int64_t b) {
    std::int64_t r = 0;
    if (!__builtin_sub_overflow(a, b, &r)) return r;
    return b < 0 ? std::numeric_limits<std::int64_t>::max()
                 : std::numeric_limits<std::int64_t>::min();
}

SceneTimeline::SceneTimeline(const WallClock& clock) : clock_(clock) {
    const WallTime start = clock_.now();
    utcAtSceneStart_ = start.utcNs;
    anchorWallNs_ = start.utcNs;
}

std::int64_t SceneTimeline::sceneNsAt(std::int64_t wallUtcNs) const {
    if (!playing_) return anchorSceneNs_;
    const std::int64_t wallElapsed = saturatingSubtract(wallUtcNs, anchorWallNs_);
    if (speed_ == 1.0) return anchorSceneNs_ + wallElapsed;
    return anchorSceneNs_ + std::int64_t(std::llround(double(wallElapsed) * speed_));
}

Instant SceneTimeline::now() const {
    const WallTime wall = clock_.now();
    Instant i;
    i.sceneNs = sceneNsAt(wall.utcNs);
    i.utcNs = utcAtSceneStart_ + i.sceneNs;
    i.localOffsetSeconds = wall.localOffsetSeconds;
    return i;
}

void SceneTimeline::anchor() {
    const std::int64_t wall = clock_.now().utcNs;
    anchorSceneNs_ = sceneNsAt(wall);
    anchorWallNs_ = wall;
}

void SceneTimeline::play() {
    anchor();
    playing_ = true;
}

void SceneTimeline::pause() {
    anchor();
    playing_ = false;
}

void SceneTimeline::seek(std::int64_t sceneNs) {
    anchor();
    anchorSceneNs_ = sceneNs;
}

void SceneTimeline::setSpeed(double speed) {
    if (!(speed > 0) || !std::isfinite(speed)) return;
    anchor();
    speed_ = speed;
}

void SceneTimeline::resync() {
    anchor();
    utcAtSceneStart_ = anchorWallNs_ - anchorSceneNs_;
}

} // namespace fl::animation
