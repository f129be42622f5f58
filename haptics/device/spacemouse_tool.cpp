#include "device/spacemouse_tool.h"

#include <algorithm>
#include <cmath>

namespace fl::haptics::spacemouse {

using field::Vec3;

SixDof toDeviceFrame(const InputState& input, const InputSettings& settings) {
    auto frame = [&](const Axes& raw) {
        const double x = normalizedAxis(raw[0], settings);
        const double y = normalizedAxis(raw[1], settings);
        const double z = normalizedAxis(raw[2], settings);
        // (right, towards the user, down) → (right, up, towards the user)
        return Vec3{x, -z, y};
    };
    return {frame(input.translation()), frame(input.rotation())};
}

SpaceMouseTool::SpaceMouseTool(MotionSettings settings) : settings_(settings) {
    // Settings that are not positive and finite would freeze or fling the
    // tool: those fall back to the defaults.
    const MotionSettings d;
    auto usable = [](double v, double fallback) {
        return v > 0 && std::isfinite(v) ? v : fallback;
    };
    settings_.maxSpeed = usable(settings.maxSpeed, d.maxSpeed);
    settings_.maxTurnRate = usable(settings.maxTurnRate, d.maxTurnRate);
    settings_.workspaceRadius = usable(settings.workspaceRadius, d.workspaceRadius);
    settings_.maxStep = usable(settings.maxStep, d.maxStep);
}

void SpaceMouseTool::reset() {
    position_ = {};
    orientation_ = {1, 0, 0, 0};
    velocity_ = {};
}

void SpaceMouseTool::step(const SixDof& input, double dt) {
    if (!(dt > 0) || !field::isFinite(input.translation) || !field::isFinite(input.rotation)) {
        velocity_ = {};
        return;
    }
    dt = std::min(dt, settings_.maxStep);
    const Vec3 before = position_;
    Vec3 next = field::along(position_, input.translation, settings_.maxSpeed * dt);
    const double r = field::length(next);
    if (r > settings_.workspaceRadius) next = field::scaled(next, settings_.workspaceRadius / r);
    position_ = next;
    velocity_ = field::scaled(field::minus(position_, before), 1 / dt);

    // Turn by ω·dt about ω's axis, in the device frame: q ← Δq ⊗ q.
    const Vec3 omega = field::scaled(input.rotation, settings_.maxTurnRate);
    const double angle = field::length(omega) * dt;
    if (!(angle > 0)) return;
    const Vec3 axis = field::unitOr(omega, {0, 0, 1});
    const double s = std::sin(angle / 2);
    const std::array<double, 4> d{std::cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s};
    const auto& q = orientation_;
    std::array<double, 4> p{d[0] * q[0] - d[1] * q[1] - d[2] * q[2] - d[3] * q[3],
                            d[0] * q[1] + d[1] * q[0] + d[2] * q[3] - d[3] * q[2],
                            d[0] * q[2] - d[1] * q[3] + d[2] * q[0] + d[3] * q[1],
                            d[0] * q[3] + d[1] * q[2] - d[2] * q[1] + d[3] * q[0]};
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
    for (double& c : p)
        c /= n;
    orientation_ = p;
}

} // namespace fl::haptics::spacemouse
