#include "haptics/device/usb_products.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace fl::haptics {
namespace {

std::string hex(std::uint16_t id) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", id);
    return text;
}

std::string rulesText() {
    std::ifstream in(FUNCTIONLAB_HAPTICS_RULES);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The udev rules and the product table must not drift apart: a SpaceMouse
// the listing finds but the rules do not open would be "not accessible"
// after the user did everything the docs say.
TEST(UdevRules, EveryKnownDeviceIsCovered) {
    const std::string rules = rulesText();
    ASSERT_FALSE(rules.empty()) << FUNCTIONLAB_HAPTICS_RULES;
    EXPECT_NE(rules.find("KERNEL==\"hidraw*\", ATTRS{idVendor}==\"256f\", MODE=\"0660\""),
              std::string::npos);
    for (const UsbProduct& p : knownUsbProducts()) {
        if (p.vendorId != kLogitechVendorId) continue;
        EXPECT_NE(
            rules.find("ATTRS{idVendor}==\"046d\", ATTRS{idProduct}==\"" + hex(p.productId) + "\""),
            std::string::npos)
            << p.name;
    }
    EXPECT_NE(rules.find("ATTR{idVendor}==\"0403\", ATTR{idProduct}==\"cb48\""), std::string::npos);
}

TEST(UdevRules, EveryRuleGrantsTheSeatAndPlugdevNoMore) {
    std::istringstream lines(rulesText());
    std::string line;
    int rules = 0;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        ++rules;
        EXPECT_NE(line.find("MODE=\"0660\""), std::string::npos) << line;
        EXPECT_NE(line.find("GROUP=\"plugdev\""), std::string::npos) << line;
        EXPECT_NE(line.find("TAG+=\"uaccess\""), std::string::npos) << line;
        // A Logitech rule without a product id would open every Logitech
        // mouse and keyboard to the group.
        if (line.find("\"046d\"") != std::string::npos) {
            EXPECT_NE(line.find("idProduct"), std::string::npos) << line;
        }
    }
    EXPECT_EQ(rules, 13);
}

} // namespace
} // namespace fl::haptics
