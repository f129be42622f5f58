#include "device/replay_device.h"

#include "device/device_limits.h"

#include <algorithm>
#include <cmath>

namespace fl::haptics {

namespace {

using Quaternion = std::array<double, 4>;

Quaternion normalized(const Quaternion& q) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(n > 0) || !std::isfinite(n)) return {1, 0, 0, 0};
    return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

Quaternion slerp(Quaternion a, const Quaternion& b, double u) {
    double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    // q and -q are the same rotation: turn through the shorter arc.
    if (cosine < 0) {
        for (double& c : a)
            c = -c;
        cosine = -cosine;
    }
    double wa = 1 - u;
    double wb = u;
    // Nearly equal rotations: the sine below vanishes; linear is exact enough.
    if (cosine < 0.9995) {
        const double angle = std::acos(std::min(cosine, 1.0));
        const double sine = std::sin(angle);
        wa = std::sin((1 - u) * angle) / sine;
        wb = std::sin(u * angle) / sine;
    }
    return normalized({wa * a[0] + wb * b[0], wa * a[1] + wb * b[1], wa * a[2] + wb * b[2],
                       wa * a[3] + wb * b[3]});
}

field::Vec3 lerp(const field::Vec3& a, const field::Vec3& b, double u) {
    return field::along(a, field::minus(b, a), u);
}

} // namespace

DeviceState interpolate(const DeviceState& a, const DeviceState& b, double t) {
    const double span = b.time - a.time;
    const double u = span > 0 ? std::clamp((t - a.time) / span, 0.0, 1.0) : 0.0;
    DeviceState s;
    s.time = t;
    s.position = lerp(a.position, b.position, u);
    s.velocity = lerp(a.velocity, b.velocity, u);
    s.orientation = slerp(normalized(a.orientation), normalized(b.orientation), u);
    s.buttons = u < 1 ? a.buttons : b.buttons;
    return s;
}

ReplayDevice::ReplayDevice(DeviceLog log, std::string source)
    : log_(std::move(log)), source_(std::move(source)) {}

std::unique_ptr<ReplayDevice> ReplayDevice::open(const std::filesystem::path& path,
                                                 std::string* error) {
    LogRead read = readDeviceLog(path);
    if (!read.log) {
        if (error) *error = read.error->text();
        return nullptr;
    }
    return std::make_unique<ReplayDevice>(std::move(*read.log), path.filename().string());
}

double ReplayDevice::duration() const {
    if (log_.samples.empty()) return 0;
    return log_.samples.back().time - log_.samples.front().time;
}

bool ReplayDevice::setTime(double t) {
    if (!(t >= time_) || !std::isfinite(t)) return false;
    time_ = t;
    return true;
}

bool ReplayDevice::advance(double dt) {
    if (!(dt >= 0) || !std::isfinite(dt)) return false;
    return setTime(time_ + dt);
}

DeviceLimits ReplayDevice::limits() const {
    return log_.limits.value_or(limitsOf(DeviceModel::Simulated));
}

std::optional<DeviceState> ReplayDevice::read() {
    const auto& samples = log_.samples;
    if (samples.empty() || finished()) return std::nullopt;
    const double t = samples.front().time + time_;
    // The clock only goes forwards, so the cursor does too: a whole replay
    // costs one pass over the samples.
    while (cursor_ + 1 < samples.size() && samples[cursor_ + 1].time <= t)
        ++cursor_;
    if (cursor_ + 1 == samples.size()) {
        DeviceState last = samples.back();
        last.orientation = normalized(last.orientation);
        return last;
    }
    return interpolate(samples[cursor_], samples[cursor_ + 1], t);
}

void ReplayDevice::command(const field::Vec3& force, const field::Vec3&) {
    lastForce_ = force;
}

} // namespace fl::haptics
