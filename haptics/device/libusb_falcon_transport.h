#pragma once
// The real FalconTransport: libusb-1.0 talking to the Falcon's FTDI chip
// (VID 0x0403, PID 0xCB48; bulk endpoints 0x02 out and 0x81 in). Needs
// write access to the device node: see docs/haptics.md, "Permissions".
#include "device/falcon_transport.h"

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

struct libusb_context;
struct libusb_device_handle;

namespace fl::haptics::falcon {

// A Falcon found on the USB, opened or not.
struct FalconUsbEntry {
    std::string location; // "usb:BUS-PORT[.PORT…]", stable while plugged in
    bool accessible = false;
    std::string problem; // why it cannot be opened, when it cannot
};

// Every Falcon on the USB. Empty, with the reason in *error when given,
// where USB cannot be read at all (no /dev/bus/usb in a container): never
// fails otherwise.
std::vector<FalconUsbEntry> findFalcons(std::string* error = nullptr);

class LibusbFalconTransport : public FalconTransport {
  public:
    // Opens the Falcon at `location` (from findFalcons), or the first one
    // when empty, and claims its interface. None with what to do in *error.
    static std::unique_ptr<LibusbFalconTransport> open(const std::string& location,
                                                       std::string* error);
    ~LibusbFalconTransport() override;
    LibusbFalconTransport(const LibusbFalconTransport&) = delete;
    LibusbFalconTransport& operator=(const LibusbFalconTransport&) = delete;

    bool control(std::uint8_t request, std::uint16_t value) override;
    bool write(std::span<const std::uint8_t> bytes, int timeoutMs) override;
    int read(std::span<std::uint8_t> buffer, int timeoutMs) override;
    std::string lastError() const override { return error_; }

  private:
    LibusbFalconTransport(libusb_context* context, libusb_device_handle* handle);

    libusb_context* context_;
    libusb_device_handle* handle_;
    std::deque<std::uint8_t> pending_; // data read but not yet asked for
    std::vector<std::uint8_t> payload_;
    std::string error_;
};

} // namespace fl::haptics::falcon
