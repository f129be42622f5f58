#pragma once
// A SpaceMouse drives a tool point by velocity: deflecting the puck moves
// the point (and turns it) at a speed proportional to the deflection, and
// letting go stops it. The point stays inside a ball, the workspace, as a
// force device's does. Axes are turned from the SpaceMouse's own (x right,
// y towards the user, z down) into the device frame every back-end shares
// (x right, y up, z towards the user): a proper rotation, so turning the
// puck turns the tool the same way.
#include "device/spacemouse_report.h"
#include "field/vec3.h"

#include <array>

namespace fl::haptics::spacemouse {

struct MotionSettings {
    double maxSpeed = 0.1;        // m/s at full deflection
    double maxTurnRate = 1.5;     // rad/s at full twist
    double workspaceRadius = 0.1; // m
    // A longer step (a paused program) counts as this long, so the tool
    // does not jump.
    double maxStep = 0.1; // s
};

struct SixDof {
    field::Vec3 translation{}; // −1…1 per axis, device frame
    field::Vec3 rotation{};    // −1…1 per axis, device frame
};

// Raw report axes to the device frame, normalised.
SixDof toDeviceFrame(const InputState& input, const InputSettings& settings);

class SpaceMouseTool {
  public:
    explicit SpaceMouseTool(MotionSettings settings = {});

    // Moves for `dt` seconds (clamped to [0, maxStep]) at the input's rates.
    void step(const SixDof& input, double dt);
    void reset();

    const field::Vec3& position() const { return position_; }
    const std::array<double, 4>& orientation() const { return orientation_; }
    // The motion the last step made (m/s): zero against the workspace's
    // edge in the outward direction.
    const field::Vec3& velocity() const { return velocity_; }
    const MotionSettings& settings() const { return settings_; }

  private:
    MotionSettings settings_;
    field::Vec3 position_{};
    std::array<double, 4> orientation_{1, 0, 0, 0};
    field::Vec3 velocity_{};
};

} // namespace fl::haptics::spacemouse
