#include "device/usb_products.h"

#include <array>

namespace fl::haptics {

namespace {

constexpr auto SM = DeviceModel::SpaceMouse;

// Product ids as the open drivers list them (spacenavd, libndofdev, OCCT):
// older devices under Logitech's vendor id, newer under 3Dconnexion's.
constexpr std::array<UsbProduct, 21> kProducts{{
    {kLogitechVendorId, 0xC603, "SpaceMouse Plus XT", SM},
    {kLogitechVendorId, 0xC605, "CADman", SM},
    {kLogitechVendorId, 0xC606, "SpaceMouse Classic", SM},
    {kLogitechVendorId, 0xC621, "SpaceBall 5000", SM},
    {kLogitechVendorId, 0xC623, "SpaceTraveler", SM},
    {kLogitechVendorId, 0xC625, "SpacePilot", SM},
    {kLogitechVendorId, 0xC626, "SpaceNavigator", SM},
    {kLogitechVendorId, 0xC627, "SpaceExplorer", SM},
    {kLogitechVendorId, 0xC628, "SpaceNavigator for Notebooks", SM},
    {kLogitechVendorId, 0xC629, "SpacePilot Pro", SM},
    {kLogitechVendorId, 0xC62B, "SpaceMouse Pro", SM},
    {k3DconnexionVendorId, 0xC62E, "SpaceMouse Wireless (cable)", SM},
    {k3DconnexionVendorId, 0xC62F, "SpaceMouse Wireless (receiver)", SM},
    {k3DconnexionVendorId, 0xC631, "SpaceMouse Pro Wireless (cable)", SM},
    {k3DconnexionVendorId, 0xC632, "SpaceMouse Pro Wireless (receiver)", SM},
    {k3DconnexionVendorId, 0xC633, "SpaceMouse Enterprise", SM},
    {k3DconnexionVendorId, 0xC635, "SpaceMouse Compact", SM},
    {k3DconnexionVendorId, 0xC636, "SpaceMouse Module", SM},
    {k3DconnexionVendorId, 0xC63A, "SpaceMouse Wireless BT", SM},
    {k3DconnexionVendorId, 0xC652, "3Dconnexion Universal Receiver", SM},
    {kFtdiVendorId, kFalconProductId, "Novint Falcon", DeviceModel::NovintFalcon},
}};

} // namespace

std::span<const UsbProduct> knownUsbProducts() {
    return kProducts;
}

const UsbProduct* findUsbProduct(std::uint16_t vendorId, std::uint16_t productId) {
    for (const UsbProduct& p : kProducts)
        if (p.vendorId == vendorId && p.productId == productId) return &p;
    return nullptr;
}

} // namespace fl::haptics
