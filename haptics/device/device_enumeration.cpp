#include "device/device_enumeration.h"

#include "device/libusb_falcon_transport.h"
#include "device/usb_products.h"
#include "text/json_text.h"

#include <algorithm>
#include <cstdio>

namespace fl::haptics {

namespace {

std::string hexId(std::uint16_t id) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", id);
    return text;
}

} // namespace

std::string_view kindName(DeviceKind kind) {
    return kind == DeviceKind::NovintFalcon ? "falcon" : "spacemouse";
}

std::vector<DeviceEntry> listDevices(std::vector<std::string>* notes) {
    std::vector<DeviceEntry> devices;
    std::string note;
    for (auto& m : spacemouse::findSpaceMice(&note)) {
        DeviceEntry e;
        e.kind = DeviceKind::SpaceMouse;
        e.name = m.name;
        e.vendorId = m.vendorId;
        e.productId = m.productId;
        e.path = m.path;
        e.accessible = m.accessible;
        e.message = m.problem;
        devices.push_back(std::move(e));
    }
    if (!note.empty() && notes) notes->push_back("SpaceMouse: " + note);
    note.clear();
    for (auto& f : falcon::findFalcons(&note)) {
        DeviceEntry e;
        e.kind = DeviceKind::NovintFalcon;
        e.name = "Novint Falcon";
        e.vendorId = kFtdiVendorId;
        e.productId = kFalconProductId;
        e.path = f.location;
        e.accessible = f.accessible;
        e.message = f.problem;
        devices.push_back(std::move(e));
    }
    if (!note.empty() && notes) notes->push_back("Novint Falcon: " + note);
    return devices;
}

std::unique_ptr<HapticDevice> openDevice(const DeviceEntry& entry, const OpenOptions& options,
                                         std::string* error) {
    if (entry.kind == DeviceKind::SpaceMouse)
        return spacemouse::HidapiSpaceMouse::open(entry.path, entry.name, options.spaceMouse,
                                                  error);
    auto transport = falcon::LibusbFalconTransport::open(entry.path, error);
    if (!transport) return nullptr;
    return falcon::startFalcon(std::move(transport), options.falconFirmware,
                               options.firmwareAttempts, error);
}

std::string formatDeviceListing(const std::vector<DeviceEntry>& devices,
                                const std::vector<std::string>& notes) {
    std::string out;
    if (devices.empty()) out += "No haptic devices found.\n";
    std::size_t nameWidth = 0;
    std::size_t pathWidth = 0;
    for (const DeviceEntry& e : devices) {
        nameWidth = std::max(nameWidth, e.name.size());
        pathWidth = std::max(pathWidth, e.path.size());
    }
    for (const DeviceEntry& e : devices) {
        std::string line = e.name + std::string(nameWidth - e.name.size() + 2, ' ');
        line += hexId(e.vendorId) + ":" + hexId(e.productId) + "  ";
        line += e.path + std::string(pathWidth - e.path.size() + 2, ' ');
        line += e.accessible ? "ready" : "not accessible";
        out += line + "\n";
        if (!e.accessible && !e.message.empty()) out += "  " + e.message + "\n";
    }
    for (const std::string& note : notes)
        out += "(" + note + ")\n";
    return out;
}

std::string deviceListingJson(const std::vector<DeviceEntry>& devices,
                              const std::vector<std::string>& notes) {
    std::string out = "{\"devices\": [";
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const DeviceEntry& e = devices[i];
        out += i ? ", {" : "{";
        out += "\"kind\": ";
        out += text::jsonString(kindName(e.kind));
        out += ", \"name\": ";
        out += text::jsonString(e.name);
        out += ", \"vendor_id\": \"0x" + hexId(e.vendorId) + "\"";
        out += ", \"product_id\": \"0x" + hexId(e.productId) + "\"";
        out += ", \"path\": ";
        out += text::jsonString(e.path);
        out += std::string(", \"accessible\": ") + (e.accessible ? "true" : "false");
        out += ", \"message\": ";
        out += text::jsonString(e.message);
        out += "}";
    }
    out += "], \"notes\": [";
    for (std::size_t i = 0; i < notes.size(); ++i) {
        if (i) out += ", ";
        out += text::jsonString(notes[i]);
    }
    out += "]}";
    return out;
}

} // namespace fl::haptics
