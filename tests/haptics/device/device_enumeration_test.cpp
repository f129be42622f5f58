#include "haptics/device/device_enumeration.h"
#include "haptics/device/usb_products.h"

#include <gtest/gtest.h>

#include <set>

namespace fl::haptics {
namespace {

TEST(UsbProducts, EachProductOnceAndTheFalconKnown) {
    std::set<std::pair<int, int>> seen;
    for (const UsbProduct& p : knownUsbProducts()) {
        EXPECT_TRUE(seen.insert({p.vendorId, p.productId}).second) << p.name;
        EXPECT_TRUE(p.vendorId == kLogitechVendorId || p.vendorId == k3DconnexionVendorId ||
                    p.vendorId == kFtdiVendorId)
            << p.name;
        EXPECT_EQ(p.model == DeviceModel::NovintFalcon, p.vendorId == kFtdiVendorId) << p.name;
    }
    const UsbProduct* falcon = findUsbProduct(0x0403, 0xCB48);
    ASSERT_TRUE(falcon);
    EXPECT_EQ(falcon->name, "Novint Falcon");
    ASSERT_TRUE(findUsbProduct(0x256F, 0xC635));
    EXPECT_EQ(findUsbProduct(0x256F, 0xC635)->name, "SpaceMouse Compact");
    EXPECT_EQ(findUsbProduct(0x046D, 0xC52B), nullptr) << "a Logitech receiver is no SpaceMouse";
    EXPECT_EQ(findUsbProduct(0x0403, 0x6001), nullptr) << "any FTDI cable is no Falcon";
}

// This machine and CI have no devices and maybe no USB at all: listing must
// still work, and whatever it finds must be well-formed.
TEST(DeviceEnumeration, ListingWorksWhateverIsPluggedIn) {
    std::vector<std::string> notes;
    const std::vector<DeviceEntry> devices = listDevices(&notes);
    for (const DeviceEntry& e : devices) {
        EXPECT_FALSE(e.path.empty());
        EXPECT_FALSE(e.name.empty());
        EXPECT_EQ(e.accessible, e.message.empty()) << e.name;
        if (e.kind == DeviceKind::NovintFalcon) {
            EXPECT_EQ(e.path.rfind("usb:", 0), 0u);
        }
    }
    for (const std::string& note : notes)
        EXPECT_FALSE(note.empty());
    EXPECT_FALSE(formatDeviceListing(devices, notes).empty());
    EXPECT_EQ(listDevices().size(), devices.size()) << "notes are optional";
}

TEST(DeviceEnumeration, NothingFoundSaysSoWithTheNotes) {
    const std::vector<std::string> notes{
        "Novint Falcon: USB is not available here (libusb: No such device)"};
    EXPECT_EQ(formatDeviceListing({}, notes),
              "No haptic devices found.\n"
              "(Novint Falcon: USB is not available here (libusb: No such device))\n");
    EXPECT_EQ(deviceListingJson({}, notes),
              "{\"devices\": [], \"notes\": [\"Novint Falcon: USB is not available here "
              "(libusb: No such device)\"]}");
}

std::vector<DeviceEntry> twoDevices() {
    std::vector<DeviceEntry> devices;
    devices.push_back(
        {DeviceKind::SpaceMouse, "SpaceMouse Compact", 0x256F, 0xC635, "/dev/hidraw3", true, ""});
    devices.push_back({DeviceKind::NovintFalcon, "Novint Falcon", 0x0403, 0xCB48, "usb:1-2.4",
                       false, "no permission to use the Falcon: install"});
    return devices;
}

TEST(DeviceEnumeration, TextListingHasOneLineADeviceAndWhatToDo) {
    EXPECT_EQ(formatDeviceListing(twoDevices()),
              "SpaceMouse Compact  256f:c635  /dev/hidraw3  ready\n"
              "Novint Falcon       0403:cb48  usb:1-2.4     not accessible\n"
              "  no permission to use the Falcon: install\n");
}

TEST(DeviceEnumeration, JsonListingIsEscaped) {
    std::vector<DeviceEntry> devices = twoDevices();
    devices[0].name = "Odd \"name\"\n\x01\\";
    EXPECT_EQ(
        deviceListingJson(devices),
        "{\"devices\": [{\"kind\": \"spacemouse\", \"name\": \"Odd \\\"name\\\"\\n\\u0001\\\\\", "
        "\"vendor_id\": \"0x256f\", \"product_id\": \"0xc635\", \"path\": \"/dev/hidraw3\", "
        "\"accessible\": true, \"message\": \"\"}, {\"kind\": \"falcon\", \"name\": \"Novint "
        "Falcon\", \"vendor_id\": \"0x0403\", \"product_id\": \"0xcb48\", \"path\": "
        "\"usb:1-2.4\", \"accessible\": false, \"message\": \"no permission to use the "
        "Falcon: install\"}], \"notes\": []}");
}

TEST(DeviceEnumeration, OpeningWhatIsNotThereFailsWithAReason) {
    std::string error;
    DeviceEntry mouse{DeviceKind::SpaceMouse,   "SpaceMouse", 0x256F, 0xC635,
                      "/dev/fl-no-such-hidraw", true,         ""};
    EXPECT_FALSE(openDevice(mouse, {}, &error));
    EXPECT_NE(error.find("/dev/fl-no-such-hidraw"), std::string::npos) << error;
    DeviceEntry falcon{
        DeviceKind::NovintFalcon, "Novint Falcon", 0x0403, 0xCB48, "usb:99-9", true, ""};
    error.clear();
    EXPECT_FALSE(openDevice(falcon, {}, &error));
    EXPECT_FALSE(error.empty());
}

} // namespace
} // namespace fl::haptics
