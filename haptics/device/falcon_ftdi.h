#pragma once
// The FTDI serial chip inside the Falcon (FT232-class): its vendor control
// requests as the Falcon needs them (wave2.md: firmware upload at 9600 then
// about 140000 baud with a 16 ms latency timer; running at the fast rate
// with a 1 ms latency timer), and the status bytes the chip puts in front
// of every USB packet it sends.
#include "device/falcon_transport.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fl::haptics::falcon::ftdi {

// Vendor requests (libftdi's SIO_* numbers).
inline constexpr std::uint8_t kReset = 0;          // value: 0 reset, 1 purge RX, 2 purge TX
inline constexpr std::uint8_t kModemControl = 1;   // value: mask << 8 | state (DTR 1, RTS 2)
inline constexpr std::uint8_t kFlowControl = 2;    // value 0: none
inline constexpr std::uint8_t kBaudRate = 3;       // value: divisor code of a 3 MHz clock
inline constexpr std::uint8_t kLineProperties = 4; // value: data bits | parity << 8 | stop << 11
inline constexpr std::uint8_t kLatencyTimer = 9;   // value: milliseconds

inline constexpr std::uint16_t kPurgeReceive = 1;
inline constexpr std::uint16_t kPurgeTransmit = 2;
inline constexpr std::uint16_t kDtrHigh = 0x0101;
inline constexpr std::uint16_t kDtrLow = 0x0100;
inline constexpr std::uint16_t kRtsLow = 0x0200;
inline constexpr std::uint16_t kEightDataBitsNoParityOneStop = 8;

// Baud divisor codes: 3 MHz / (integer + fraction), the fraction in the top
// bits (0x4000 is one half).
inline constexpr std::uint16_t kBaud9600 = 0x4138;      // 3 MHz / 312.5
inline constexpr std::uint16_t kBaud140000 = 0x0015;    // 3 MHz / 21 ≈ 142857
inline constexpr std::uint16_t kBaudFalconRun = 0x0002; // 3 MHz / 2 = 1.5 Mbaud

// The chip's packets on the bulk IN endpoint are at most 64 bytes and each
// starts with two modem-status bytes: the data is what follows them.
inline constexpr std::size_t kMaxPacket = 64;
inline constexpr std::size_t kStatusBytes = 2;

// Appends the data bytes of one bulk transfer (several chip packets, the
// last maybe short) to `out`. A trailing fragment of fewer than two bytes
// carries no data.
void appendPayload(std::span<const std::uint8_t> transfer, std::vector<std::uint8_t>& out);

// The run mode of the Falcon's firmware: 1 ms latency, 1.5 Mbaud, both
// buffers purged. False with transport.lastError() on failure.
bool enterRunMode(FalconTransport& transport);
bool purge(FalconTransport& transport);

} // namespace fl::haptics::falcon::ftdi
