#include "haptics/device/falcon_homing.h"

#include <gtest/gtest.h>

namespace fl::haptics::falcon {
namespace {

FalconReading homedAs(std::uint8_t axes) {
    FalconReading r;
    r.homedAxes = axes;
    return r;
}

TEST(FalconHoming, StartsHomingWithRedLightAndTheRequestOn) {
    FalconHoming homing;
    EXPECT_EQ(homing.phase(), HomingPhase::Homing);
    EXPECT_TRUE(homing.homingMode());
    EXPECT_EQ(homing.leds(), kLedRed);
    EXPECT_NE(homing.instruction().find("move the grip"), std::string::npos);
}

TEST(FalconHoming, NamesTheLegsStillToHome) {
    FalconHoming homing;
    homing.update(homedAs(0b010), 0);
    EXPECT_NE(homing.instruction().find("legs 1 and 3 still to find their index"),
              std::string::npos)
        << homing.instruction();
    homing.update(homedAs(0b011), 0.5);
    EXPECT_NE(homing.instruction().find("leg 3 still to find its index"), std::string::npos)
        << homing.instruction();
}

TEST(FalconHoming, AllThreeLegsHomedTurnsTheLightGreen) {
    FalconHoming homing;
    homing.update(homedAs(0b011), 0);
    EXPECT_FALSE(homing.homed());
    homing.update(homedAs(0b111), 1);
    EXPECT_TRUE(homing.homed());
    EXPECT_EQ(homing.leds(), kLedGreen);
    EXPECT_TRUE(homing.homingMode()) << "the firmware reports homing only while asked";
    EXPECT_TRUE(homing.instruction().empty());
}

TEST(FalconHoming, LostHomingIsNoticedAndHomedAgain) {
    FalconHoming homing;
    homing.update(homedAs(7), 0);
    homing.update(homedAs(0), 5);
    EXPECT_FALSE(homing.homed());
    EXPECT_EQ(homing.homingLosses(), 1);
    EXPECT_EQ(homing.leds(), kLedRed);
    EXPECT_NE(homing.instruction().find("lost its homing"), std::string::npos);
    homing.update(homedAs(0), 6);
    EXPECT_NE(homing.instruction().find("lost its homing"), std::string::npos);
    homing.update(homedAs(7), 7);
    EXPECT_TRUE(homing.homed());
    homing.update(homedAs(1), 8);
    EXPECT_EQ(homing.homingLosses(), 2);
}

TEST(FalconHoming, SaysMoreWhenHomingTakesLong) {
    FalconHoming homing;
    homing.update(homedAs(0), 100);
    EXPECT_EQ(homing.instruction().find("Still not homed"), std::string::npos);
    homing.update(homedAs(0), 100 + FalconHoming::kPatienceSeconds);
    EXPECT_NE(homing.instruction().find("Still not homed after 20 s"), std::string::npos);
}

} // namespace
} // namespace fl::haptics::falcon
