#include "haptics/device/polyline_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fl::haptics {
namespace {

using field::Vec3;

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-12) {
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

PolylinePath makePath(std::vector<Vec3> points, double duration) {
    auto path = PolylinePath::make(std::move(points), duration);
    EXPECT_TRUE(path.has_value());
    return *path;
}

TEST(PolylinePath, WalksTheWholePolylineAtConstantSpeed) {
    // Two segments of lengths 3 and 1: at a quarter of 4 s the tool is 1 m
    // along; at 3.5 s it is half-way along the second segment.
    const PolylinePath path = makePath({{0, 0, 0}, {3, 0, 0}, {3, 1, 0}}, 4.0);
    EXPECT_DOUBLE_EQ(path.length(), 4.0);
    EXPECT_DOUBLE_EQ(path.speed(), 1.0);
    expectNear(path.at(1.0).position, {1, 0, 0});
    expectNear(path.at(1.0).velocity, {1, 0, 0});
    expectNear(path.at(3.5).position, {3, 0.5, 0});
    expectNear(path.at(3.5).velocity, {0, 1, 0});
}

TEST(PolylinePath, RestsAtTheEndsOutsideItsDuration) {
    const PolylinePath path = makePath({{1, 2, 3}, {4, 5, 6}}, 2.0);
    expectNear(path.at(-1).position, {1, 2, 3});
    expectNear(path.at(-1).velocity, {0, 0, 0});
    expectNear(path.at(2.0).position, {4, 5, 6});
    expectNear(path.at(5.0).velocity, {0, 0, 0});
    expectNear(path.at(std::numeric_limits<double>::quiet_NaN()).position, {1, 2, 3});
}

TEST(PolylinePath, SpeedIsTheSameOnEverySegmentProperty) {
    const PolylinePath path =
        makePath({{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.3, 0}, {0.1, 0.3, -0.2}, {0, 0, 0}}, 1.3);
    for (int i = 0; i < 1000; ++i) {
        const double t = 1.3 * (i + 0.5) / 1000;
        EXPECT_NEAR(field::length(path.at(t).velocity), path.speed(), 1e-12) << t;
        // The position moves by speed × dt (within a segment or across a corner).
        const double dt = 1e-6;
        const double moved =
            field::length(field::minus(path.at(t + dt).position, path.at(t).position));
        EXPECT_LE(moved, path.speed() * dt * (1 + 1e-6)) << t;
    }
}

TEST(PolylinePath, RepeatedPointsAndSinglePointsHaveNoVelocity) {
    const PolylinePath still = makePath({{1, 1, 1}}, 1.0);
    expectNear(still.at(0.5).position, {1, 1, 1});
    expectNear(still.at(0.5).velocity, {0, 0, 0});
    const PolylinePath repeated = makePath({{0, 0, 0}, {0, 0, 0}, {2, 0, 0}, {2, 0, 0}}, 2.0);
    expectNear(repeated.at(0.5).position, {0.5, 0, 0});
    expectNear(repeated.at(0.5).velocity, {1, 0, 0});
}

TEST(PolylinePath, RefusesWhatCannotBeWalked) {
    std::string error;
    EXPECT_FALSE(PolylinePath::make({}, 1.0, &error));
    EXPECT_NE(error.find("at least one point"), std::string::npos);
    EXPECT_FALSE(PolylinePath::make({{0, 0, 0}}, 0.0, &error));
    EXPECT_NE(error.find("duration"), std::string::npos);
    EXPECT_FALSE(PolylinePath::make({{0, 0, 0}}, std::numeric_limits<double>::infinity(), &error));
    EXPECT_FALSE(PolylinePath::make({{0, std::nan(""), 0}}, 1.0, &error));
    EXPECT_NE(error.find("point 1"), std::string::npos);
    EXPECT_FALSE(PolylinePath::make({{-1e308, 0, 0}, {1e308, 0, 0}}, 1.0, &error));
    EXPECT_NE(error.find("overflows"), std::string::npos);
}

TEST(PathSpec, ReadsPointsSeparatedByColons) {
    const auto points = parsePathSpec("0,0,0.5:1e-3,-2,3");
    ASSERT_TRUE(points);
    ASSERT_EQ(points->size(), 2u);
    expectNear((*points)[0], {0, 0, 0.5});
    expectNear((*points)[1], {1e-3, -2, 3});
}

TEST(PathSpec, NamesThePointAndCoordinateThatIsWrong) {
    std::string error;
    EXPECT_FALSE(parsePathSpec("0,0,0:1,x,2", &error));
    EXPECT_EQ(error, "point 2: coordinate 2 \"x\" is not a finite number");
    EXPECT_FALSE(parsePathSpec("0,0", &error));
    EXPECT_NE(error.find("three coordinates"), std::string::npos);
    EXPECT_FALSE(parsePathSpec("0,0,0:", &error));
    EXPECT_NE(error.find("point 2"), std::string::npos);
    EXPECT_FALSE(parsePathSpec("", &error));
    EXPECT_FALSE(parsePathSpec("1,2,3,4", &error));
    EXPECT_FALSE(parsePathSpec("1,2,inf", &error));
    EXPECT_FALSE(parsePathSpec("1, 2,3", &error));
    EXPECT_FALSE(parsePathSpec("1,2,1e999", &error));
}

} // namespace
} // namespace fl::haptics
