#include "haptics/device/simulated_device.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fl::haptics {
namespace {

using field::Vec3;

PolylinePath makePath(std::vector<Vec3> points, double duration) {
    return *PolylinePath::make(std::move(points), duration);
}

// One servo tick: read, compute a force from the state, command it.
template <class ForceOf>
void runServo(SimulatedDevice& device, double until, double period, ForceOf forceOf) {
    while (device.time() < until - 1e-12) {
        device.advance(period);
        const auto state = device.read();
        ASSERT_TRUE(state);
        device.command(forceOf(*state), {});
    }
}

TEST(SimulatedDevice, RestsAtTheOriginWithoutAPath) {
    SimulatedDevice device;
    EXPECT_EQ(device.name(), "Simulated");
    EXPECT_TRUE(device.rendersForce());
    EXPECT_DOUBLE_EQ(device.limits().maxForce, limitsOf(DeviceModel::Simulated).maxForce);
    ASSERT_TRUE(device.advance(0.5));
    const auto state = device.read();
    ASSERT_TRUE(state);
    EXPECT_DOUBLE_EQ(state->time, 0.5);
    EXPECT_EQ(state->position, (Vec3{0, 0, 0}));
    EXPECT_EQ(state->orientation, (std::array<double, 4>{1, 0, 0, 0}));
}

TEST(SimulatedDevice, FollowsAPathExactlyAndRecordsTheForces) {
    SimulatedDevice device;
    device.followPath(makePath({{0, 0, 0}, {0.2, 0, 0}}, 2.0));
    device.advance(0.5);
    auto state = device.read();
    ASSERT_TRUE(state);
    EXPECT_NEAR(state->position[0], 0.05, 1e-15);
    EXPECT_NEAR(state->velocity[0], 0.1, 1e-15);
    device.command({1, 2, 3}, {0.1, 0, 0});
    EXPECT_EQ(device.lastForce(), (Vec3{1, 2, 3}));
    EXPECT_EQ(device.lastTorque(), (Vec3{0.1, 0, 0}));
    EXPECT_EQ(device.commandCount(), 1u);
    // The force does not move a path-driven tool; its work is F · Δx.
    device.advance(0.5);
    state = device.read();
    EXPECT_NEAR(state->position[0], 0.1, 1e-15);
    EXPECT_NEAR(device.forceWork(), 1 * 0.05, 1e-15);
}

TEST(SimulatedDevice, PathTimeStartsWhenThePathIsGiven) {
    SimulatedDevice device;
    device.advance(10);
    device.followPath(makePath({{0, 0, 0}, {1, 0, 0}}, 1.0));
    device.advance(0.25);
    EXPECT_NEAR(device.read()->position[0], 0.25, 1e-12);
}

TEST(SimulatedDevice, ClockOnlyGoesForwards) {
    SimulatedDevice device;
    EXPECT_TRUE(device.setTime(1.0));
    EXPECT_FALSE(device.setTime(0.5));
    EXPECT_FALSE(device.advance(-0.1));
    EXPECT_FALSE(device.advance(std::numeric_limits<double>::quiet_NaN()));
    EXPECT_FALSE(device.setTime(std::numeric_limits<double>::infinity()));
    EXPECT_DOUBLE_EQ(device.time(), 1.0);
    device.holdWithHand(makePath({{0, 0, 0}}, 1.0));
    EXPECT_FALSE(device.advance(1e9)) << "10^13 sub-steps would hang the caller";
    EXPECT_DOUBLE_EQ(device.time(), 1.0);
}

TEST(SimulatedDevice, SilentDeviceSaysNothingButKeepsTime) {
    SimulatedDevice device;
    device.setSilent(true);
    device.advance(0.1);
    EXPECT_FALSE(device.read());
    device.setSilent(false);
    ASSERT_TRUE(device.read());
    EXPECT_DOUBLE_EQ(device.read()->time, 0.1);
}

TEST(SimulatedDevice, ForceThatIsNotFiniteIsNoForce) {
    SimulatedDevice device;
    device.command({std::nan(""), 0, 0}, {0, std::numeric_limits<double>::infinity(), 0});
    EXPECT_EQ(device.lastForce(), (Vec3{0, 0, 0}));
    EXPECT_EQ(device.lastTorque(), (Vec3{0, 0, 0}));
}

TEST(SimulatedDevice, HandPullsTheToolToTheEndOfThePath) {
    SimulatedDevice device;
    device.holdWithHand(makePath({{0, 0, 0}, {0.1, 0.05, 0}}, 0.5));
    device.advance(0.25);
    const Vec3 midway = device.read()->position;
    EXPECT_NEAR(midway[0], 0.05, 5e-3) << "the tool lags the hand only a little";
    device.advance(2.0);
    const auto end = device.read();
    EXPECT_NEAR(end->position[0], 0.1, 1e-5);
    EXPECT_NEAR(end->position[1], 0.05, 1e-5);
    EXPECT_NEAR(field::length(end->velocity), 0, 1e-4);
}

TEST(SimulatedDevice, HeldForceDeflectsTheToolByForceOverStiffness) {
    SimulatedDevice device;
    HandModel hand;
    hand.stiffness = 300;
    device.holdWithHand(makePath({{0, 0, 0}}, 1.0), hand);
    device.command({3, 0, 0}, {});
    device.advance(3.0);
    EXPECT_NEAR(device.read()->position[0], 3.0 / 300, 1e-6);
    // The spring stored ½ k x² and the damper took the rest of F·x.
    EXPECT_NEAR(device.forceWork(), 3.0 * 0.01, 1e-6);
}

TEST(SimulatedDevice, RunsRepeatToTheLastBit) {
    auto run = [] {
        SimulatedDevice device;
        device.holdWithHand(makePath({{0, 0, 0}, {0.05, 0, 0}, {0, 0, 0}}, 1.0));
        std::vector<double> xs;
        runServo(device, 1.0, 1e-3, [&](const DeviceState& s) {
            xs.push_back(s.position[0]);
            return Vec3{s.position[0] > 0.02 ? -800 * (s.position[0] - 0.02) : 0, 0, 0};
        });
        return xs;
    };
    EXPECT_EQ(run(), run());
}

TEST(SimulatedDevice, ViscousForceTakesEnergyOut) {
    SimulatedDevice device;
    device.holdWithHand(makePath({{0, 0, 0}, {0.05, 0, 0}, {0, 0, 0}}, 1.0));
    runServo(device, 1.5, 1e-3,
             [](const DeviceState& s) { return field::scaled(s.velocity, -5.0); });
    EXPECT_LT(device.forceWork(), -1e-4);
}

// A stiff virtual wall sampled at the servo rate and held between samples
// is not passive (Colgate & Brown): over a closed path it gives energy back.
// The measure must see that gain, and see it shrink as the rate rises.
TEST(SimulatedDevice, ForceWorkSeesTheEnergyASampledWallGains) {
    auto gainAt = [](double period) {
        SimulatedDevice device;
        device.followPath(makePath({{0, 0, 0}, {0.03, 0, 0}, {0, 0, 0}}, 0.2));
        runServo(device, 0.25, period, [](const DeviceState& s) {
            const double depth = s.position[0] - 0.01;
            return Vec3{depth > 0 ? -3000 * depth : 0, 0, 0};
        });
        return device.forceWork();
    };
    const double slow = gainAt(4e-3);
    const double fast = gainAt(1e-3);
    EXPECT_GT(slow, 0);
    EXPECT_GT(fast, 0);
    EXPECT_LT(fast, slow);
}

} // namespace
} // namespace fl::haptics
