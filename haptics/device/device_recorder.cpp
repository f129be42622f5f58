#include "device/device_recorder.h"

#include "device/device_log.h"

#include <cmath>
#include <fstream>

namespace fl::haptics {

namespace {

bool finiteState(const DeviceState& s) {
    return std::isfinite(s.time) && field::isFinite(s.position) && field::isFinite(s.velocity) &&
           std::isfinite(s.orientation[0]) && std::isfinite(s.orientation[1]) &&
           std::isfinite(s.orientation[2]) && std::isfinite(s.orientation[3]);
}

} // namespace

DeviceRecorder::DeviceRecorder(HapticDevice& device, std::ostream& out)
    : device_(device), out_(out) {
    out_ << formatLogHeader(device_.name(), device_.limits(), true);
}

DeviceRecorder::DeviceRecorder(std::unique_ptr<HapticDevice> device,
                               std::unique_ptr<std::ostream> out)
    : ownedDevice_(std::move(device)), ownedOut_(std::move(out)), device_(*ownedDevice_),
      out_(*ownedOut_) {
    out_ << formatLogHeader(device_.name(), device_.limits(), true);
}

std::unique_ptr<DeviceRecorder> DeviceRecorder::toFile(std::unique_ptr<HapticDevice> device,
                                                       const std::filesystem::path& path,
                                                       std::string* error) {
    if (!device) {
        if (error) *error = "no device to record";
        return nullptr;
    }
    auto out = std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc);
    if (!*out) {
        if (error) *error = "cannot create the log " + path.string();
        return nullptr;
    }
    return std::unique_ptr<DeviceRecorder>(new DeviceRecorder(std::move(device), std::move(out)));
}

DeviceRecorder::~DeviceRecorder() {
    out_.flush();
}

void DeviceRecorder::flush() {
    out_.flush();
}

bool DeviceRecorder::ok() const {
    return !out_.fail();
}

std::optional<DeviceState> DeviceRecorder::read() {
    std::optional<DeviceState> state = device_.read();
    if (!state) return state;
    // A quaternion off unit length by more than the reader accepts would
    // make the log unreadable: such a sample is skipped too.
    const auto& q = state->orientation;
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!finiteState(*state) || (anyWritten_ && !(state->time > lastTime_)) ||
        !(std::abs(norm - 1) <= kQuaternionNormTolerance)) {
        ++skipped_;
        return state;
    }
    out_ << formatLogSample(*state, true);
    anyWritten_ = true;
    lastTime_ = state->time;
    ++written_;
    return state;
}

void DeviceRecorder::command(const field::Vec3& force, const field::Vec3& torque) {
    device_.command(force, torque);
}

} // namespace fl::haptics
