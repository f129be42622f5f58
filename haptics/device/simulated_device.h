#pragma once
// The simulated device (issue 16 §1): a tool point on a clock the caller
// advances, so every run is the same to the last bit. Two ways to drive it:
//  - along a path: the tool is exactly where the path says (`probe`); the
//    commanded forces move nothing, they are recorded;
//  - by a hand: a hand target walks the path and holds the tool, a point
//    mass, through a spring-damper; the commanded force acts on that mass,
//    so a rendered wall pushes the tool back as it would a real hand
//    (passivity tests).
// Without a path the tool rests at the origin.
#include "device/device_limits.h"
#include "device/haptic_device.h"
#include "device/polyline_path.h"

#include <cstdint>
#include <optional>

namespace fl::haptics {

// The hand that holds the tool in the mass–spring model. Defaults: a light
// grip (tool 0.1 kg, 300 N/m, 8 N·s/m: about 9 Hz, damped at 0.73 of
// critical) so forces of a few newtons visibly deflect the tool.
struct HandModel {
    double toolMass = 0.1;  // kg
    double stiffness = 300; // N/m between hand and tool
    double damping = 8;     // N·s/m between hand and tool
    double maxStep = 1e-4;  // s: the integrator's largest sub-step
};

class SimulatedDevice : public HapticDevice {
  public:
    explicit SimulatedDevice(DeviceLimits limits = limitsOf(DeviceModel::Simulated));

    // The tool follows `path` exactly, from the current time on (path time 0
    // is now).
    void followPath(PolylinePath path);
    // A hand follows `path` from now on and pulls the tool along; the tool
    // starts where the hand is, moving with it.
    void holdWithHand(PolylinePath path, HandModel hand = {});

    // The clock. Both only go forwards: an earlier time, a negative step or
    // a value that is not finite is ignored (returns false); so is a jump of
    // more than 10^7 hand-model sub-steps (1000 s at the default step).
    bool setTime(double t);
    bool advance(double dt);
    double time() const { return time_; }

    // While silent, read() says nothing (a device that stopped answering,
    // for watchdog tests). The clock still runs.
    void setSilent(bool silent) { silent_ = silent; }
    void setButtons(std::uint32_t buttons) { buttons_ = buttons; }

    // What the device was last told, and how often.
    const field::Vec3& lastForce() const { return lastForce_; }
    const field::Vec3& lastTorque() const { return lastTorque_; }
    std::uint64_t commandCount() const { return commandCount_; }
    // Work (J) the commanded forces did on the tool so far: each force is
    // held from its command() to the next, as a device's motors hold it, and
    // dotted with the tool's displacement meanwhile. A passive rendering
    // gives no energy back over a closed path: this stays ≤ 0 up to what the
    // sampling costs.
    double forceWork() const { return work_; }

    // HapticDevice
    std::string name() const override { return "Simulated"; }
    DeviceLimits limits() const override { return limits_; }
    bool rendersForce() const override { return true; }
    std::optional<DeviceState> read() override;
    void command(const field::Vec3& force, const field::Vec3& torque) override;

  private:
    enum class Drive { Rest, Path, Hand };
    void step(double dt); // one hand-model sub-step
    PathSample handAt(double t) const;

    DeviceLimits limits_;
    Drive drive_ = Drive::Rest;
    std::optional<PolylinePath> path_;
    HandModel hand_;
    double pathStart_ = 0; // the clock's time at path time 0
    double time_ = 0;
    field::Vec3 position_{};
    field::Vec3 velocity_{};
    std::uint32_t buttons_ = 0;
    bool silent_ = false;
    field::Vec3 lastForce_{};
    field::Vec3 lastTorque_{};
    std::uint64_t commandCount_ = 0;
    double work_ = 0;
};

} // namespace fl::haptics
