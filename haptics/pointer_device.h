#pragma once
// A device without hardware for the window: the mouse (or any other thread)
// sets where the tool point is, the servo thread reads it — the student who
// has no haptic device still explores the forces, as arrows and colours
// (issue 16 §3). Positions are in the device frame (metres), like any device;
// the velocity is estimated from the last two positions set. Thread-safe:
// moveTo() from one thread, read() and command() from the servo thread.
#include "device/haptic_device.h"

#include <chrono>
#include <mutex>

namespace fl::haptics {

class PointerDevice : public HapticDevice {
  public:
    explicit PointerDevice(DeviceLimits limits);

    // The tool to `position`. The first time, the servo loop first sees it at
    // `approach` (a point outside the surface): contact is found by the tool
    // crossing the surface, so a tool that appeared inside would be inside.
    void moveTo(const field::Vec3& position, std::optional<field::Vec3> approach = std::nullopt);
    // The force last commanded (what the window draws as an arrow).
    field::Vec3 lastForce() const;

    std::string name() const override { return "Mouse (no haptic device)"; }
    DeviceLimits limits() const override { return limits_; }
    bool rendersForce() const override { return true; }
    std::optional<DeviceState> read() override;
    void command(const field::Vec3& force, const field::Vec3& torque) override;

  private:
    using Clock = std::chrono::steady_clock;
    DeviceLimits limits_;
    mutable std::mutex mutex_;
    field::Vec3 position_{}, previous_{};
    Clock::time_point at_ = Clock::now(), previousAt_ = Clock::now();
    field::Vec3 force_{};
    std::optional<DeviceState> lastRead_; // the servo thread's own
    std::optional<field::Vec3> approach_; // shown once before the first position
    bool placed_ = false;
};

} // namespace fl::haptics
