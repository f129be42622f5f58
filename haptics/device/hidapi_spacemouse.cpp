#include "device/hidapi_spacemouse.h"

#include "device/device_limits.h"
#include "device/usb_products.h"

#include <hidapi.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cwchar>
#include <map>

namespace fl::haptics::spacemouse {

namespace {

// Usage page Generic Desktop, usage Multi-axis Controller: the puck.
constexpr unsigned short kGenericDesktop = 0x01;
constexpr unsigned short kMultiAxisController = 0x08;
// Reports drained per read(): a SpaceMouse sends at most ~125 a second, so
// more than this queued means the caller stalled; the rest wait.
constexpr int kMaxReportsPerRead = 64;

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

std::string narrow(const wchar_t* text) {
    std::string out;
    if (!text) return out;
    for (; *text; ++text)
        out += *text >= 0x20 && *text < 0x7F ? char(*text) : '?';
    return out;
}

std::string hidError(hid_device* device) {
    const std::string text = narrow(hid_error(device));
    return text.empty() ? "unknown HID error" : text;
}

// 0 not a SpaceMouse; higher ranks win among one node's collections.
int rank(const hid_device_info& info) {
    const UsbProduct* known = findUsbProduct(info.vendor_id, info.product_id);
    const bool usageKnown = info.usage_page != 0;
    const bool puck = info.usage_page == kGenericDesktop && info.usage == kMultiAxisController;
    if (usageKnown && !puck) return 0; // e.g. a SpaceMouse Pro's keyboard collection
    if (known && known->model == DeviceModel::SpaceMouse) return puck ? 3 : 2;
    // A newer 3Dconnexion model than the table knows, announcing a puck.
    if (info.vendor_id == k3DconnexionVendorId && puck) return 1;
    return 0;
}

std::string accessAdvice(const std::string& path) {
    return "no permission to read " + path +
           ": install haptics/device/70-functionlab-haptics.rules into /etc/udev/rules.d/, run "
           "`sudo udevadm control --reload-rules && sudo udevadm trigger`, and unplug and "
           "replug the SpaceMouse (docs/haptics.md, Permissions)";
}

} // namespace

std::vector<SpaceMouseEntry> findSpaceMice(std::string* error) {
    std::vector<SpaceMouseEntry> found;
    if (hid_init() != 0) {
        if (error) *error = "HID devices cannot be listed here (hid_init failed)";
        return found;
    }
    hid_device_info* list = hid_enumerate(0, 0);
    std::map<std::string, std::pair<int, SpaceMouseEntry>> byPath;
    for (hid_device_info* info = list; info; info = info->next) {
        const int r = rank(*info);
        if (r == 0 || !info->path) continue;
        SpaceMouseEntry entry;
        entry.path = info->path;
        entry.vendorId = info->vendor_id;
        entry.productId = info->product_id;
        const UsbProduct* known = findUsbProduct(info->vendor_id, info->product_id);
        entry.name = known ? std::string(known->name) : narrow(info->product_string);
        if (entry.name.empty()) entry.name = "SpaceMouse";
        auto [it, inserted] = byPath.try_emplace(entry.path, r, entry);
        if (!inserted && r > it->second.first) it->second = {r, entry};
    }
    hid_free_enumeration(list);
    for (auto& [path, ranked] : byPath) {
        SpaceMouseEntry& entry = ranked.second;
        // Listing comes from sysfs; opening needs the node's permissions.
        entry.accessible = ::access(path.c_str(), R_OK | W_OK) == 0;
        if (!entry.accessible) entry.problem = accessAdvice(path);
        found.push_back(std::move(entry));
    }
    return found;
}

HidapiSpaceMouse::HidapiSpaceMouse(hid_device_* device, std::string name, SpaceMouseOptions options)
    : device_(device), name_(std::move(name)), options_(options), tool_(options.motion) {
    startTime_ = steadySeconds();
}

std::unique_ptr<HidapiSpaceMouse> HidapiSpaceMouse::open(const std::string& path, std::string name,
                                                         SpaceMouseOptions options,
                                                         std::string* error) {
    if (hid_init() != 0) {
        if (error) *error = "HID devices cannot be used here (hid_init failed)";
        return nullptr;
    }
    hid_device* device = hid_open_path(path.c_str());
    if (!device) {
        if (error)
            *error =
                ::access(path.c_str(), F_OK) != 0
                    ? "no SpaceMouse at " + path + " (unplugged? run `functionlab haptics devices`)"
                : ::access(path.c_str(), R_OK | W_OK) != 0
                    ? accessAdvice(path)
                    : "the SpaceMouse at " + path + " cannot be opened: " + hidError(nullptr);
        return nullptr;
    }
    return std::unique_ptr<HidapiSpaceMouse>(
        new HidapiSpaceMouse(device, name.empty() ? "SpaceMouse" : std::move(name), options));
}

HidapiSpaceMouse::~HidapiSpaceMouse() {
    hid_close(device_);
}

DeviceLimits HidapiSpaceMouse::limits() const {
    DeviceLimits limits = limitsOf(DeviceModel::SpaceMouse);
    limits.workspaceRadius = tool_.settings().workspaceRadius;
    return limits;
}

std::optional<DeviceState> HidapiSpaceMouse::read() {
    std::array<std::uint8_t, 64> buffer{};
    for (int i = 0; i < kMaxReportsPerRead; ++i) {
        const int n = hid_read_timeout(device_, buffer.data(), buffer.size(), 0);
        if (n < 0) {
            error_ = "the SpaceMouse stopped answering (" + hidError(device_) +
                     "): unplugged? Open it again";
            return std::nullopt;
        }
        if (n == 0) break;
        ++reports_;
        if (const auto report = parseReport(std::span(buffer).first(std::size_t(n))))
            input_.apply(*report);
    }
    const double now = steadySeconds() - startTime_;
    tool_.step(toDeviceFrame(input_, options_.input), now - lastTime_);
    lastTime_ = now;
    DeviceState state;
    state.time = now;
    state.position = tool_.position();
    state.orientation = tool_.orientation();
    state.velocity = tool_.velocity();
    state.buttons = input_.buttons();
    return state;
}

} // namespace fl::haptics::spacemouse
