#pragma once
// The USB devices FunctionLab knows, by vendor and product id: the
// 3Dconnexion SpaceMice (Logitech's vendor id for the older ones,
// 3Dconnexion's own for the newer) and the Novint Falcon (an FTDI chip with
// Novint's product id). Logitech's vendor id also covers its mice and
// keyboards, so under it only the listed products are SpaceMice.
#include "device/device_limits.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace fl::haptics {

inline constexpr std::uint16_t kLogitechVendorId = 0x046D;
inline constexpr std::uint16_t k3DconnexionVendorId = 0x256F;
inline constexpr std::uint16_t kFtdiVendorId = 0x0403;
inline constexpr std::uint16_t kFalconProductId = 0xCB48;

struct UsbProduct {
    std::uint16_t vendorId;
    std::uint16_t productId;
    std::string_view name;
    DeviceModel model;
};

std::span<const UsbProduct> knownUsbProducts();
// The known product with these ids, or nullptr.
const UsbProduct* findUsbProduct(std::uint16_t vendorId, std::uint16_t productId);

} // namespace fl::haptics
