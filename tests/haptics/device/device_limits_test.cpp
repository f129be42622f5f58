#include "haptics/device/device_limits.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fl::haptics {
namespace {

TEST(DeviceLimits, TableHasEveryModelOnceInEnumOrder) {
    const auto table = deviceLimitsTable();
    ASSERT_EQ(table.size(), 5u);
    for (std::size_t i = 0; i < table.size(); ++i)
        EXPECT_EQ(static_cast<std::size_t>(table[i].model), i) << table[i].name;
}

TEST(DeviceLimits, FalconMatchesTheAnchorTable) {
    const DeviceLimits falcon = limitsOf(DeviceModel::NovintFalcon);
    EXPECT_DOUBLE_EQ(falcon.maxForce, 8.0);
    EXPECT_DOUBLE_EQ(falcon.maxStiffness, 3000.0);
    EXPECT_DOUBLE_EQ(falcon.maxDamping, 20.0);
    EXPECT_DOUBLE_EQ(falcon.workspaceRadius, 0.04);
    EXPECT_EQ(modelName(DeviceModel::NovintFalcon), "Novint Falcon");
}

TEST(DeviceLimits, OmniAndTouchMatchTheAnchorTable) {
    EXPECT_DOUBLE_EQ(limitsOf(DeviceModel::PhantomOmni).maxForce, 3.3);
    EXPECT_DOUBLE_EQ(limitsOf(DeviceModel::PhantomOmni).maxStiffness, 700.0);
    EXPECT_DOUBLE_EQ(limitsOf(DeviceModel::Touch).maxStiffness, 400.0);
    EXPECT_DOUBLE_EQ(limitsOf(DeviceModel::Touch).workspaceRadius, 0.075);
}

TEST(DeviceLimits, SpaceMouseRendersNoForce) {
    const DeviceLimits mouse = limitsOf(DeviceModel::SpaceMouse);
    EXPECT_EQ(mouse.maxForce, 0.0);
    EXPECT_EQ(mouse.maxStiffness, 0.0);
    EXPECT_GT(mouse.workspaceRadius, 0.0);
}

TEST(DeviceLimits, EveryLimitIsFiniteAndTheSimulatedOneIsTheMostGenerous) {
    const DeviceLimits sim = limitsOf(DeviceModel::Simulated);
    for (const auto& row : deviceLimitsTable()) {
        for (double v : {row.limits.maxForce, row.limits.maxStiffness, row.limits.maxDamping,
                         row.limits.workspaceRadius}) {
            EXPECT_TRUE(std::isfinite(v)) << row.name;
            EXPECT_GE(v, 0.0) << row.name;
        }
        EXPECT_GT(row.limits.workspaceRadius, 0.0) << row.name;
        EXPECT_GE(sim.maxForce, row.limits.maxForce) << row.name;
        EXPECT_GE(sim.maxStiffness, row.limits.maxStiffness) << row.name;
        EXPECT_GE(sim.maxDamping, row.limits.maxDamping) << row.name;
    }
}

} // namespace
} // namespace fl::haptics
