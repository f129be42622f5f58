#include "device/libusb_falcon_transport.h"

#include "device/falcon_ftdi.h"
#include "device/usb_products.h"

#include <libusb.h>

#include <algorithm>
#include <array>

namespace fl::haptics::falcon {

namespace {

constexpr unsigned char kEndpointOut = 0x02;
constexpr unsigned char kEndpointIn = 0x81;
constexpr std::uint8_t kVendorOut = 0x40; // LIBUSB_REQUEST_TYPE_VENDOR | RECIPIENT_DEVICE, out
constexpr unsigned kControlTimeoutMs = 1000;

std::string usbError(int code) {
    return libusb_strerror(static_cast<libusb_error>(code));
}

std::string locationOf(libusb_device* device) {
    std::array<std::uint8_t, 8> ports{};
    const int depth = libusb_get_port_numbers(device, ports.data(), int(ports.size()));
    std::string text = "usb:" + std::to_string(libusb_get_bus_number(device)) + "-";
    for (int i = 0; i < depth; ++i)
        text += (i ? "." : "") + std::to_string(ports[std::size_t(i)]);
    if (depth <= 0) text += std::to_string(libusb_get_device_address(device));
    return text;
}

bool isFalcon(libusb_device* device) {
    libusb_device_descriptor d{};
    return libusb_get_device_descriptor(device, &d) == 0 && d.idVendor == kFtdiVendorId &&
           d.idProduct == kFalconProductId;
}

std::string accessAdvice() {
    return "install haptics/device/70-functionlab-haptics.rules into /etc/udev/rules.d/, run "
           "`sudo udevadm control --reload-rules && sudo udevadm trigger`, and unplug and "
           "replug the Falcon (docs/haptics.md, Permissions)";
}

// Owns a libusb context and its device list for one scan.
struct DeviceList {
    libusb_context* context = nullptr;
    libusb_device** devices = nullptr;
    ssize_t count = 0;
    ~DeviceList() {
        if (devices) libusb_free_device_list(devices, 1);
        if (context) libusb_exit(context);
    }
};

bool scan(DeviceList& list, std::string* error) {
    const int rc = libusb_init(&list.context);
    if (rc != 0) {
        list.context = nullptr;
        if (error) *error = "USB is not available here (libusb: " + usbError(rc) + ")";
        return false;
    }
    list.count = libusb_get_device_list(list.context, &list.devices);
    if (list.count < 0) {
        if (error) *error = "cannot list USB devices (libusb: " + usbError(int(list.count)) + ")";
        list.devices = nullptr;
        return false;
    }
    return true;
}

} // namespace

std::vector<FalconUsbEntry> findFalcons(std::string* error) {
    std::vector<FalconUsbEntry> found;
    DeviceList list;
    if (!scan(list, error)) return found;
    for (ssize_t i = 0; i < list.count; ++i) {
        libusb_device* device = list.devices[i];
        if (!isFalcon(device)) continue;
        FalconUsbEntry entry;
        entry.location = locationOf(device);
        // Opening without claiming is how to learn whether we may: the
        // node's permissions decide, and nothing is sent to the device.
        libusb_device_handle* handle = nullptr;
        const int rc = libusb_open(device, &handle);
        if (rc == 0) {
            entry.accessible = true;
            libusb_close(handle);
        } else if (rc == LIBUSB_ERROR_ACCESS) {
            entry.problem = "no permission to use the Falcon: " + accessAdvice();
        } else {
            entry.problem =
                "the Falcon cannot be opened (libusb: " + usbError(rc) + "): unplug and replug it";
        }
        found.push_back(std::move(entry));
    }
    return found;
}

LibusbFalconTransport::LibusbFalconTransport(libusb_context* context, libusb_device_handle* handle)
    : context_(context), handle_(handle) {
    payload_.reserve(512);
}

std::unique_ptr<LibusbFalconTransport> LibusbFalconTransport::open(const std::string& location,
                                                                   std::string* error) {
    auto fail = [&](std::string message) {
        if (error) *error = std::move(message);
        return nullptr;
    };
    libusb_context* context = nullptr;
    if (const int rc = libusb_init(&context); rc != 0)
        return fail("USB is not available here (libusb: " + usbError(rc) + ")");
    libusb_device** devices = nullptr;
    const ssize_t count = libusb_get_device_list(context, &devices);
    libusb_device_handle* handle = nullptr;
    int openRc = LIBUSB_ERROR_NOT_FOUND;
    for (ssize_t i = 0; i < count; ++i) {
        if (!isFalcon(devices[i])) continue;
        if (!location.empty() && locationOf(devices[i]) != location) continue;
        openRc = libusb_open(devices[i], &handle);
        break;
    }
    if (devices) libusb_free_device_list(devices, 1);
    if (openRc != 0) {
        libusb_exit(context);
        if (openRc == LIBUSB_ERROR_NOT_FOUND)
            return fail(location.empty() ? "no Novint Falcon is connected"
                                         : "no Novint Falcon at " + location +
                                               " (unplugged? run `functionlab haptics devices`)");
        if (openRc == LIBUSB_ERROR_ACCESS)
            return fail("no permission to use the Falcon: " + accessAdvice());
        return fail("the Falcon cannot be opened (libusb: " + usbError(openRc) + ")");
    }
    // The kernel's FTDI serial driver may have taken the chip: borrow it.
    libusb_set_auto_detach_kernel_driver(handle, 1);
    if (const int rc = libusb_claim_interface(handle, 0); rc != 0) {
        libusb_close(handle);
        libusb_exit(context);
        return fail("the Falcon is in use by another program (libusb: " + usbError(rc) +
                    "): close it and try again");
    }
    return std::unique_ptr<LibusbFalconTransport>(new LibusbFalconTransport(context, handle));
}

LibusbFalconTransport::~LibusbFalconTransport() {
    libusb_release_interface(handle_, 0);
    libusb_close(handle_);
    libusb_exit(context_);
}

bool LibusbFalconTransport::control(std::uint8_t request, std::uint16_t value) {
    const int rc = libusb_control_transfer(handle_, kVendorOut, request, value, 0, nullptr, 0,
                                           kControlTimeoutMs);
    if (rc < 0) {
        error_ = "USB control request " + std::to_string(request) + " failed: " + usbError(rc);
        return false;
    }
    return true;
}

bool LibusbFalconTransport::write(std::span<const std::uint8_t> bytes, int timeoutMs) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
        int transferred = 0;
        // libusb reads a timeout of 0 as "wait forever": never ask for that.
        const int rc = libusb_bulk_transfer(
            handle_, kEndpointOut, const_cast<unsigned char*>(bytes.data() + sent),
            int(bytes.size() - sent), &transferred, unsigned(std::max(timeoutMs, 1)));
        sent += std::size_t(std::max(transferred, 0));
        if (rc != 0 && sent < bytes.size()) {
            error_ = "USB write failed: " + usbError(rc);
            return false;
        }
    }
    return true;
}

int LibusbFalconTransport::read(std::span<std::uint8_t> buffer, int timeoutMs) {
    if (pending_.empty()) {
        // Ask for whole chip packets: asking for less than the device sends
        // is a libusb overflow error.
        std::array<std::uint8_t, 8 * ftdi::kMaxPacket> transfer{};
        int got = 0;
        const int rc =
            libusb_bulk_transfer(handle_, kEndpointIn, transfer.data(), int(transfer.size()), &got,
                                 unsigned(std::max(timeoutMs, 1)));
        if (rc != 0 && rc != LIBUSB_ERROR_TIMEOUT) {
            error_ = "USB read failed: " + usbError(rc);
            return -1;
        }
        payload_.clear();
        ftdi::appendPayload(std::span(transfer).first(std::size_t(std::max(got, 0))), payload_);
        pending_.insert(pending_.end(), payload_.begin(), payload_.end());
    }
    const std::size_t n = std::min(buffer.size(), pending_.size());
    std::copy_n(pending_.begin(), n, buffer.begin());
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(n));
    return int(n);
}

} // namespace fl::haptics::falcon
