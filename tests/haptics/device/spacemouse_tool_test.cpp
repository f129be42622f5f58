#include "haptics/device/spacemouse_tool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace fl::haptics::spacemouse {
namespace {

using field::Vec3;

InputState inputOf(Axes translation, Axes rotation) {
    InputState input;
    Report r;
    r.translation = translation;
    r.rotation = rotation;
    input.apply(r);
    return input;
}

TEST(SpaceMouseTool, DeviceAxesAreRightUpTowardsTheUser) {
    const InputSettings s{0, 100};
    // Raw: x right, y towards the user, z down.
    EXPECT_EQ(toDeviceFrame(inputOf({100, 0, 0}, {}), s).translation, (Vec3{1, 0, 0}));
    EXPECT_EQ(toDeviceFrame(inputOf({0, 100, 0}, {}), s).translation, (Vec3{0, 0, 1}));
    EXPECT_EQ(toDeviceFrame(inputOf({0, 0, 100}, {}), s).translation, (Vec3{0, -1, 0}));
    EXPECT_EQ(toDeviceFrame(inputOf({}, {0, 0, -100}), s).rotation, (Vec3{0, 1, 0}));
}

TEST(SpaceMouseTool, AxisMapIsAProperRotation) {
    const InputSettings s{0, 100};
    Vec3 columns[3];
    for (int i = 0; i < 3; ++i) {
        Axes raw{};
        raw[i] = 100;
        columns[i] = toDeviceFrame(inputOf(raw, {}), s).translation;
    }
    EXPECT_DOUBLE_EQ(field::dot(columns[0], field::cross(columns[1], columns[2])), 1.0);
}

TEST(SpaceMouseTool, DeflectionMovesAtProportionalSpeed) {
    SpaceMouseTool tool;
    for (int i = 0; i < 50; ++i)
        tool.step({{1, 0, -0.5}, {}}, 0.01);
    EXPECT_NEAR(tool.position()[0], 0.05, 1e-12);
    EXPECT_NEAR(tool.position()[2], -0.025, 1e-12);
    EXPECT_NEAR(tool.velocity()[0], 0.1, 1e-12);
    tool.step({}, 0.01);
    EXPECT_EQ(tool.velocity(), (Vec3{0, 0, 0})) << "letting go stops the tool";
}

TEST(SpaceMouseTool, StaysInsideItsWorkspace) {
    MotionSettings m;
    m.workspaceRadius = 0.05;
    SpaceMouseTool tool(m);
    for (int i = 0; i < 200; ++i)
        tool.step({{1, 1, 0}, {}}, 0.01);
    EXPECT_NEAR(field::length(tool.position()), 0.05, 1e-12);
    EXPECT_NEAR(field::length(tool.velocity()), 0, 1e-9);
    // Sliding along the edge still moves.
    tool.step({{1, -1, 0}, {}}, 0.01);
    EXPECT_GT(field::length(tool.velocity()), 0.01);
    EXPECT_LE(field::length(tool.position()), 0.05 + 1e-15);
}

TEST(SpaceMouseTool, TwistTurnsAboutTheAxis) {
    SpaceMouseTool tool;
    for (int i = 0; i < 100; ++i)
        tool.step({{}, {0, 1, 0}}, 0.01);
    // 1.5 rad/s for 1 s about y: (cos 0.75, 0, sin 0.75, 0).
    const auto q = tool.orientation();
    EXPECT_NEAR(q[0], std::cos(0.75), 1e-12);
    EXPECT_NEAR(q[2], std::sin(0.75), 1e-12);
    EXPECT_NEAR(q[1], 0, 1e-15);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1, 1e-14);
}

TEST(SpaceMouseTool, LongPausesAndNonsenseDoNotFlingTheTool) {
    SpaceMouseTool tool;
    tool.step({{1, 0, 0}, {}}, 60.0);
    EXPECT_NEAR(tool.position()[0], 0.01, 1e-12) << "a minute counts as 0.1 s";
    tool.step({{std::nan(""), 0, 0}, {}}, 0.01);
    tool.step({{1, 0, 0}, {}}, -1);
    tool.step({{1, 0, 0}, {}}, std::numeric_limits<double>::quiet_NaN());
    EXPECT_NEAR(tool.position()[0], 0.01, 1e-12);
    EXPECT_TRUE(field::isFinite(tool.position()));
    tool.reset();
    EXPECT_EQ(tool.position(), (Vec3{0, 0, 0}));
    MotionSettings bad;
    bad.maxSpeed = -1;
    bad.workspaceRadius = std::numeric_limits<double>::infinity();
    SpaceMouseTool fallback(bad);
    EXPECT_DOUBLE_EQ(fallback.settings().maxSpeed, MotionSettings{}.maxSpeed);
    EXPECT_DOUBLE_EQ(fallback.settings().workspaceRadius, MotionSettings{}.workspaceRadius);
}

} // namespace
} // namespace fl::haptics::spacemouse
