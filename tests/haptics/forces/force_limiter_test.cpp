// The limits between the force model and the motors (haptics/force_limiter.h).
#include "haptics/force_limiter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace fl::haptics;
using fl::field::Vec3;

namespace {
LimiterSettings settings(double maxForce, double ramp = 0, double change = 0) {
    LimiterSettings s;
    s.maxForce = maxForce;
    s.rampSeconds = ramp;
    s.maxChangePerTick = change;
    return s;
}
} // namespace

TEST(ForceLimiter, ClampsToTheDevicesMaximumKeepingTheDirection) {
    ForceLimiter l(settings(8));
    const Vec3 f = l.limit({30, 40, 0}, 0);
    EXPECT_NEAR(f[0], 4.8, 1e-12);
    EXPECT_NEAR(f[1], 6.4, 1e-12);
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::Clamped);
    EXPECT_EQ(l.limit({1, 0, 0}, 0)[0], 1);
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::None);
}

TEST(ForceLimiter, RampsFromNothingOverTwoSecondsAfterAConnectOrASceneChange) {
    ForceLimiter l(settings(8, 2));
    l.restartRamp(10);
    EXPECT_EQ(l.limit({4, 0, 0}, 10)[0], 0);
    EXPECT_NEAR(l.limit({4, 0, 0}, 11)[0], 2, 1e-12);
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::Ramp);
    EXPECT_NEAR(l.limit({4, 0, 0}, 12)[0], 4, 1e-12);
    EXPECT_NEAR(l.limit({4, 0, 0}, 13)[0], 4, 1e-12);
    l.restartRamp(20); // the scene changed
    EXPECT_NEAR(l.limit({4, 0, 0}, 20.5)[0], 1, 1e-12);
}

TEST(ForceLimiter, LimitsTheChangeOfForcePerTick) {
    ForceLimiter l(settings(8, 0, 0.5));
    EXPECT_NEAR(l.limit({8, 0, 0}, 0)[0], 0.5, 1e-12);
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::Change);
    EXPECT_NEAR(l.limit({8, 0, 0}, 0.001)[0], 1.0, 1e-12);
    EXPECT_NEAR(l.limit({0, 0, 0}, 0.002)[0], 0.5, 1e-12);
}

TEST(ForceLimiter, ANonFiniteForceBecomesNone) {
    ForceLimiter l(settings(8));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(fl::field::length(l.limit({nan, 1, 0}, 0)), 0);
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::NotFinite);
    EXPECT_EQ(fl::field::length(l.limit({INFINITY, 0, 0}, 0)), 0);
}

TEST(ForceLimiter, TheWatchdogStopsTheForceOnStaleDataOrMissedDeadlines) {
    ForceLimiter l(settings(8));
    EXPECT_EQ(l.limit({1, 0, 0}, 0, 0.001)[0], 1);
    EXPECT_EQ(l.limit({1, 0, 0}, 0, 0.050)[0], 0); // 50 ms old
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::Stale);
    EXPECT_EQ(l.limit({1, 0, 0}, 0, std::nan(""))[0], 0);
    EXPECT_EQ(l.limit({1, 0, 0}, 0, 0, true)[0], 1); // one late tick is tolerated
    EXPECT_EQ(l.limit({1, 0, 0}, 0, 0, true)[0], 1);
    EXPECT_EQ(l.limit({1, 0, 0}, 0, 0, true)[0], 0); // the third in a row is not
    EXPECT_EQ(l.lastCut(), ForceLimiter::Cut::Late);
    EXPECT_EQ(l.limit({1, 0, 0}, 0, 0, false)[0], 1); // on time again
}
