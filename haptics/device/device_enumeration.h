#pragma once
// What is plugged in, and opening it: `functionlab haptics devices` lists
// with these, the window's haptics panel offers them. Listing never fails:
// on a machine without USB access (a container, CI) it finds nothing and
// says why in its notes.
#include "device/falcon_device.h"
#include "device/haptic_device.h"
#include "device/hidapi_spacemouse.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fl::haptics {

enum class DeviceKind { SpaceMouse, NovintFalcon };

// "spacemouse", "falcon": stable words for scripts and JSON.
std::string_view kindName(DeviceKind kind);

struct DeviceEntry {
    DeviceKind kind = DeviceKind::SpaceMouse;
    std::string name; // "SpaceMouse Compact", "Novint Falcon"
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string path; // /dev/hidrawN for a SpaceMouse, usb:BUS-PORTS for a Falcon
    bool accessible = false;
    // When present but not accessible: what is wrong and what to do (the
    // udev rule, reloading udev, replugging).
    std::string message;
};

// Every SpaceMouse and Falcon connected. Where a whole back-end cannot look
// (no USB access in a container or CI), it finds nothing and, when `notes`
// is given, appends why: "Novint Falcon: USB is not available here (…)".
std::vector<DeviceEntry> listDevices(std::vector<std::string>* notes = nullptr);

struct OpenOptions {
    // Novint's firmware, supplied by the user (we never ship it); needed
    // only when the Falcon has none running (after every power-on).
    std::filesystem::path falconFirmware;
    int firmwareAttempts = 3;
    spacemouse::SpaceMouseOptions spaceMouse;
};

// Opens a listed device; none with what to do in *error.
std::unique_ptr<HapticDevice> openDevice(const DeviceEntry& entry, const OpenOptions& options,
                                         std::string* error = nullptr);

// The listing for people: one line a device (name, vid:pid, path, "ready"
// or the problem), the notes, or a line saying nothing was found.
std::string formatDeviceListing(const std::vector<DeviceEntry>& devices,
                                const std::vector<std::string>& notes = {});
// The listing as one JSON object:
// {"devices": [{"kind", "name", "vendor_id", "product_id", "path",
//   "accessible", "message"}], "notes": [...]}; ids as "0x256f" strings.
std::string deviceListingJson(const std::vector<DeviceEntry>& devices,
                              const std::vector<std::string>& notes = {});

} // namespace fl::haptics
