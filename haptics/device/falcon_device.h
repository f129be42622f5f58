#pragma once
// The Novint Falcon as a HapticDevice: packets over a FalconTransport (the
// libusb one for a real Falcon), encoders to position by the kinematics,
// forces to motor values by the Jacobian, homing watched throughout.
//
// I/O: the firmware answers each 16-byte command with one 16-byte reading.
// command() sends at once when no packet is waiting for its answer; read()
// first sends the held command if nothing is outstanding, then collects
// what arrived (waiting at most ioTimeoutMs). So a servo loop that reads
// then commands sends one packet a tick, and a lost answer is re-asked
// after a few empty reads. Until the Falcon is homed the motors get zero:
// positions before homing are relative to where the arm was at power-on.
#include "device/device_limits.h"
#include "device/falcon_homing.h"
#include "device/falcon_kinematics.h"
#include "device/falcon_packet.h"
#include "device/falcon_transport.h"
#include "device/haptic_device.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace fl::haptics::falcon {

struct FalconDeviceOptions {
    int ioTimeoutMs = 1;
    // Time (s) for the state's clock; the steady clock from construction
    // when empty. Tests give a simulated clock.
    std::function<double()> clock;
    // Velocity is the position's difference filtered with this time
    // constant (s): encoder steps of about 0.04 mm would make the raw
    // difference jump by tens of mm/s at 1 kHz.
    double velocityTimeConstant = 0.005;
};

class FalconDevice : public HapticDevice {
  public:
    explicit FalconDevice(std::unique_ptr<FalconTransport> transport,
                          FalconDeviceOptions options = {});
    // Sends zero force and turns the light off.
    ~FalconDevice() override;

    const FalconHoming& homing() const { return homing_; }
    // The last transport failure; empty while all is well.
    const std::string& lastError() const { return error_; }
    // Packets received, and reads that found none.
    std::uint64_t packets() const { return framer_.packets(); }
    std::uint64_t misses() const { return misses_; }
    const FalconCommand& lastCommandSent() const { return sent_; }

    // HapticDevice
    std::string name() const override { return "Novint Falcon"; }
    DeviceLimits limits() const override { return limitsOf(DeviceModel::NovintFalcon); }
    bool rendersForce() const override { return true; }
    std::optional<DeviceState> read() override;
    void command(const field::Vec3& force, const field::Vec3& torque) override;

  private:
    double now() const;
    bool send();

    std::unique_ptr<FalconTransport> transport_;
    FalconDeviceOptions options_;
    double startTime_ = 0;
    ReadingFramer framer_;
    FalconHoming homing_;
    FalconCommand held_;       // the next packet's content
    FalconCommand sent_;       // the last packet sent
    bool outstanding_ = false; // a packet is waiting for its answer
    int emptyReads_ = 0;
    std::uint64_t misses_ = 0;
    std::uint64_t seenPackets_ = 0;
    std::optional<field::Vec3> kinematicPosition_;
    field::Vec3 velocity_{};
    double lastTime_ = 0;
    std::string error_;
};

// Brings a Falcon up on `transport`: run mode, and when no firmware answers,
// the user's firmware file uploaded (up to `attempts` times). None with what
// to do in *error (e.g. no firmware file given, or it does not exist).
std::unique_ptr<FalconDevice> startFalcon(std::unique_ptr<FalconTransport> transport,
                                          const std::filesystem::path& firmwareFile, int attempts,
                                          std::string* error, FalconDeviceOptions options = {});

} // namespace fl::haptics::falcon
