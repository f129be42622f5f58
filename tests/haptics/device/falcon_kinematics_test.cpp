#include "haptics/device/falcon_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace fl::haptics::falcon {
namespace {

using field::Vec3;

// Points of a ball about the workspace centre, evenly spread and repeatable.
std::vector<Vec3> ballPoints(double radius, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Vec3> points;
    while (int(points.size()) < count) {
        const Vec3 d{u(rng), u(rng), u(rng)};
        if (field::dot(d, d) > 1) continue;
        points.push_back(field::along(kWorkspaceCentre, d, radius));
    }
    return points;
}

TEST(FalconKinematics, EncoderCountsAndAnglesAreInverse) {
    EXPECT_NEAR(encoderToAngle(0), 35 * std::numbers::pi / 180, 1e-15);
    // 1280 counts a motor turn, geared 110 / 14.25 down to the thigh.
    EXPECT_NEAR(encoderToAngle(1280) - encoderToAngle(0), 2 * std::numbers::pi * 14.25 / 110,
                1e-12);
    for (double c : {-30000.0, -1447.0, 0.0, 1.0, 2999.5})
        EXPECT_NEAR(angleToEncoder(encoderToAngle(c)), c, 1e-9);
}

TEST(FalconKinematics, LegsAgreeOnTheAxisBySymmetry) {
    const auto angles = thighAngles(kWorkspaceCentre);
    ASSERT_TRUE(angles);
    EXPECT_NEAR((*angles)[0], (*angles)[1], 1e-12);
    EXPECT_NEAR((*angles)[1], (*angles)[2], 1e-12);
    // Pushed in, the thighs swing back; pulled out, forward.
    const auto in = thighAngles({0, 0, 0.09});
    const auto out = thighAngles({0, 0, 0.15});
    ASSERT_TRUE(in && out);
    EXPECT_LT((*in)[0], (*angles)[0]);
    EXPECT_GT((*out)[0], (*angles)[0]);
}

TEST(FalconKinematics, WholeWorkspaceIsReachable) {
    for (const Vec3& p : ballPoints(0.05, 3000, 1))
        ASSERT_TRUE(thighAngles(p)) << p[0] << " " << p[1] << " " << p[2];
}

TEST(FalconKinematics, ForwardOfInverseIsIdentityProperty) {
    for (const Vec3& p : ballPoints(0.05, 2000, 2)) {
        const auto angles = thighAngles(p);
        ASSERT_TRUE(angles);
        // From the centre, as at start-up, and from a point nearby, as in
        // the servo loop.
        for (const Vec3& guess : {kWorkspaceCentre, field::plus(p, Vec3{1e-3, -1e-3, 5e-4})}) {
            const auto back = effectorPosition(*angles, guess);
            ASSERT_TRUE(back);
            EXPECT_LT(field::length(field::minus(*back, p)), 1e-9);
        }
    }
}

TEST(FalconKinematics, JacobianMatchesFiniteDifferencesProperty) {
    const double h = 1e-6;
    for (const Vec3& p : ballPoints(0.045, 300, 3)) {
        const auto J = angleJacobian(p);
        ASSERT_TRUE(J);
        for (int j = 0; j < 3; ++j) {
            Vec3 step{};
            step[j] = h;
            const auto plus = thighAngles(field::plus(p, step));
            const auto minus = thighAngles(field::minus(p, step));
            ASSERT_TRUE(plus && minus);
            for (int i = 0; i < 3; ++i) {
                const double fd = ((*plus)[i] - (*minus)[i]) / (2 * h);
                EXPECT_NEAR((*J)[i][j], fd, 1e-6 * std::max(1.0, std::abs(fd)))
                    << "leg " << i << " d/dp" << j;
            }
        }
    }
}

TEST(FalconKinematics, TorquesDoTheSameVirtualWorkAsTheForceProperty) {
    std::mt19937 rng(4);
    std::normal_distribution<double> g(0, 1);
    for (const Vec3& p : ballPoints(0.04, 300, 5)) {
        const Vec3 force{3 * g(rng), 3 * g(rng), 3 * g(rng)};
        const auto tau = jointTorques(p, force);
        ASSERT_TRUE(tau);
        const Vec3 delta{1e-7 * g(rng), 1e-7 * g(rng), 1e-7 * g(rng)};
        const auto a = thighAngles(p);
        const auto b = thighAngles(field::plus(p, delta));
        const Vec3 dTheta = field::minus(*b, *a);
        EXPECT_NEAR(field::dot(*tau, dTheta), field::dot(force, delta),
                    1e-4 * field::length(force) * field::length(delta));
    }
}

TEST(FalconKinematics, MotorValuesKeepTheForceDirection) {
    EXPECT_EQ(motorValues({0, 0, 0}), (std::array<std::int16_t, 3>{0, 0, 0}));
    EXPECT_EQ(motorValues({0.1, -0.2, 0}), (std::array<std::int16_t, 3>{-1000, 2000, 0}));
    // Far past the motors' range: the largest is pinned, the rest scaled.
    const auto big = motorValues({100, -50, 25});
    EXPECT_EQ(big[0], -32767);
    EXPECT_NEAR(big[1], 32767 / 2.0, 0.5 + 1e-9);
    EXPECT_NEAR(big[2], -32767 / 4.0, 0.5 + 1e-9);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(motorValues({inf, 0, 0}), (std::array<std::int16_t, 3>{0, 0, 0}));
    EXPECT_EQ(motorValues({std::nan(""), 1, 0}), (std::array<std::int16_t, 3>{0, 0, 0}));
}

TEST(FalconKinematics, UnreachableAndNonsenseGiveNothing) {
    EXPECT_FALSE(thighAngles({0, 0, 1}));
    EXPECT_FALSE(thighAngles({0.5, 0, 0.12}));
    EXPECT_FALSE(thighAngles({std::nan(""), 0, 0.12}));
    EXPECT_FALSE(angleJacobian({0, 0, 1}));
    EXPECT_FALSE(effectorPosition({10, -10, 3}));
    EXPECT_FALSE(effectorPosition({std::nan(""), 0, 0}));
    EXPECT_FALSE(jointTorques(kWorkspaceCentre, {std::nan(""), 0, 0}));
    EXPECT_FALSE(jointTorques({0, 0, 1}, {1, 0, 0}));
    // A guess outside the reach falls back to the centre.
    const auto angles = thighAngles(field::plus(kWorkspaceCentre, Vec3{0.01, 0.02, -0.01}));
    const auto back = effectorPosition(*angles, {5, 5, 5});
    ASSERT_TRUE(back);
    EXPECT_NEAR((*back)[1], 0.02, 1e-9);
}

TEST(FalconKinematics, Mat3Helpers) {
    const Mat3 m{{{2, 0, 1}, {1, 3, 0}, {0, 1, 4}}};
    const auto inv = inverse(m);
    ASSERT_TRUE(inv);
    for (int i = 0; i < 3; ++i) {
        Vec3 e{};
        e[i] = 1;
        const Vec3 back = multiply(m, multiply(*inv, e));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(back[k], e[k], 1e-14);
    }
    EXPECT_EQ(transpose(m)[0], (Vec3{2, 1, 0}));
    EXPECT_FALSE(inverse(Mat3{{{1, 2, 3}, {2, 4, 6}, {0, 1, 0}}}));
    EXPECT_FALSE(inverse(Mat3{}));
}

} // namespace
} // namespace fl::haptics::falcon
