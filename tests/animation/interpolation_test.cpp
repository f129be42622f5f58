// Interpolators and sequencers (ISO/IEC 19775-1 §19, §30): segments, clamping
// at the ends, jumps at repeated keys, HSV colour blending, shortest-arc
// rotations, unit normals, n values per key, steps.
#include "animation/interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace fl::animation;
using K = InterpolatorKind;

namespace {
constexpr double pi = std::numbers::pi;

void expectNear(const std::vector<double>& got, const std::vector<double>& want,
                double tol = 1e-12) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}
} // namespace

TEST(Interpolation, KindsByNodeType) {
    EXPECT_EQ(interpolatorKind(fl::scene::NodeKind::ScalarInterpolator), K::Scalar);
    EXPECT_EQ(interpolatorKind(fl::scene::NodeKind::CoordinateInterpolator2D), K::Coordinate2D);
    EXPECT_EQ(interpolatorKind(fl::scene::NodeKind::IntegerSequencer), K::Integer);
    EXPECT_FALSE(interpolatorKind(fl::scene::NodeKind::Transform).has_value());
}

TEST(Interpolation, ScalarSegmentsAndEnds) {
    const std::vector<double> key{0, 0.5, 1}, value{0, 10, 0};
    expectNear(interpolate(K::Scalar, key, value, -1), {0});
    expectNear(interpolate(K::Scalar, key, value, 0.25), {5});
    expectNear(interpolate(K::Scalar, key, value, 0.5), {10});
    expectNear(interpolate(K::Scalar, key, value, 0.75), {5});
    expectNear(interpolate(K::Scalar, key, value, 2), {0});
    expectNear(interpolate(K::Scalar, key, value, std::nan("")), {0}); // NaN reads as 0
}

TEST(Interpolation, RepeatedKeysJump) {
    const std::vector<double> key{0, 0.5, 0.5, 1}, value{0, 1, 5, 6};
    expectNear(interpolate(K::Scalar, key, value, 0.4999), {0.9998}, 1e-9);
    expectNear(interpolate(K::Scalar, key, value, 0.5), {5});
    expectNear(interpolate(K::Scalar, key, value, 0.75), {5.5});
}

TEST(Interpolation, PositionIsComponentwise) {
    expectNear(interpolate(K::Position, std::vector<double>{0, 1},
                           std::vector<double>{0, 0, 0, 2, 4, -6}, 0.5),
               {1, 2, -3});
}

TEST(Interpolation, ColourBlendsInHsvTheShortWayRound) {
    // Red (hue 0) to blue (hue 2/3): the short way passes magenta.
    expectNear(interpolate(K::Color, std::vector<double>{0, 1},
                           std::vector<double>{1, 0, 0, 0, 0, 1}, 0.5),
               {1, 0, 1});
    // Green to red passes yellow, keeping full brightness (RGB would give dark olive).
    expectNear(interpolate(K::Color, std::vector<double>{0, 1},
                           std::vector<double>{0, 1, 0, 1, 0, 0}, 0.5),
               {1, 1, 0});
    // White to red: grey has no hue, so only saturation changes.
    expectNear(interpolate(K::Color, std::vector<double>{0, 1},
                           std::vector<double>{1, 1, 1, 1, 0, 0}, 0.5),
               {1, 0.5, 0.5});
}

TEST(Interpolation, HsvRoundTrip) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(0, 1);
    for (int i = 0; i < 500; ++i) {
        const std::array<double, 3> rgb{d(rng), d(rng), d(rng)};
        const std::vector<double> hsv = rgbToHsv(rgb);
        expectNear(hsvToRgb(std::span<const double, 3>(hsv.data(), 3)), {rgb[0], rgb[1], rgb[2]},
                   1e-12);
    }
}

TEST(Interpolation, OrientationTakesTheShortestArc) {
    expectNear(interpolate(K::Orientation, std::vector<double>{0, 1},
                           std::vector<double>{0, 1, 0, 0, 0, 1, 0, pi / 2}, 0.5),
               {0, 1, 0, pi / 4});
    // 3 rad and -3 rad about y are 0.28 rad apart through pi, not 6 rad through 0.
    const std::vector<double> r = interpolate(K::Orientation, std::vector<double>{0, 1},
                                              std::vector<double>{0, 1, 0, 3, 0, 1, 0, -3}, 0.5);
    ASSERT_EQ(r.size(), 4u);
    EXPECT_NEAR(std::abs(r[1]), 1, 1e-12);
    EXPECT_NEAR(r[3], pi, 1e-9);
    // A zero axis is no rotation, not NaN.
    const std::vector<double> z = interpolate(K::Orientation, std::vector<double>{0, 1},
                                              std::vector<double>{0, 0, 0, 1, 0, 0, 1, 0}, 0.5);
    for (double c : z)
        EXPECT_TRUE(std::isfinite(c));
}

TEST(Interpolation, NormalsStayUnitLength) {
    const std::vector<double> key{0, 1};
    const std::vector<double> value{1, 0, 0, 0, 0, 2, /* key 1 */ 0, 1, 0, 0, 0, 2};
    const std::vector<double> n = interpolate(K::Normal, key, value, 0.5);
    ASSERT_EQ(n.size(), 6u);
    const double s = std::sqrt(0.5);
    expectNear(n, {s, s, 0, 0, 0, 1});
}

TEST(Interpolation, CoordinatesHoldManyPointsPerKey) {
    const std::vector<double> key{0, 1};
    const std::vector<double> value{0, 0, 0, 1, 1, 1, /* key 1 */ 2, 2, 2, 3, 3, 3};
    expectNear(interpolate(K::Coordinate, key, value, 0.5), {1, 1, 1, 2, 2, 2});
    expectNear(interpolate(K::Coordinate2D, key, std::vector<double>{0, 0, 4, 4}, 0.25), {1, 1});
}

TEST(Interpolation, SequencersStep) {
    const std::vector<double> key{0, 0.5, 1}, value{3, 7, 9};
    expectNear(interpolate(K::Integer, key, value, 0.49), {3});
    expectNear(interpolate(K::Integer, key, value, 0.5), {7});
    expectNear(interpolate(K::Integer, key, value, 5), {9});
    expectNear(interpolate(K::Boolean, key, std::vector<double>{1, 0, 1}, 0.7), {0});
}

TEST(Interpolation, UnusableKeysAreExplainedAndGiveNothing) {
    EXPECT_NE(checkKeys(K::Scalar, {}, {}).find("empty"), std::string::npos);
    EXPECT_NE(checkKeys(K::Scalar, std::vector<double>{0, 1}, std::vector<double>{1})
                  .find("1 values for 2 keys"),
              std::string::npos);
    EXPECT_NE(
        checkKeys(K::Scalar, std::vector<double>{1, 0}, std::vector<double>{1, 2}).find("decrease"),
        std::string::npos);
    EXPECT_NE(checkKeys(K::Coordinate, std::vector<double>{0, 1}, std::vector<double>{1, 2, 3})
                  .find("whole number"),
              std::string::npos);
    EXPECT_NE(checkKeys(K::Scalar, std::vector<double>{0}, std::vector<double>{NAN}).find("finite"),
              std::string::npos);
    EXPECT_TRUE(
        interpolate(K::Scalar, std::vector<double>{1, 0}, std::vector<double>{1, 2}, 0.5).empty());
    EXPECT_EQ(checkKeys(K::Scalar, std::vector<double>{0, 1}, std::vector<double>{1, 2}), "");
}
