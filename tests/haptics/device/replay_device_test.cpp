#include "haptics/device/device_recorder.h"
#include "haptics/device/replay_device.h"
#include "haptics/device/simulated_device.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace fl::haptics {
namespace {

using field::Vec3;

DeviceLog twoSampleLog() {
    DeviceLog log;
    DeviceState a;
    a.time = 10;
    a.position = {0, 0, 0};
    a.velocity = {1, 0, 0};
    a.buttons = 1;
    DeviceState b = a;
    b.time = 11;
    b.position = {1, 2, 0};
    b.velocity = {3, 0, 0};
    // 90° about z: (cos 45°, 0, 0, sin 45°).
    b.orientation = {std::sqrt(0.5), 0, 0, std::sqrt(0.5)};
    b.buttons = 2;
    log.samples = {a, b};
    log.hasVelocity = true;
    return log;
}

TEST(ReplayDevice, InterpolatesBetweenSamplesAndHoldsButtons) {
    ReplayDevice replay(twoSampleLog(), "probe.log");
    EXPECT_EQ(replay.name(), "Replay of probe.log");
    EXPECT_FALSE(replay.rendersForce());
    EXPECT_DOUBLE_EQ(replay.duration(), 1.0);
    replay.setTime(0.25);
    const auto s = replay.read();
    ASSERT_TRUE(s);
    EXPECT_DOUBLE_EQ(s->time, 10.25);
    EXPECT_DOUBLE_EQ(s->position[0], 0.25);
    EXPECT_DOUBLE_EQ(s->position[1], 0.5);
    EXPECT_DOUBLE_EQ(s->velocity[0], 1.5);
    EXPECT_EQ(s->buttons, 1u);
    // A quarter of the way through a 90° turn is 22.5°: (cos 11.25°, 0, 0, sin 11.25°).
    const double half = 22.5 / 2 * M_PI / 180;
    EXPECT_NEAR(s->orientation[0], std::cos(half), 1e-12);
    EXPECT_NEAR(s->orientation[3], std::sin(half), 1e-12);
    replay.setTime(1.0);
    EXPECT_EQ(replay.read()->buttons, 2u);
    EXPECT_DOUBLE_EQ(replay.read()->position[1], 2.0);
}

TEST(ReplayDevice, SaysNothingAfterTheLastSample) {
    ReplayDevice replay(twoSampleLog());
    replay.setTime(1.0);
    EXPECT_TRUE(replay.read());
    EXPECT_FALSE(replay.finished());
    replay.advance(0.001);
    EXPECT_TRUE(replay.finished());
    EXPECT_FALSE(replay.read());
    EXPECT_FALSE(ReplayDevice(DeviceLog{}).read());
}

TEST(ReplayDevice, ClockOnlyGoesForwards) {
    ReplayDevice replay(twoSampleLog());
    EXPECT_TRUE(replay.setTime(0.5));
    EXPECT_FALSE(replay.setTime(0.25));
    EXPECT_FALSE(replay.advance(-1));
    EXPECT_DOUBLE_EQ(replay.time(), 0.5);
}

TEST(ReplayDevice, TakesTheShorterArcBetweenOppositeSignQuaternions) {
    DeviceLog log = twoSampleLog();
    // -q is the same rotation as q: no turn at all between the samples.
    log.samples[1].orientation = {-1, 0, 0, 0};
    ReplayDevice replay(log);
    replay.setTime(0.5);
    const auto q = replay.read()->orientation;
    EXPECT_NEAR(std::abs(q[0]), 1.0, 1e-12);
}

TEST(ReplayDevice, LimitsComeFromTheLogOrTheSimulatedDevice) {
    DeviceLog log = twoSampleLog();
    EXPECT_DOUBLE_EQ(ReplayDevice(log).limits().maxForce,
                     limitsOf(DeviceModel::Simulated).maxForce);
    log.limits = limitsOf(DeviceModel::NovintFalcon);
    EXPECT_DOUBLE_EQ(ReplayDevice(log).limits().maxForce, 8.0);
}

TEST(ReplayDevice, KeepsTheLastCommandWithoutMovingAnything) {
    ReplayDevice replay(twoSampleLog());
    replay.command({1, 2, 3}, {});
    EXPECT_EQ(replay.lastForce(), (Vec3{1, 2, 3}));
    EXPECT_EQ(replay.read()->position, (Vec3{0, 0, 0}));
}

TEST(ReplayDevice, OpenReportsTheParsersError) {
    const auto path = std::filesystem::temp_directory_path() / "fl_replay_bad.log";
    {
        std::ofstream out(path);
        out << "functionlab-device-log 1\n0 0 0 0 2 0 0 0 0\n";
    }
    std::string error;
    EXPECT_FALSE(ReplayDevice::open(path, &error));
    EXPECT_NE(error.find("fl_replay_bad.log:2:9:"), std::string::npos) << error;
    std::filesystem::remove(path);
}

// Record a simulated run, replay it at the same ticks: the replay reads
// back exactly what the device said.
TEST(DeviceRecorder, RecordedRunReplaysSampleForSample) {
    SimulatedDevice device;
    device.followPath(*PolylinePath::make({{0, 0, 0}, {0.03, 0.01, 0}, {0, 0.02, 0.01}}, 0.2));
    std::ostringstream out;
    std::vector<DeviceState> seen;
    {
        DeviceRecorder recorder(device, out);
        EXPECT_EQ(recorder.name(), "Simulated");
        EXPECT_TRUE(recorder.rendersForce());
        for (int i = 0; i <= 200; ++i) {
            device.setTime(i * 1e-3);
            device.setButtons(i / 50);
            seen.push_back(*recorder.read());
            recorder.command({0, 0, 1}, {});
        }
        EXPECT_EQ(recorder.written(), 201u);
        EXPECT_TRUE(recorder.ok());
    }
    EXPECT_EQ(device.lastForce(), (Vec3{0, 0, 1})) << "commands pass through";
    const LogRead log = parseDeviceLog(out.str(), "run.log");
    ASSERT_TRUE(log.log) << log.error->text();
    EXPECT_EQ(log.log->deviceName, "Simulated");
    EXPECT_TRUE(log.log->hasVelocity);
    ReplayDevice replay(*log.log);
    EXPECT_DOUBLE_EQ(replay.limits().maxStiffness, device.limits().maxStiffness);
    for (int i = 0; i <= 200; ++i) {
        replay.setTime(i * 1e-3);
        const auto s = replay.read();
        ASSERT_TRUE(s) << i;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(s->position[k], seen[i].position[k], 1e-15) << i;
            EXPECT_NEAR(s->velocity[k], seen[i].velocity[k], 1e-12) << i;
        }
        EXPECT_EQ(s->buttons, seen[i].buttons) << i;
    }
}

