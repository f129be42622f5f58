#pragma once
// Where time comes from. Every animated value in a scene is a function of one
// `Instant`: the scene's own timeline (play, pause, scrub, speed) and the wall
// clock it stands for. Times are whole nanoseconds in 64-bit integers, so a
// scene that runs for weeks keeps nanosecond precision (a double of seconds
// since 1970 only resolves about 0.2 microseconds); the wall clock is
// injectable so tests are deterministic.
#include <cstdint>
#include <optional>
#include <string_view>

namespace fl::animation {

inline constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;

struct WallTime {
    std::int64_t utcNs = 0;              // since 1970-01-01 00:00 UTC
    std::int32_t localOffsetSeconds = 0; // local time minus UTC (DST included)
};

class WallClock {
  public:
    virtual ~WallClock() = default;
    virtual WallTime now() const = 0;
};

// The machine's clock and time zone.
class SystemWallClock final : public WallClock {
  public:
    WallTime now() const override;
};

// A clock that moves only when told: for tests and for rendering a scene at a
// chosen moment (`functionlab render --time`).
class ManualWallClock final : public WallClock {
  public:
    explicit ManualWallClock(WallTime start = {}) : now_(start) {}
    WallTime now() const override { return now_; }
    void set(WallTime t) { now_ = t; }
    void advance(std::int64_t ns) { now_.utcNs += ns; }

  private:
    WallTime now_;
};

// Which clock a function node's `timeBase` names.
enum class TimeBase : std::uint8_t { Scene, Local, Utc };
std::optional<TimeBase> parseTimeBase(std::string_view text); // "scene", "local", "utc"

// One moment of a running scene on all of its clocks.
struct Instant {
    std::int64_t sceneNs = 0; // since the scene started, on its timeline
    std::int64_t utcNs = 0;   // the wall-clock moment the timeline stands for
    std::int32_t localOffsetSeconds = 0;

    std::int64_t nanosecondsOn(TimeBase base) const;
    // X3D time (SFTime): UTC seconds since 1970, what TimeSensor works in.
    double x3dSeconds() const { return double(utcNs) / double(kNanosecondsPerSecond); }
};

// The scene's timeline. While it plays at speed 1 and nobody scrubs, the wall
// clock it stands for is the real one. Pausing freezes every clock of the
// scene together (TimeSensors, `timeBase "utc"` and `"local"` nodes alike), so
// one frame is always one consistent moment; `resync()` puts the wall clocks
// back on real time.
class SceneTimeline {
  public:
    explicit SceneTimeline(const WallClock& clock);

    Instant now() const;
    void play();
    void pause();
    bool playing() const { return playing_; }
    void seek(std::int64_t sceneNs);
    void setSpeed(double speed); // > 0; 1 is real time
    double speed() const { return speed_; }
    // Move the timeline's wall clock back onto the real one, keeping the
    // scene time where it is.
    void resync();

  private:
    std::int64_t sceneNsAt(std::int64_t wallUtcNs) const;
    void anchor();

    const WallClock& clock_;
    std::int64_t utcAtSceneStart_ = 0; // wall moment of scene time 0
    std::int64_t anchorWallNs_ = 0;    // the wall clock when the timeline last changed
    std::int64_t anchorSceneNs_ = 0;   // the scene time then
    double speed_ = 1.0;
    bool playing_ = true;
};

// Saturating conversions between SFTime seconds and nanoseconds (±~290 years).
std::int64_t secondsToNanoseconds(double seconds);
std::int64_t saturatingSubtract(std::int64_t a, std::int64_t b);

} // namespace fl::animation
