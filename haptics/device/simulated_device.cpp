#include "device/simulated_device.h"

#include <cmath>

namespace fl::haptics {

using field::Vec3;

namespace {
constexpr double kMaxSubSteps = 1e7;
}

SimulatedDevice::SimulatedDevice(DeviceLimits limits) : limits_(limits) {}

void SimulatedDevice::followPath(PolylinePath path) {
    path_ = std::move(path);
    drive_ = Drive::Path;
    pathStart_ = time_;
    const PathSample s = handAt(time_);
    position_ = s.position;
    velocity_ = s.velocity;
}

void SimulatedDevice::holdWithHand(PolylinePath path, HandModel hand) {
    followPath(std::move(path));
    drive_ = Drive::Hand;
    // A hand with no mass, a negative spring or a step of zero would make the
    // integrator meaningless: keep the defaults for those parts.
    const HandModel defaults;
    hand_.toolMass =
        hand.toolMass > 0 && std::isfinite(hand.toolMass) ? hand.toolMass : defaults.toolMass;
    hand_.stiffness =
        hand.stiffness >= 0 && std::isfinite(hand.stiffness) ? hand.stiffness : defaults.stiffness;
    hand_.damping =
        hand.damping >= 0 && std::isfinite(hand.damping) ? hand.damping : defaults.damping;
    hand_.maxStep =
        hand.maxStep > 0 && std::isfinite(hand.maxStep) ? hand.maxStep : defaults.maxStep;
}

PathSample SimulatedDevice::handAt(double t) const {
    if (!path_) return {};
    return path_->at(t - pathStart_);
}

bool SimulatedDevice::advance(double dt) {
    if (!(dt >= 0) || !std::isfinite(dt)) return false;
    return setTime(time_ + dt);
}

bool SimulatedDevice::setTime(double t) {
    if (!(t >= time_) || !std::isfinite(t)) return false;
    if (drive_ == Drive::Hand) {
        // Fixed sub-steps of equal length: the same (start, end) always
        // takes the same steps, so runs repeat exactly.
        const double span = t - time_;
        const double count = std::ceil(span / hand_.maxStep);
        // A jump of hours at 0.1 ms steps would hang the caller: refuse it.
        if (count > kMaxSubSteps) return false;
        const auto steps = static_cast<long long>(count);
        const double start = time_;
        for (long long i = 1; i <= steps; ++i) {
            const double next = i == steps ? t : start + span * (double(i) / count);
            step(next - time_);
            time_ = next;
        }
        time_ = t;
        return true;
    }
    const Vec3 before = position_;
    time_ = t;
    if (drive_ == Drive::Path) {
        const PathSample s = handAt(time_);
        position_ = s.position;
        velocity_ = s.velocity;
    }
    work_ += field::dot(lastForce_, field::minus(position_, before));
    return true;
}

void SimulatedDevice::step(double dt) {
    // Semi-implicit Euler on the tool mass: velocity from the forces at the
    // start of the step, then position from the new velocity. The hand's
    // pull is evaluated at the step's end time so a fast hand is not late.
    const PathSample hand = handAt(time_ + dt);
    const Vec3 stretch = field::minus(hand.position, position_);
    const Vec3 slip = field::minus(hand.velocity, velocity_);
    const Vec3 pull =
        field::plus(field::scaled(stretch, hand_.stiffness), field::scaled(slip, hand_.damping));
    const Vec3 total = field::plus(pull, lastForce_);
    velocity_ = field::along(velocity_, total, dt / hand_.toolMass);
    const Vec3 displacement = field::scaled(velocity_, dt);
    work_ += field::dot(lastForce_, displacement);
    position_ = field::plus(position_, displacement);
}

std::optional<DeviceState> SimulatedDevice::read() {
    if (silent_) return std::nullopt;
    DeviceState state;
    state.time = time_;
    state.position = position_;
    state.velocity = velocity_;
    state.buttons = buttons_;
    return state;
}

void SimulatedDevice::command(const Vec3& force, const Vec3& torque) {
    // A force that is not finite would poison the integrator for good: the
    // device treats it as no force, as a motor driver refuses a bad value.
    lastForce_ = field::isFinite(force) ? force : Vec3{};
    lastTorque_ = field::isFinite(torque) ? torque : Vec3{};
    ++commandCount_;
}

} // namespace fl::haptics
