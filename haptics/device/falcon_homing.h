#pragma once
// Homing of the Novint Falcon. Its encoders count from wherever the arm was
// at power-on; each leg finds its absolute zero when its encoder passes an
// index mark, which happens only when the user moves the grip through its
// range. While homing mode is requested, the firmware reports which legs
// have found their mark. Until all three have, positions are meaningless:
// the device layer renders no force, lights the LED red and tells the user
// what to do; once homed the LED turns green. The firmware reports homing
// only while the mode is requested, so the request stays on for the whole
// session, and a Falcon that loses its homing (power or USB reset) is
// noticed and homed again.
#include "device/falcon_packet.h"

#include <cstdint>
#include <string>

namespace fl::haptics::falcon {

enum class HomingPhase { Homing, Homed };

class FalconHoming {
  public:
    // After this long without homing, the instruction says more.
    static constexpr double kPatienceSeconds = 20;

    // Each reading from the device, with the time (s) it came.
    void update(const FalconReading& reading, double time);

    HomingPhase phase() const { return phase_; }
    bool homed() const { return phase_ == HomingPhase::Homed; }
    // What to send in the next command packet.
    bool homingMode() const { return true; }
    std::uint8_t leds() const { return homed() ? kLedGreen : kLedRed; }
    // What the user should do now; empty once homed.
    std::string instruction() const;
    // How often a homed Falcon lost its homing.
    int homingLosses() const { return losses_; }

  private:
    HomingPhase phase_ = HomingPhase::Homing;
    std::uint8_t homedAxes_ = 0;
    bool started_ = false;
    double since_ = 0; // when the current homing began
    double now_ = 0;
    int losses_ = 0;
    bool afterLoss_ = false; // homing again because it was lost
};

} // namespace fl::haptics::falcon
