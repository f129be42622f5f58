#pragma once
// What stands between the force model and the motors (docs/haptics.md,
// "Safety"): the device's maximum force; a ramp from nothing to full force
// over about 2 s when a device connects and when the scene changes; a limit
// on the change of force per tick (an impulse limit, as OpenHaptics has); a
// force that is not finite becomes none; and a watchdog — no force when the
// device's data is stale or the loop missed its deadlines.
#include "field/vec3.h"

#include <cstdint>

namespace fl::haptics {

struct LimiterSettings {
    double maxForce = 0;           // N: the device's
    double rampSeconds = 2;        // 0: no ramp (probe)
    double maxChangePerTick = 0;   // N; 0: no limit
    double staleSeconds = 0.005;   // device data older than this: no force
    int missedDeadlinesToStop = 3; // consecutive late ticks: no force until on time again
};

class ForceLimiter {
  public:
    explicit ForceLimiter(LimiterSettings settings);

    // Starts the ramp again (a device connected, the scene changed).
    void restartRamp(double now);
    // The force to send at `now` (s): `wanted` limited; `deviceAge` how old
    // the device's newest state is (s), `late` whether this tick missed its
    // deadline.
    field::Vec3 limit(const field::Vec3& wanted, double now, double deviceAge = 0,
                      bool late = false);

    // Why the last force was cut, for the panel and the tests.
    enum class Cut : std::uint8_t { None, Clamped, Ramp, Change, NotFinite, Stale, Late };
    Cut lastCut() const { return lastCut_; }
    const LimiterSettings& settings() const { return settings_; }

  private:
    LimiterSettings settings_;
    double rampStart_ = 0;
    bool ramping_ = false;
    int lateInARow_ = 0;
    field::Vec3 last_{};
    Cut lastCut_ = Cut::None;
};

} // namespace fl::haptics
