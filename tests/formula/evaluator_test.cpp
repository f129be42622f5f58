#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fl::formula {
namespace {

using testing::eval;

TEST(Evaluator, PaperWatermelonGeometry) {
    const char* src = "(1-x^2-y^2-z^2) & (-((z-x) & y & z))";
    // inside the sphere, outside the cut-out wedge
    double x = -0.5, y = 0.1, z = 0.1;
    double expected = std::min(1 - x * x - y * y - z * z, -std::min(std::min(z - x, y), z));
    EXPECT_EQ(eval(src, x, y, z), expected);
    EXPECT_LT(eval(src, 0.1, 0.3, 0.3), 0.0); // inside the wedge: cut away
    EXPECT_LT(eval(src, 2, 0, 0), 0.0);       // outside the sphere
}

TEST(Evaluator, Primitives) {
    EXPECT_DOUBLE_EQ(eval("sphere(2)", 1, 0, 0), 3.0);
    EXPECT_DOUBLE_EQ(eval("sphere(1, 0, 0, 1)", 1, 0, 0), 1.0);
    EXPECT_DOUBLE_EQ(eval("box(1, 2, 3)", 0.5, 0, 0), 0.5);
    EXPECT_DOUBLE_EQ(eval("box(1, 1, 1, 1, 2, 3)", 1, 1, 4), 0.0);
    EXPECT_DOUBLE_EQ(eval("ellipsoid(0, 0, 0, 2, 1, 1)", 1, 0, 0), 0.75);
    EXPECT_DOUBLE_EQ(eval("cylinder(1, 2)", 0.5, 0.5, 0), 0.5);
    EXPECT_LT(eval("cylinder(1, 2)", 0, 1.5, 0), 0.0);
    EXPECT_GT(eval("cone(1, 2)", 0, -0.5, 0), 0.0);
    EXPECT_LT(eval("cone(1, 2)", 0.6, 0.5, 0), 0.0);
    EXPECT_NEAR(eval("torus(1, 0.25)", 1, 0, 0), 0.0625, 1e-15);
    EXPECT_LT(eval("torus(1, 0.25)", 0, 0, 0), 0.0);
    EXPECT_DOUBLE_EQ(eval("halfspace(0, 1, 0, 0)", 0, 2, 0), 2.0);
    EXPECT_NEAR(eval("superellipsoid(0, 0, 0, 1, 1, 1, 1, 1)", 0.5, 0, 0), 0.75, 1e-15);
    EXPECT_DOUBLE_EQ(eval("blob(0, 0, 0, 2, 1)", 0, 0, 0), 2.0);
}

TEST(Evaluator, BlendsAndMorph) {
    double a = 0.2, b = -0.1;
    double base = a + b + std::sqrt(a * a + b * b);
    EXPECT_NEAR(eval("blend_union(0.2, -0.1, 0.5, 1, 2)"),
                base + 0.5 / (1 + std::pow(a / 1, 2) + std::pow(b / 2, 2)), 1e-15);
    EXPECT_EQ(eval("morph(x, y, 0)", 3, 7), 3.0);
    EXPECT_EQ(eval("morph(x, y, 1)", 3, 7), 7.0);
    EXPECT_EQ(eval("morph(x, y, t)", 3, 7, 0, 0.25), 4.0);
    EXPECT_EQ(eval("mix(0, 10, 0.3)"), 3.0);
}

TEST(Evaluator, MathLibrary) {
    EXPECT_EQ(eval("mod(-1, 3)"), 2.0);
    EXPECT_EQ(eval("mod(1, -3)"), -2.0);
    EXPECT_TRUE(std::isnan(eval("mod(1, 0)")));
    EXPECT_EQ(eval("clamp(5, 0, 1)"), 1.0);
    EXPECT_EQ(eval("step(0.5, 0.7)"), 1.0);
    EXPECT_EQ(eval("smoothstep(0, 1, 0.5)"), 0.5);
    EXPECT_EQ(eval("fract(-0.25)"), 0.75);
    EXPECT_EQ(eval("sign(-3) + sign(0)"), -1.0);
    EXPECT_EQ(eval("hypot(3, 4, 12)"), 13.0);
    EXPECT_EQ(eval("max(1, 5, 3, 2)"), 5.0);
    EXPECT_DOUBLE_EQ(eval("e"), std::exp(1.0));
}

TEST(Evaluator, TimeIsAnInput) {
    const char* bouncing = "1 - x^2 - (y - abs(sin(pi*t)))^2 - z^2";
    EXPECT_DOUBLE_EQ(eval(bouncing, 0, 1, 0, 0.5), 1.0);
    EXPECT_DOUBLE_EQ(eval(bouncing, 0, 1, 0, 0.0), 0.0);
}

} // namespace
} // namespace fl::formula
