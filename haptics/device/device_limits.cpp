#include "device/device_limits.h"

#include <array>

namespace fl::haptics {

namespace {

// Force (N), stiffness (N/m), damping (N·s/m), workspace radius (m).
// Falcon, Omni and Touch: CHAI3D's device tables (wave2.md). The Omni's
// workspace is 160 × 120 × 70 mm: 0.035 m is the largest sphere inside it.
// The simulated device is generous so tests can probe stiff scenes, yet
// finite so the servo loop's clamps are exercised there too. The
// SpaceMouse renders nothing; its radius bounds where its input can drive
// the tool point (spacemouse_tool.h).
constexpr std::array<DeviceModelLimits, 5> kTable{{
    {DeviceModel::Simulated, "Simulated", {50.0, 20000.0, 200.0, 1.0}},
    {DeviceModel::NovintFalcon, "Novint Falcon", {8.0, 3000.0, 20.0, 0.04}},
    {DeviceModel::PhantomOmni, "Phantom Omni", {3.3, 700.0, 5.0, 0.035}},
    {DeviceModel::Touch, "Touch", {3.3, 400.0, 4.0, 0.075}},
    {DeviceModel::SpaceMouse, "SpaceMouse", {0.0, 0.0, 0.0, 0.1}},
}};

const DeviceModelLimits& entryOf(DeviceModel model) {
    return kTable[static_cast<std::size_t>(model)];
}

} // namespace

std::span<const DeviceModelLimits> deviceLimitsTable() {
    return kTable;
}

DeviceLimits limitsOf(DeviceModel model) {
    return entryOf(model).limits;
}

std::string_view modelName(DeviceModel model) {
    return entryOf(model).name;
}

} // namespace fl::haptics
