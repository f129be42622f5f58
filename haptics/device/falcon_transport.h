#pragma once
// The seam between the Falcon's logic and its USB: the Falcon talks through
// an FTDI serial chip, so all the device layer needs is the chip's vendor
// control requests and a byte pipe each way. libusb_falcon_transport.h is
// the real one; tests put a simulated Falcon behind this interface and run
// the real codec, kinematics, homing and firmware sequence against it.
#include <cstdint>
#include <span>
#include <string>

namespace fl::haptics::falcon {

class FalconTransport {
  public:
    virtual ~FalconTransport() = default;
    // An FTDI vendor request (host to device, bmRequestType 0x40) with
    // wValue `value` on the chip's first port. False on failure.
    virtual bool control(std::uint8_t request, std::uint16_t value) = 0;
    // Sends all of `bytes`; false if they could not all go within timeoutMs.
    virtual bool write(std::span<const std::uint8_t> bytes, int timeoutMs) = 0;
    // Receives up to buffer.size() data bytes (the FTDI status bytes already
    // taken out): how many came within timeoutMs, 0 if none, -1 on failure.
    virtual int read(std::span<std::uint8_t> buffer, int timeoutMs) = 0;
    // What the last failure was, for the user.
    virtual std::string lastError() const = 0;
};

} // namespace fl::haptics::falcon
