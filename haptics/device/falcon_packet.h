#pragma once
// The Novint Falcon's wire format with Novint's firmware (studied from
// libnifalcon's FalconFirmwareNovintSDK; our own code). Every packet is 16
// printable bytes framed '<' … '>'. Both directions carry three signed
// 16-bit values as four little-endian nibbles each, every nibble sent as
// 0x41 + nibble ('A'…'P'): motor commands going out, encoder counts coming
// back. Byte 13 (also offset by 0x41) carries the LEDs and the homing-mode
// request going out; coming back, the grip's buttons (low nibble) and which
// encoders have found their index mark (bits 4–6). Byte 14's meaning is
// unknown: sent as 'A', ignored when read.
//
// Packets from the device are hostile until checked: the decoder accepts
// only a frame whose every byte is in range, and the framer finds frames in
// any byte stream, resynchronising after garbage, within a bounded buffer.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fl::haptics::falcon {

inline constexpr std::size_t kPacketSize = 16;
using Packet = std::array<std::uint8_t, kPacketSize>;

// Byte 13 going out. libnifalcon's documentation comment and its enum
// disagree on the LED bits; these follow the enum, which its code uses.
inline constexpr std::uint8_t kHomingModeBit = 0x01;
inline constexpr std::uint8_t kLedGreen = 0x02;
inline constexpr std::uint8_t kLedBlue = 0x04;
inline constexpr std::uint8_t kLedRed = 0x08;

struct FalconCommand {
    std::array<std::int16_t, 3> motors{}; // signed motor drive per leg
    std::uint8_t leds = 0;                // kLedRed | kLedGreen | kLedBlue
    bool homingMode = false;              // ask the firmware to report homing
};

struct FalconReading {
    std::array<std::int16_t, 3> encoders{}; // counts per leg
    std::uint8_t gripButtons = 0;           // 4 bits, bit i: button i down
    std::uint8_t homedAxes = 0;             // 3 bits, bit i: leg i homed
    bool allHomed() const { return (homedAxes & 7) == 7; }
};

bool operator==(const FalconCommand& a, const FalconCommand& b);
bool operator==(const FalconReading& a, const FalconReading& b);

// Host → device. `leds` bits outside red, green and blue are not sent.
Packet encodeCommand(const FalconCommand& command);
// Device → host. Bits of gripButtons above 4 and homedAxes above 3 are not
// sent.
Packet encodeReading(const FalconReading& reading);
// None unless `bytes` is exactly one well-formed packet.
std::optional<FalconCommand> decodeCommand(std::span<const std::uint8_t> bytes);
std::optional<FalconReading> decodeReading(std::span<const std::uint8_t> bytes);

// Finds device packets in the byte stream as it arrives (reads split and
// join packets at will, and a glitch can insert or drop bytes).
class ReadingFramer {
  public:
    // Never more than one partial frame is kept.
    static constexpr std::size_t kMaxBuffered = kPacketSize;

    ReadingFramer() { buffer_.reserve(kPacketSize); }

    // Adds bytes; returns how many packets they completed.
    std::size_t push(std::span<const std::uint8_t> bytes);
    // The newest packet completed so far, if any.
    const std::optional<FalconReading>& latest() const { return latest_; }
    std::uint64_t packets() const { return packets_; }
    // Bytes thrown away while looking for a frame.
    std::uint64_t discarded() const { return discarded_; }
    void clear();

  private:
    std::vector<std::uint8_t> buffer_;
    std::optional<FalconReading> latest_;
    std::uint64_t packets_ = 0;
    std::uint64_t discarded_ = 0;
};

} // namespace fl::haptics::falcon
