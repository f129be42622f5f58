// R-functions: the definitions fixed by the foundation issue, in stable forms.
#include "formula/rfunctions.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace fl::formula {
namespace {

// Reference in long double, textbook form, for inputs where it is accurate.
long double refIntersect(long double a, long double b) {
    return a + b - std::sqrt(a * a + b * b);
}

TEST(RFunction, MatchesTheDefinitionOnOrdinaryValues) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> v(-10, 10);
    for (int i = 0; i < 10000; ++i) {
        double a = v(rng), b = v(rng);
        EXPECT_NEAR(rIntersect0(a, b), static_cast<double>(refIntersect(a, b)),
                    1e-13 * (1 + std::abs(a) + std::abs(b)));
        EXPECT_NEAR(rUnion0(a, b), static_cast<double>(-refIntersect(-a, -b)),
                    1e-13 * (1 + std::abs(a) + std::abs(b)));
    }
}

TEST(RFunction, CmIsR0TimesTheNormToTheM) {
    double a = 0.7, b = -0.4;
    for (double m : {1.0, 2.0, 3.0}) {
        double expected = rIntersect0(a, b) * std::pow(a * a + b * b, m / 2);
        EXPECT_NEAR(rIntersect(a, b, m, 0.0), expected, 1e-15);
        expected = rUnion0(a, b) * std::pow(a * a + b * b, m / 2);
        EXPECT_NEAR(rUnion(a, b, m, 0.0), expected, 1e-15);
    }
    EXPECT_NEAR(testing::eval("rintersect(0.7, -0.4, 2)"), rIntersect0(0.7, -0.4) * 0.65, 1e-15);
}

TEST(RFunction, BothArgumentsZero) {
    EXPECT_EQ(rIntersect0(0.0, 0.0), 0.0);
    EXPECT_EQ(rUnion0(0.0, 0.0), 0.0);
    EXPECT_EQ(rIntersect(0.0, 0.0, 1.0, 0.0), 0.0);
    EXPECT_EQ(rUnion(0.0, 0.0, 2.0, 0.0), 0.0);
    EXPECT_FALSE(std::isnan(rIntersect(0.0, 0.0, 0.5, 0.0)));
}

TEST(RFunction, OneArgumentDwarfsTheOther) {
    // 1e8 inside and 1e-8 inside: inside (> 0), about 1e-8 - 1e-24 / 2
    double r = rIntersect0(1e8, 1e-8);
    EXPECT_GT(r, 0.0);
    EXPECT_NEAR(r, 1e-8, 1e-20);
    // one barely outside: the sign must say outside, and the value ~ -1e-8
    r = rIntersect0(1e8, -1e-8);
    EXPECT_LT(r, 0.0);
    EXPECT_NEAR(r, -1e-8, 1e-20);
    r = rIntersect0(-1e-8, 1e8);
    EXPECT_LT(r, 0.0);
    // unions, mirrored
    EXPECT_LT(rUnion0(-1e8, -1e-8), 0.0);
    EXPECT_NEAR(rUnion0(-1e8, -1e-8), -1e-8, 1e-20);
    EXPECT_GT(rUnion0(-1e8, 1e-8), 0.0);
    EXPECT_NEAR(rUnion0(-1e8, 1e-8), 1e-8, 1e-20);
    // the textbook form really does fail here (why the stable form exists):
    // 49% error for (1e8, 1e-8), and a point outside one shape lands on the surface
    volatile double a = 1e8, b = 1e-8;
    EXPECT_GT(std::abs((a + b - std::sqrt(a * a + b * b)) - 1e-8), 0.4e-8);
    volatile double c = -5e-9;
    EXPECT_GE(a + c - std::sqrt(a * a + c * c), 0.0);
    EXPECT_LT(rIntersect0(1e8, -5e-9), 0.0);
}

TEST(RFunction, HugeArgumentsDoNotOverflow) {
    double r = rIntersect0(1e200, 1e200);
    EXPECT_TRUE(std::isfinite(r));
    EXPECT_NEAR(r / 1e200, 2.0 - std::sqrt(2.0), 1e-14);
    r = rUnion0(1e200, 1e200);
    EXPECT_TRUE(std::isfinite(r));
    EXPECT_NEAR(r / 1e200, 2.0 + std::sqrt(2.0), 1e-14);
    EXPECT_NEAR(rIntersect0(-1e200, -1e200) / 1e200, -2.0 - std::sqrt(2.0), 1e-14);
    // C^1 of 1e200: the true value 1e400 is out of range; infinity of the right sign, never NaN
    EXPECT_EQ(rIntersect(1e200, 1e200, 1.0, 0.0), INFINITY);
    EXPECT_EQ(rIntersect(-1e200, -1e200, 1.0, 0.0), -INFINITY);
}

TEST(RFunction, SignAgreesWithMinMaxEverywhere) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> e(-300, 300);
    std::bernoulli_distribution neg(0.5);
    for (int i = 0; i < 100000; ++i) {
        double a = std::pow(10.0, e(rng)) * (neg(rng) ? -1 : 1);
        double b = std::pow(10.0, e(rng)) * (neg(rng) ? -1 : 1);
        double ri = rIntersect0(a, b), ru = rUnion0(a, b);
        ASSERT_EQ(std::signbit(ri) && ri != 0, std::min(a, b) < 0) << a << " " << b << " -> " << ri;
        ASSERT_EQ(ru > 0, std::max(a, b) > 0) << a << " " << b << " -> " << ru;
        ASSERT_FALSE(std::isnan(rIntersect(a, b, 1.0, 0.0)));
    }
}

TEST(RFunction, AlphaOneIsMinMaxAndAlphaZeroIsR0) {
    EXPECT_EQ(rIntersectAlpha(0.3, -0.2, 1.0), -0.2);
    EXPECT_EQ(rUnionAlpha(0.3, -0.2, 1.0), 0.3);
    EXPECT_EQ(rIntersectAlpha(0.3, -0.2, 0.0), rIntersect0(0.3, -0.2));
    double a = 0.3, b = 0.5, alpha = 0.5;
    double expected = (a + b - std::sqrt(a * a + b * b - 2 * alpha * a * b)) / (1 + alpha);
    EXPECT_NEAR(rIntersectAlpha(a, b, alpha), expected, 1e-15);
}

TEST(RFunction, SetOperatorsFollowTheShapesMode) {
    CompileOptions o;
    o.setOperations.kind = SetOperationMode::Kind::RFunction;
    o.setOperations.m = 1.0;
    CompileResult r = compile("x & y", o);
    ASSERT_TRUE(r.ok());
    ScalarEvaluator e(*r.tape);
    EXPECT_NEAR(e.evaluate(pointXYZ(0.7, -0.4, 0)), rIntersect(0.7, -0.4, 1.0, 0.0), 1e-16);
    CompileResult mm = compile("x & y");
    ScalarEvaluator e2(*mm.tape);
    EXPECT_EQ(e2.evaluate(pointXYZ(0.7, -0.4, 0)), -0.4);
    EXPECT_EQ(testing::eval("x \\ y", 0.7, 0.4), 0.7 < -0.4 ? 0.7 : -0.4);
    EXPECT_EQ(testing::eval("x | y", 0.7, 0.4), 0.7);
    EXPECT_EQ(testing::eval("~x", 0.7), -0.7);
}

} // namespace
} // namespace fl::formula
