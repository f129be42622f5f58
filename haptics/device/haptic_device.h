#pragma once
// One interface for every haptic device (DESIGN §6): what the servo loop reads
// (position, orientation, velocity, buttons) and what it writes (force,
// torque), with the device's own limits. Back-ends: simulated, replay,
// hidapi (SpaceMouse, input only) and libusb (Novint Falcon). Positions are
// in the device's own frame, metres: every back-end puts x to the right, y up
// and z towards the user, with the origin at its workspace's centre; the
// servo loop maps them into the scene. (docs/haptics.md, "Devices".)
//
// Threading: read() and command() are called by the servo thread only;
// open() and close() by the thread that owns the device, never while the
// servo loop runs it.
#include "field/vec3.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace fl::haptics {

// What a device can do safely (wave2.md: CHAI3D and HAPI device tables).
struct DeviceLimits {
    double maxForce = 0;        // N; 0 for an input-only device
    double maxStiffness = 0;    // N/m the device renders stably
    double maxDamping = 0;      // N·s/m
    double workspaceRadius = 0; // m, about the device's centre
};

struct DeviceState {
    double time = 0;        // s, on the device's clock (simulated or steady)
    field::Vec3 position{}; // m, device frame
    // Unit quaternion w, x, y, z (identity for a 3-DOF device).
    std::array<double, 4> orientation{1, 0, 0, 0};
    field::Vec3 velocity{};    // m/s
    std::uint32_t buttons = 0; // bit i: button i pressed
};

class HapticDevice {
  public:
    virtual ~HapticDevice() = default;

    // "Simulated", "Replay of probe.log", "SpaceMouse Compact", "Novint Falcon".
    virtual std::string name() const = 0;
    virtual DeviceLimits limits() const = 0;
    // False for input-only devices (a SpaceMouse): command() is ignored.
    virtual bool rendersForce() const = 0;

    // The newest state; none when the device has nothing new or fresh to say
    // (the servo loop's watchdog counts those).
    virtual std::optional<DeviceState> read() = 0;
    // The force (N) and torque (N·m) the device applies to the hand, in the
    // device frame, already limited by the servo loop.
    virtual void command(const field::Vec3& force, const field::Vec3& torque) = 0;
};

} // namespace fl::haptics
