#include "haptics/device/device_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

namespace fl::haptics {
namespace {

const char* kGood = "functionlab-device-log 1\n"
                    "# t x y z qw qx qy qz buttons\n"
                    "device Novint Falcon\n"
                    "limits 8 3000 20 0.04\n"
                    "0 0 0 0 1 0 0 0 0\n"
                    "\n"
                    "0.001 0.002 0 0 1 0 0 0 1   # trailing comments are not allowed\n";

LogError errorOf(std::string_view text) {
    const LogRead r = parseDeviceLog(text, "probe.log");
    EXPECT_FALSE(r.log);
    return r.error.value_or(LogError{});
}

TEST(DeviceLog, ReadsHeaderDeviceLimitsAndSamples) {
    const LogRead r = parseDeviceLog("functionlab-device-log 1\r\n"
                                     "# comment\n"
                                     "device  Novint Falcon \n"
                                     "limits 8 3000 20 0.04\n"
                                     "0 0 0 0 1 0 0 0 0\n"
                                     "   # indented comment\n"
                                     "0.5\t0.01 0 0 1 0 0 0 5\r\n",
                                     "probe.log");
    ASSERT_TRUE(r.log) << r.error->text();
    EXPECT_EQ(r.log->deviceName, "Novint Falcon");
    ASSERT_TRUE(r.log->limits);
    EXPECT_DOUBLE_EQ(r.log->limits->maxStiffness, 3000);
    ASSERT_EQ(r.log->samples.size(), 2u);
    EXPECT_EQ(r.log->samples[1].buttons, 5u);
    EXPECT_FALSE(r.log->hasVelocity);
    // Velocity estimated from the two positions: 0.01 m in 0.5 s.
    EXPECT_DOUBLE_EQ(r.log->samples[0].velocity[0], 0.02);
    EXPECT_DOUBLE_EQ(r.log->samples[1].velocity[0], 0.02);
}

TEST(DeviceLog, ReadsSamplesWithVelocity) {
    const LogRead r = parseDeviceLog("functionlab-device-log 1\n"
                                     "0 0 0 0 1 0 0 0 0.5 -1 2 3\n",
                                     "v.log");
    ASSERT_TRUE(r.log) << r.error->text();
    EXPECT_TRUE(r.log->hasVelocity);
    EXPECT_EQ(r.log->samples[0].velocity, (field::Vec3{0.5, -1, 2}));
    EXPECT_EQ(r.log->samples[0].buttons, 3u);
    EXPECT_TRUE(r.log->deviceName.empty());
    EXPECT_FALSE(r.log->limits);
}

TEST(DeviceLog, ErrorsNameFileLineColumnAndWhatToDo) {
    EXPECT_EQ(errorOf(kGood).text(),
              "probe.log:7:29: a # comment must be on a line of its own, not after a sample");
    const LogError notALog = errorOf("hello\n");
    EXPECT_EQ(notALog.line, 1);
    EXPECT_NE(notALog.message.find("first line must be \"functionlab-device-log 1\""),
              std::string::npos);
    const LogError newer = errorOf("functionlab-device-log 7\n");
    EXPECT_EQ(newer.column, 24);
    EXPECT_NE(newer.message.find("update FunctionLab"), std::string::npos);
    const LogError badNumber = errorOf("functionlab-device-log 1\n0 0 0 x 1 0 0 0 0\n");
    EXPECT_EQ(badNumber.text(), "probe.log:2:7: z \"x\" is not a finite number (write it as 0.125 "
                                "or 1.25e-3)");
}

struct BadLog {
    const char* text;
    int line;
    int column;
    const char* says;
};

TEST(DeviceLog, RefusesEveryKindOfBadLine) {
    const std::string h = "functionlab-device-log 1\n";
    const std::vector<BadLog> cases = {
        {"", 1, 1, "not a FunctionLab device log"},
        {"functionlab-device-log\n", 1, 1, "not a FunctionLab device log"},
        {"functionlab-device-log one\n", 1, 24, "not a positive whole number"},
        {"functionlab-device-log 0\n", 1, 24, "not a positive whole number"},
        {"functionlab-device-log 1 extra\n", 1, 1, "not a FunctionLab device log"},
        {"functionlab-device-log 1\n", 1, 1, "no samples"},
        {"functionlab-device-log 1\n# only comments\n", 2, 1, "no samples"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 0\n0 1 0 0 1 0 0 0 0\n", 3, 1,
         "increasing time order"},
        {"functionlab-device-log 1\n1 0 0 0 1 0 0 0 0\n0.5 1 0 0 1 0 0 0 0\n", 3, 1,
         "not after the previous sample's 1"},
        {"functionlab-device-log 1\n0 0 0 0 0.5 0 0 0 0\n", 2, 9, "not a unit quaternion"},
        {"functionlab-device-log 1\n0 0 0 0 0 0 0 0 0\n", 2, 9, "not a unit quaternion"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 -1\n", 2, 17, "whole number"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 4294967296\n", 2, 17, "whole number"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 1.5\n", 2, 17, "whole number"},
        {"functionlab-device-log 1\nnan 0 0 0 1 0 0 0 0\n", 2, 1, "time \"nan\""},
        {"functionlab-device-log 1\n0 inf 0 0 1 0 0 0 0\n", 2, 3, "x \"inf\""},
        {"functionlab-device-log 1\n0 1e999 0 0 1 0 0 0 0\n", 2, 3, "x \"1e999\""},
        {"functionlab-device-log 1\n0 +1 0 0 1 0 0 0 0\n", 2, 3, "x \"+1\""},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0\n", 2, 15, "this line has 8"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 0 1 2 3 4\n", 2, 25, "this line has 13"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 0\n1 0 0 0 1 0 0 0 0 0 0 0\n", 3, 1,
         "on every sample or on none"},
        {"functionlab-device-log 1\nsample 0 0 0 1 0 0 0 0\n", 2, 1, "starts no known line"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 0\ndevice late\n", 3, 1,
         "before the first sample"},
        {"functionlab-device-log 1\n0 0 0 0 1 0 0 0 0\nlimits 1 1 1 1\n", 3, 1,
         "before the first sample"},
        {"functionlab-device-log 1\ndevice a\ndevice b\n", 3, 1, "second \"device\""},
        {"functionlab-device-log 1\nlimits 1 1 1 1\nlimits 1 1 1 1\n", 3, 1, "second \"limits\""},
        {"functionlab-device-log 1\nlimits 1 1 1\n", 2, 1, "four numbers"},
        {"functionlab-device-log 1\nlimits 1 -1 1 1\n", 2, 10, "max stiffness is negative"},
        {"functionlab-device-log 1\nlimits 1 1 nan 1\n", 2, 12, "max damping"},
        {"functionlab-device-log 1\ndevice bad\x01name\n", 2, 11, "control character"},
    };
    for (const BadLog& c : cases) {
        const LogError e = errorOf(c.text);
        EXPECT_EQ(e.line, c.line) << c.text << " → " << e.text();
        EXPECT_EQ(e.column, c.column) << c.text << " → " << e.text();
        EXPECT_NE(e.message.find(c.says), std::string::npos) << c.text << " → " << e.text();
        EXPECT_EQ(e.file, "probe.log");
    }
    (void)h;
}

TEST(DeviceLog, BoundsLinesNamesAndSize) {
    const std::string longLine = "functionlab-device-log 1\n" + std::string(5000, '0') + "\n";
    const LogError line = errorOf(longLine);
    EXPECT_EQ(line.line, 2);
    EXPECT_EQ(line.column, 4097);
    const std::string longName = "functionlab-device-log 1\ndevice " + std::string(300, 'a') + "\n";
    EXPECT_NE(errorOf(longName).message.find("longer than 200"), std::string::npos);
    const std::string huge(kMaxDeviceLogBytes + 1, '\n');
    EXPECT_NE(errorOf(huge).message.find("MiB"), std::string::npos);
}

TEST(DeviceLog, HostileTokensAreQuotedShortAndPrintable) {
    const std::string text =
        "functionlab-device-log 1\n0 \x1b[31m" + std::string(100, 'x') + " 0 0 1 0 0 0 0\n";
    const std::string message = errorOf(text).message;
    EXPECT_EQ(message.find('\x1b'), std::string::npos);
    EXPECT_LT(message.size(), 160u);
}

DeviceState randomState(std::mt19937_64& rng, double time) {
    std::uniform_real_distribution<double> pos(-0.2, 0.2);
    std::normal_distribution<double> gauss(0, 1);
    DeviceState s;
    s.time = time;
    s.position = {pos(rng), pos(rng), pos(rng)};
    std::array<double, 4> q{gauss(rng), gauss(rng), gauss(rng), gauss(rng)};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q)
        c /= n;
    s.orientation = q;
    s.velocity = {gauss(rng), gauss(rng), -0.0};
    s.buttons = static_cast<std::uint32_t>(rng());
    return s;
}

bool sameBits(const DeviceState& a, const DeviceState& b) {
    return std::memcmp(&a.time, &b.time, sizeof(double)) == 0 && a.position == b.position &&
           a.orientation == b.orientation && a.velocity == b.velocity && a.buttons == b.buttons &&
           std::signbit(a.velocity[2]) == std::signbit(b.velocity[2]);
}

TEST(DeviceLog, WriteThenReadGivesBackEveryBitProperty) {
    std::mt19937_64 rng(16);
    for (int trial = 0; trial < 50; ++trial) {
        DeviceLog log;
        log.deviceName = trial % 2 ? "Novint Falcon" : "";
        if (trial % 3) log.limits = DeviceLimits{8, 3000, 20, 0.04 + trial * 1e-17};
        log.hasVelocity = true;
        double t = std::ldexp(double(trial), -7) - 3;
        for (int i = 0; i < 40; ++i) {
            t = std::nextafter(t + i * 1e-4, 1e300);
            log.samples.push_back(randomState(rng, t));
        }
        const std::string text = formatDeviceLog(log);
        const LogRead back = parseDeviceLog(text, "roundtrip.log");
        ASSERT_TRUE(back.log) << back.error->text();
        EXPECT_EQ(back.log->deviceName, log.deviceName);
        EXPECT_EQ(back.log->limits.has_value(), log.limits.has_value());
        if (log.limits) {
            EXPECT_EQ(back.log->limits->workspaceRadius, log.limits->workspaceRadius);
        }
        ASSERT_EQ(back.log->samples.size(), log.samples.size());
        for (std::size_t i = 0; i < log.samples.size(); ++i)
            EXPECT_TRUE(sameBits(back.log->samples[i], log.samples[i])) << i;
        EXPECT_EQ(formatDeviceLog(*back.log), text);
    }
}

TEST(DeviceLog, WithoutVelocityTheEstimateIsRecomputedIdentically) {
    std::mt19937_64 rng(3);
    DeviceLog log;
    for (int i = 0; i < 10; ++i)
        log.samples.push_back(randomState(rng, i * 0.001));
    estimateVelocities(log.samples);
    const std::string text = formatDeviceLog(log);
    EXPECT_EQ(text.find("vx"), std::string::npos);
    const LogRead back = parseDeviceLog(text, "x.log");
    ASSERT_TRUE(back.log);
    for (std::size_t i = 0; i < log.samples.size(); ++i)
        EXPECT_TRUE(sameBits(back.log->samples[i], log.samples[i])) << i;
}

TEST(DeviceLog, NameWithLineBreaksIsWrittenOnOneLine) {
    DeviceLog log;
    log.deviceName = "  evil\nname\r ";
    log.samples.push_back(DeviceState{});
    const LogRead back = parseDeviceLog(formatDeviceLog(log), "n.log");
    ASSERT_TRUE(back.log) << back.error->text();
    EXPECT_EQ(back.log->deviceName, "evilname");
}

TEST(DeviceLog, ReadsFilesAndRefusesMissingOnes) {
    const auto path = std::filesystem::temp_directory_path() / "fl_device_log_test.log";
    {
        std::ofstream out(path);
        out << "functionlab-device-log 1\n0 1 2 3 1 0 0 0 0\n";
    }
    const LogRead r = readDeviceLog(path);
    ASSERT_TRUE(r.log);
    EXPECT_EQ(r.log->samples[0].position, (field::Vec3{1, 2, 3}));
    std::filesystem::remove(path);
    const LogRead missing = readDeviceLog(path);
    ASSERT_TRUE(missing.error);
    EXPECT_NE(missing.error->text().find("cannot read the log"), std::string::npos);
}

} // namespace
} // namespace fl::haptics
