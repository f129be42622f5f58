#include "device/falcon_device.h"

#include "device/falcon_firmware.h"
#include "device/falcon_ftdi.h"

#include <array>
#include <chrono>

namespace fl::haptics::falcon {

using field::Vec3;

namespace {

// Empty reads before the packet is taken as lost and the command re-sent.
constexpr int kResendAfterEmptyReads = 3;

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

FalconDevice::FalconDevice(std::unique_ptr<FalconTransport> transport, FalconDeviceOptions options)
    : transport_(std::move(transport)), options_(std::move(options)) {
    startTime_ = options_.clock ? 0 : steadySeconds();
    held_.homingMode = homing_.homingMode();
    held_.leds = homing_.leds();
}

FalconDevice::~FalconDevice() {
    if (!transport_) return;
    FalconCommand off;
    const Packet packet = encodeCommand(off);
    transport_->write(packet, 10);
}

double FalconDevice::now() const {
    return options_.clock ? options_.clock() : steadySeconds() - startTime_;
}

bool FalconDevice::send() {
    const Packet packet = encodeCommand(held_);
    if (!transport_->write(packet, options_.ioTimeoutMs)) {
        error_ = "writing to the Falcon failed: " + transport_->lastError();
        return false;
    }
    sent_ = held_;
    outstanding_ = true;
    emptyReads_ = 0;
    return true;
}

std::optional<DeviceState> FalconDevice::read() {
    if (!outstanding_ && !send()) return std::nullopt;
    std::array<std::uint8_t, 64> buffer{};
    const int n = transport_->read(buffer, options_.ioTimeoutMs);
    if (n < 0) {
        error_ = "reading from the Falcon failed: " + transport_->lastError();
        return std::nullopt;
    }
    framer_.push(std::span(buffer).first(std::size_t(n)));
    if (framer_.packets() == seenPackets_) {
        ++misses_;
        if (++emptyReads_ >= kResendAfterEmptyReads) outstanding_ = false;
        return std::nullopt;
    }
    seenPackets_ = framer_.packets();
    outstanding_ = false;
    error_.clear();
    const FalconReading& reading = *framer_.latest();
    const double time = now();
    homing_.update(reading, time);
    held_.homingMode = homing_.homingMode();
    held_.leds = homing_.leds();

    const Vec3 angles{encoderToAngle(reading.encoders[0]), encoderToAngle(reading.encoders[1]),
                      encoderToAngle(reading.encoders[2])};
    const auto position = effectorPosition(angles, kinematicPosition_.value_or(kWorkspaceCentre));
    if (!position) return std::nullopt; // encoders no arm can show: not trusted
    if (kinematicPosition_ && time > lastTime_) {
        const double dt = time - lastTime_;
        const Vec3 raw = field::scaled(field::minus(*position, *kinematicPosition_), 1 / dt);
        const double alpha = dt / (dt + options_.velocityTimeConstant);
        velocity_ = field::plus(velocity_, field::scaled(field::minus(raw, velocity_), alpha));
    }
    kinematicPosition_ = position;
    lastTime_ = time;

    DeviceState state;
    state.time = time;
    state.position = field::minus(*position, kWorkspaceCentre);
    state.velocity = velocity_;
    state.buttons = reading.gripButtons;
    return state;
}

void FalconDevice::command(const Vec3& force, const Vec3&) {
    held_.motors = {0, 0, 0};
    if (homing_.homed() && kinematicPosition_) {
        if (const auto torques = jointTorques(*kinematicPosition_, force))
            held_.motors = motorValues(*torques);
    }
    if (!outstanding_) send();
}

std::unique_ptr<FalconDevice> startFalcon(std::unique_ptr<FalconTransport> transport,
                                          const std::filesystem::path& firmwareFile, int attempts,
                                          std::string* error, FalconDeviceOptions options) {
    auto fail = [&](std::string message) {
        if (error) *error = std::move(message);
        return nullptr;
    };
    if (!transport) return fail("no Falcon transport");
    if (!ftdi::enterRunMode(*transport))
        return fail("could not set up the Falcon's USB serial chip (" + transport->lastError() +
                    "): unplug and replug the Falcon");
    if (!firmwareAnswers(*transport)) {
        // A Falcon boots without firmware: it must be uploaded after every
        // power-on, from the user's own copy.
        std::string why;
        const auto image = readFirmwareFile(firmwareFile, &why);
        if (!image) return fail("the Falcon has no firmware running; " + why);
        if (!loadFirmware(*transport, *image, attempts, &why))
            return fail("loading the Falcon's firmware failed: " + why);
        if (!firmwareAnswers(*transport))
            return fail("the firmware " + firmwareFile.string() +
                        " was uploaded but the Falcon does not answer: is it Novint's Falcon "
                        "firmware (nvent_firmware.bin)? Unplug the Falcon's power and USB and "
                        "try again");
    }
    return std::make_unique<FalconDevice>(std::move(transport), std::move(options));
}

} // namespace fl::haptics::falcon