TEST(DeviceRecorder, SkipsRepeatedTimesAndValuesThatAreNotFinite) {
    SimulatedDevice device;
    std::ostringstream out;
    DeviceRecorder recorder(device, out);
    recorder.read();
    recorder.read(); // same time again
    device.advance(0.001);
    recorder.read();
    EXPECT_EQ(recorder.written(), 2u);
    EXPECT_EQ(recorder.skipped(), 1u);
    device.setSilent(true);
    EXPECT_FALSE(recorder.read());
    EXPECT_EQ(recorder.written(), 2u);
    EXPECT_TRUE(parseDeviceLog(out.str(), "x.log").log);
}

TEST(DeviceRecorder, RecordsIntoAFileItOwns) {
    const auto path = std::filesystem::temp_directory_path() / "fl_recorder_test.log";
    std::string error;
    {
        auto recorder = DeviceRecorder::toFile(std::make_unique<SimulatedDevice>(), path, &error);
        ASSERT_TRUE(recorder) << error;
        recorder->read();
    }
    std::string replayError;
    auto replay = ReplayDevice::open(path, &replayError);
    ASSERT_TRUE(replay) << replayError;
    EXPECT_EQ(replay->name(), "Replay of fl_recorder_test.log");
    EXPECT_EQ(replay->log().samples.size(), 1u);
    std::filesystem::remove(path);
    EXPECT_FALSE(DeviceRecorder::toFile(std::make_unique<SimulatedDevice>(),
                                        "/nonexistent-folder/x.log", &error));
    EXPECT_NE(error.find("cannot create"), std::string::npos);
}

} // namespace
} // namespace fl::haptics
