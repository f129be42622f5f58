#include "pointer_device.h"

namespace fl::haptics {

PointerDevice::PointerDevice(DeviceLimits limits) : limits_(limits) {}

void PointerDevice::moveTo(const field::Vec3& position, std::optional<field::Vec3> approach) {
    if (!field::isFinite(position)) return;
    std::lock_guard lock(mutex_);
    if (!placed_ && approach && field::isFinite(*approach)) approach_ = approach;
    placed_ = true;
    previous_ = position_;
    previousAt_ = at_;
    position_ = position;
    at_ = Clock::now();
}

field::Vec3 PointerDevice::lastForce() const {
    std::lock_guard lock(mutex_);
    return force_;
}

std::optional<DeviceState> PointerDevice::read() {
    // The servo thread never waits for the window: if the pointer is being
    // moved this instant, the last state stands for one more tick.
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock) return lastRead_;
    if (!placed_) return std::nullopt; // nowhere yet: no force
    DeviceState s;
    const auto now = Clock::now();
    s.time = std::chrono::duration<double>(now.time_since_epoch()).count();
    s.position = position_;
    if (approach_) { // one tick outside first
        s.position = *approach_;
        approach_.reset();
        lastRead_ = s;
        return s;
    }
    // The mouse moves in jumps: the velocity of the last jump, and none once
    // the pointer has rested for 50 ms.
    const double dt = std::chrono::duration<double>(at_ - previousAt_).count();
    const double rest = std::chrono::duration<double>(now - at_).count();
    if (dt > 0 && rest < 0.05)
        s.velocity = field::scaled(field::minus(position_, previous_), 1 / dt);
    lastRead_ = s;
    return s;
}

void PointerDevice::command(const field::Vec3& force, const field::Vec3&) {
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (lock) force_ = force; // else the window sees it next tick
}

} // namespace fl::haptics
