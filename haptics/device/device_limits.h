#pragma once
// What each kind of device may be asked to do: one table (wave2.md, Haptics:
// CHAI3D and HAPI device tables). The servo loop clamps force, stiffness and
// damping to these numbers; a value of 0 means the device renders no force.
#include "device/haptic_device.h"

#include <span>
#include <string_view>

namespace fl::haptics {

enum class DeviceModel {
    Simulated,    // the deterministic tool point of the tests and `probe`
    NovintFalcon, // 3-DOF force, libusb back-end
    PhantomOmni,  // 3-DOF force (listed for the table; no back-end yet)
    Touch,        // 3D Systems Touch (listed for the table; no back-end yet)
    SpaceMouse,   // 6-DOF input only, hidapi back-end
};

struct DeviceModelLimits {
    DeviceModel model;
    std::string_view name;
    DeviceLimits limits;
};

// Every model, once, in the order of the enum.
std::span<const DeviceModelLimits> deviceLimitsTable();
DeviceLimits limitsOf(DeviceModel model);
std::string_view modelName(DeviceModel model);

} // namespace fl::haptics
