#include "device/falcon_packet.h"

#include <algorithm>

namespace fl::haptics::falcon {

namespace {

constexpr std::uint8_t kStart = '<';
constexpr std::uint8_t kEnd = '>';
constexpr std::uint8_t kOffset = 0x41; // 'A'
constexpr std::uint8_t kLedMask = kLedRed | kLedGreen | kLedBlue;
constexpr std::size_t kStatusByte = 13;
constexpr std::size_t kUnknownByte = 14;

void putValues(Packet& p, const std::array<std::int16_t, 3>& values) {
    for (std::size_t i = 0; i < 3; ++i) {
        const auto bits = static_cast<std::uint16_t>(values[i]);
        for (std::size_t n = 0; n < 4; ++n)
            p[1 + 4 * i + n] = static_cast<std::uint8_t>(kOffset + ((bits >> (4 * n)) & 0xF));
    }
}

// The three values, or none when a nibble byte is outside 'A'…'P'.
std::optional<std::array<std::int16_t, 3>> getValues(std::span<const std::uint8_t> p) {
    std::array<std::int16_t, 3> values{};
    for (std::size_t i = 0; i < 3; ++i) {
        std::uint16_t bits = 0;
        for (std::size_t n = 0; n < 4; ++n) {
            const std::uint8_t b = p[1 + 4 * i + n];
            if (b < kOffset || b > kOffset + 0xF) return std::nullopt;
            bits = static_cast<std::uint16_t>(bits | ((b - kOffset) << (4 * n)));
        }
        values[i] = static_cast<std::int16_t>(bits);
    }
    return values;
}

bool framed(std::span<const std::uint8_t> bytes) {
    return bytes.size() == kPacketSize && bytes[0] == kStart && bytes[kPacketSize - 1] == kEnd;
}

// Byte 13 holds a 7-bit value above 'A'.
std::optional<std::uint8_t> statusOf(std::span<const std::uint8_t> bytes) {
    const std::uint8_t b = bytes[kStatusByte];
    if (b < kOffset || b > kOffset + 0x7F) return std::nullopt;
    return static_cast<std::uint8_t>(b - kOffset);
}

} // namespace

bool operator==(const FalconCommand& a, const FalconCommand& b) {
    return a.motors == b.motors && a.leds == b.leds && a.homingMode == b.homingMode;
}

bool operator==(const FalconReading& a, const FalconReading& b) {
    return a.encoders == b.encoders && a.gripButtons == b.gripButtons && a.homedAxes == b.homedAxes;
}

Packet encodeCommand(const FalconCommand& command) {
    Packet p{};
    p[0] = kStart;
    p[kPacketSize - 1] = kEnd;
    putValues(p, command.motors);
    const std::uint8_t status =
        (command.leds & kLedMask) | (command.homingMode ? kHomingModeBit : 0);
    p[kStatusByte] = static_cast<std::uint8_t>(kOffset + status);
    p[kUnknownByte] = kOffset;
    return p;
}

Packet encodeReading(const FalconReading& reading) {
    Packet p{};
    p[0] = kStart;
    p[kPacketSize - 1] = kEnd;
    putValues(p, reading.encoders);
    const std::uint8_t status = (reading.gripButtons & 0x0F) | ((reading.homedAxes & 0x07) << 4);
    p[kStatusByte] = static_cast<std::uint8_t>(kOffset + status);
    p[kUnknownByte] = kOffset;
    return p;
}

std::optional<FalconCommand> decodeCommand(std::span<const std::uint8_t> bytes) {
    if (!framed(bytes)) return std::nullopt;
    const auto values = getValues(bytes);
    const auto status = statusOf(bytes);
    // Going out, only the LED and homing bits exist.
    if (!values || !status || (*status & ~(kLedMask | kHomingModeBit))) return std::nullopt;
    FalconCommand c;
    c.motors = *values;
    c.leds = *status & kLedMask;
    c.homingMode = (*status & kHomingModeBit) != 0;
    return c;
}

std::optional<FalconReading> decodeReading(std::span<const std::uint8_t> bytes) {
    if (!framed(bytes)) return std::nullopt;
    const auto values = getValues(bytes);
    const auto status = statusOf(bytes);
    if (!values || !status) return std::nullopt;
    FalconReading r;
    r.encoders = *values;
    r.gripButtons = *status & 0x0F;
    r.homedAxes = (*status >> 4) & 0x07;
    return r;
}

std::size_t ReadingFramer::push(std::span<const std::uint8_t> bytes) {
    std::size_t completed = 0;
    for (std::uint8_t b : bytes) {
        buffer_.push_back(b);
        // Scan from the front: drop bytes until the buffer starts with a
        // '<'; a full candidate frame either decodes (and is consumed) or
        // its '<' was not a start and is dropped, so the next '<' inside it
        // gets its chance.
        while (!buffer_.empty()) {
            if (buffer_.front() != kStart) {
                buffer_.erase(buffer_.begin());
                ++discarded_;
                continue;
            }
            if (buffer_.size() < kPacketSize) break;
            if (auto reading = decodeReading(std::span(buffer_).first(kPacketSize))) {
                latest_ = *reading;
                ++packets_;
                ++completed;
                buffer_.erase(buffer_.begin(), buffer_.begin() + kPacketSize);
            } else {
                buffer_.erase(buffer_.begin());
                ++discarded_;
            }
        }
    }
    // The scan leaves at most one partial frame (< 16 bytes): the buffer
    // never grows past its reserve, so the servo loop never allocates here.
    return completed;
}

void ReadingFramer::clear() {
    buffer_.clear();
    latest_.reset();
}

} // namespace fl::haptics::falcon
