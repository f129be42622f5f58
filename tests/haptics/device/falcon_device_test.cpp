#include "haptics/device/falcon_device.h"
#include "haptics/device/falcon_firmware.h"

#include "fake_falcon.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace fl::haptics::falcon {
namespace {

using field::Vec3;
using testing::FakeFalcon;
using testing::FakeFalconState;

std::vector<std::uint8_t> someFirmware(std::size_t size) {
    std::mt19937 rng(7);
    std::vector<std::uint8_t> bytes(size);
    for (auto& b : bytes)
        b = std::uint8_t(rng());
    return bytes;
}

std::filesystem::path writeFile(const std::string& name, const std::vector<std::uint8_t>& bytes) {
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

struct Rig {
    FakeFalconState state;
    double clock = 0;
    FalconDeviceOptions options() {
        FalconDeviceOptions o;
        o.clock = [this] { return clock; };
        return o;
    }
    std::unique_ptr<FalconDevice> start(const std::filesystem::path& firmware = {},
                                        int attempts = 3, std::string* error = nullptr) {
        return startFalcon(std::make_unique<FakeFalcon>(state), firmware, attempts, error,
                           options());
    }
};

TEST(FalconStart, RunningFirmwareNeedsNoUpload) {
    Rig rig;
    rig.state.firmwareRunning = true;
    std::string error;
    auto falcon = rig.start({}, 3, &error);
    ASSERT_TRUE(falcon) << error;
    EXPECT_EQ(rig.state.uploads, 0);
    EXPECT_EQ(falcon->name(), "Novint Falcon");
    EXPECT_TRUE(falcon->rendersForce());
    EXPECT_DOUBLE_EQ(falcon->limits().maxForce, 8.0);
}

TEST(FalconStart, WithoutFirmwareTheUserIsToldWhatToGive) {
    Rig rig;
    std::string error;
    EXPECT_FALSE(rig.start({}, 3, &error));
    EXPECT_NE(error.find("no firmware running"), std::string::npos) << error;
    EXPECT_NE(error.find("does not ship Novint's firmware"), std::string::npos) << error;
    EXPECT_FALSE(rig.start("/nonexistent/nvent_firmware.bin", 3, &error));
    EXPECT_NE(error.find("/nonexistent/nvent_firmware.bin does not exist"), std::string::npos)
        << error;
    EXPECT_EQ(rig.state.uploads, 0);
}

TEST(FalconStart, UploadsTheUsersFirmwareThroughAFlakyBootLoader) {
    Rig rig;
    rig.state.expectedImage = someFirmware(8492);
    rig.state.handshakeFailures = 7; // answered at the eighth hello
    rig.state.corruptEchoAt = 4000;  // the first upload is corrupted
    const auto path = writeFile("fl_falcon_fw_test.bin", rig.state.expectedImage);
    std::string error;
    auto falcon = rig.start(path, 3, &error);
    std::filesystem::remove(path);
    ASSERT_TRUE(falcon) << error;
    EXPECT_EQ(rig.state.uploads, 2);
    EXPECT_TRUE(rig.state.firmwareRunning);
    EXPECT_EQ(rig.state.received, rig.state.expectedImage);
}

TEST(FalconStart, ACorruptedUploadWithoutRetriesSaysWhere) {
    Rig rig;
    rig.state.expectedImage = someFirmware(1000);
    rig.state.corruptEchoAt = 130;
    const auto path = writeFile("fl_falcon_fw_corrupt.bin", rig.state.expectedImage);
    std::string error;
    EXPECT_FALSE(rig.start(path, 1, &error));
    std::filesystem::remove(path);
    EXPECT_NE(error.find("different byte at 130"), std::string::npos) << error;
    EXPECT_NE(error.find("(1 attempts)"), std::string::npos) << error;
}

TEST(FalconStart, ASilentBootLoaderFailsCleanly) {
    Rig rig;
    rig.state.expectedImage = someFirmware(100);
    rig.state.handshakeFailures = 1000;
    const auto path = writeFile("fl_falcon_fw_silent.bin", rig.state.expectedImage);
    std::string error;
    EXPECT_FALSE(rig.start(path, 2, &error));
    std::filesystem::remove(path);
    EXPECT_NE(error.find("did not answer the handshake"), std::string::npos) << error;
}

TEST(FalconStart, TheWrongFileIsNotTakenForFirmware) {
    Rig rig;
    rig.state.expectedImage = someFirmware(100);
    const auto other = writeFile("fl_falcon_fw_other.bin", someFirmware(99));
    std::string error;
    EXPECT_FALSE(rig.start(other, 1, &error));
    EXPECT_NE(error.find("does not answer"), std::string::npos) << error;
    const auto empty = writeFile("fl_falcon_fw_empty.bin", {});
    EXPECT_FALSE(rig.start(empty, 1, &error));
    EXPECT_NE(error.find("is 0 bytes"), std::string::npos) << error;
    const auto huge = writeFile("fl_falcon_fw_huge.bin", someFirmware(kMaxFirmwareBytes + 1));
    EXPECT_FALSE(rig.start(huge, 1, &error));
    EXPECT_NE(error.find("64 KiB"), std::string::npos) << error;
    for (const auto& p : {other, empty, huge})
        std::filesystem::remove(p);
}

TEST(FalconDevice, ReadsThePositionAboutTheWorkspaceCentre) {
    Rig rig;
    rig.state.firmwareRunning = true;
    rig.state.buttons = 0b0101;
    auto falcon = rig.start();
    ASSERT_TRUE(falcon);
    rig.state.arm = field::plus(kWorkspaceCentre, Vec3{0.01, -0.02, 0.015});
    const auto s = falcon->read();
    ASSERT_TRUE(s);
    // One encoder count moves the effector by a few hundredths of a mm.
    EXPECT_NEAR(s->position[0], 0.01, 2e-4);
    EXPECT_NEAR(s->position[1], -0.02, 2e-4);
    EXPECT_NEAR(s->position[2], 0.015, 2e-4);
    EXPECT_EQ(s->buttons, 0b0101u);
    EXPECT_EQ(s->orientation, (std::array<double, 4>{1, 0, 0, 0}));
}

TEST(FalconDevice, RendersNoForceUntilHomed) {
    Rig rig;
    rig.state.firmwareRunning = true;
    auto falcon = rig.start();
    ASSERT_TRUE(falcon);
    ASSERT_TRUE(falcon->read());
    falcon->command({0, 0, 4}, {});
    ASSERT_FALSE(rig.state.commands.empty());
    EXPECT_EQ(rig.state.commands.back().motors, (std::array<std::int16_t, 3>{0, 0, 0}));
    EXPECT_EQ(rig.state.commands.back().leds, kLedRed);
    EXPECT_TRUE(rig.state.commands.back().homingMode);
    EXPECT_FALSE(falcon->homing().instruction().empty());

    // The answer to a command comes with the next read: one tick late.
    rig.state.homedAxes = 7;
    rig.clock = 0.001;
    ASSERT_TRUE(falcon->read());
    falcon->command({}, {});
    rig.clock = 0.002;
    const auto s = falcon->read();
    ASSERT_TRUE(s);
    EXPECT_TRUE(falcon->homing().homed());
    const Vec3 force{1, -2, 4};
    falcon->command(force, {});
    const FalconCommand& sent = rig.state.commands.back();
    EXPECT_EQ(sent.leds, kLedGreen);
    // The motor values are the Jacobian's answer at the read position.
    const Vec3 at = field::plus(s->position, kWorkspaceCentre);
    EXPECT_EQ(sent.motors, motorValues(*jointTorques(at, force)));
    EXPECT_NE(sent.motors, (std::array<std::int16_t, 3>{0, 0, 0}));
}

TEST(FalconDevice, OnePacketATickWhenTheLoopReadsThenCommands) {
    Rig rig;
    rig.state.firmwareRunning = true;
    rig.state.homedAxes = 7;
    auto falcon = rig.start();
    ASSERT_TRUE(falcon);
    const std::size_t before = rig.state.commands.size();
    for (int tick = 1; tick <= 100; ++tick) {
        rig.clock = tick * 1e-3;
        ASSERT_TRUE(falcon->read()) << tick;
        falcon->command({0, 0, 1}, {});
    }
    // The first read sends the idle command, then each command() is one.
    EXPECT_EQ(rig.state.commands.size() - before, 101u);
    EXPECT_EQ(rig.state.badPackets, 0);
    EXPECT_EQ(falcon->misses(), 0u);
}

TEST(FalconDevice, VelocityFollowsTheArm) {
    Rig rig;
    rig.state.firmwareRunning = true;
    rig.state.homedAxes = 7;
    auto falcon = rig.start();
    ASSERT_TRUE(falcon);
    std::optional<DeviceState> s;
    for (int tick = 0; tick <= 200; ++tick) {
        rig.clock = tick * 1e-3;
        rig.state.arm = field::plus(kWorkspaceCentre, Vec3{0.1 * rig.clock - 0.01, 0, 0});
        s = falcon->read();
        ASSERT_TRUE(s);
        falcon->command({}, {});
    }
    EXPECT_NEAR(s->velocity[0], 0.1, 0.01);
    EXPECT_NEAR(s->velocity[1], 0.0, 0.01);
}

TEST(FalconDevice, LostAnswersAreAskedAgain) {
    Rig rig;
    rig.state.firmwareRunning = true;
    auto falcon = rig.start();
    ASSERT_TRUE(falcon);
    ASSERT_TRUE(falcon->read());
    rig.state.dropAnswers = 1;
    falcon->command({}, {});
    int empty = 0;
    while (!falcon->read() && empty < 10)
        ++empty;
    EXPECT_EQ(empty, 3) << "three empty reads, then the command is sent again";
    EXPECT_EQ(falcon->misses(), 3u);
}

TEST(FalconDevice, TransportFailureIsReportedNotThrown) {
    Rig rig;
    rig.state.firmwareRunning = true;
    auto falcon = rig.start();
    ASSERT_TRUE(falcon);
    rig.state.broken = true;
    EXPECT_FALSE(falcon->read());
    EXPECT_NE(falcon->lastError().find("cable pulled"), std::string::npos);
    falcon->command({1, 0, 0}, {});
    rig.state.broken = false;
    EXPECT_TRUE(falcon->read());
    EXPECT_TRUE(falcon->lastError().empty());
}

TEST(FalconDevice, ClosingTurnsTheMotorsAndLightOff) {
    Rig rig;
    rig.state.firmwareRunning = true;
    rig.state.homedAxes = 7;
    {
        auto falcon = rig.start();
        ASSERT_TRUE(falcon->read());
        falcon->command({0, 0, 5}, {});
        ASSERT_NE(rig.state.commands.back().motors, (std::array<std::int16_t, 3>{0, 0, 0}));
        ASSERT_TRUE(falcon->read());
    }
    EXPECT_EQ(rig.state.commands.back(), FalconCommand{});
}

} // namespace
} // namespace fl::haptics::falcon
