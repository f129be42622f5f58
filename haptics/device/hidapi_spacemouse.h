#pragma once
// A 3Dconnexion SpaceMouse through hidapi (hidraw on Linux): 6-DOF input
// that drives a tool point (spacemouse_tool.h); no force. read() never
// waits: it takes every report already queued (hid_read_timeout with 0)
// and moves the tool for the time since the last read. Needs read and
// write access to the /dev/hidraw node: see docs/haptics.md, "Permissions".
// One program at a time can read a SpaceMouse's reports reliably: stop
// spacenavd or 3Dconnexion's driver if the tool does not move.
#include "device/haptic_device.h"
#include "device/spacemouse_report.h"
#include "device/spacemouse_tool.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct hid_device_;

namespace fl::haptics::spacemouse {

struct SpaceMouseEntry {
    std::string path; // hidapi's path, /dev/hidrawN
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string name;
    bool accessible = false;
    std::string problem; // why it cannot be opened, when it cannot
};

// Every SpaceMouse hidapi sees (one entry per device node, the puck's
// collection preferred). Empty, with the reason in *error when given, when
// HID cannot be read at all.
std::vector<SpaceMouseEntry> findSpaceMice(std::string* error = nullptr);

struct SpaceMouseOptions {
    InputSettings input;
    MotionSettings motion;
};

class HidapiSpaceMouse : public HapticDevice {
  public:
    // None with what to do in *error.
    static std::unique_ptr<HidapiSpaceMouse> open(const std::string& path, std::string name,
                                                  SpaceMouseOptions options, std::string* error);
    ~HidapiSpaceMouse() override;
    HidapiSpaceMouse(const HidapiSpaceMouse&) = delete;
    HidapiSpaceMouse& operator=(const HidapiSpaceMouse&) = delete;

    const std::string& lastError() const { return error_; }
    std::uint64_t reports() const { return reports_; }

    // HapticDevice
    std::string name() const override { return name_; }
    DeviceLimits limits() const override;
    bool rendersForce() const override { return false; }
    std::optional<DeviceState> read() override;
    void command(const field::Vec3&, const field::Vec3&) override {}

  private:
    HidapiSpaceMouse(hid_device_* device, std::string name, SpaceMouseOptions options);

    hid_device_* device_;
    std::string name_;
    SpaceMouseOptions options_;
    InputState input_;
    SpaceMouseTool tool_;
    double startTime_ = 0;
    double lastTime_ = 0;
    std::uint64_t reports_ = 0;
    std::string error_;
};

} // namespace fl::haptics::spacemouse
