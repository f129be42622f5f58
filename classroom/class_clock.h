#pragma once
// Where the classroom reads the time: leases, rate limits, heartbeats and the
// failed-join throttle all ask one Clock, so tests drive them with a
// ManualClock (no sleeps) and the server with the steady clock.
#include <chrono>
#include <cstdint>

namespace fl::classroom {

using Millis = std::int64_t; // milliseconds on a clock that never goes back

class Clock {
  public:
    virtual ~Clock() = default;
    virtual Millis now() const = 0;
};

class SteadyClock final : public Clock {
  public:
    Millis now() const override {
        using namespace std::chrono;
        return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
    }
};

// A clock that moves only when told: what deterministic lease tests need.
class ManualClock final : public Clock {
  public:
    explicit ManualClock(Millis start = 0) : now_(start) {}
    Millis now() const override { return now_; }
    void advance(Millis by) { now_ += by; }

  private:
    Millis now_;
};

} // namespace fl::classroom
