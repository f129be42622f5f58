// Law: the interval evaluator's result contains every point value of the box.
#include "formula/compiler.h"
#include "formula/eval_interval.h"
#include "formula/eval_scalar.h"
#include "random_formula.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace fl::formula {
namespace {

void checkContainment(const std::string& src, std::mt19937_64& rng, int boxes, int samples) {
    CompileResult r = compile(src);
    ASSERT_TRUE(r.ok()) << src;
    ScalarEvaluator scalar(*r.tape);
    IntervalEvaluator interval(*r.tape);
    std::uniform_real_distribution<double> centre(-4.0, 4.0);
    std::uniform_real_distribution<double> logWidth(-6.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int b = 0; b < boxes; ++b) {
        double lo[4], hi[4];
        for (int i = 0; i < 4; ++i) {
            double c = centre(rng), w = std::pow(10.0, logWidth(rng));
            lo[i] = c - w;
            hi[i] = c + w;
            if (i == 3 && b % 2 == 0) hi[i] = lo[i]; // fixed t half of the time
        }
        Box box = boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        box[3] = Interval::of(lo[3], hi[3]);
        Interval range = interval.evaluate(box);
        for (int s = 0; s < samples; ++s) {
            Point p{};
            for (int i = 0; i < 4; ++i) {
                double u = s == 0 ? 0.0 : (s == 1 ? 1.0 : unit(rng)); // corners too
                p[i] = std::min(hi[i], lo[i] + u * (hi[i] - lo[i]));  // stay inside the box
            }
            double v = scalar.evaluate(p);
            ASSERT_TRUE(range.contains(v))
                << "formula: " << src << "\nbox x[" << lo[0] << "," << hi[0] << "] y[" << lo[1]
                << "," << hi[1] << "] z[" << lo[2] << "," << hi[2] << "] t[" << lo[3] << ","
                << hi[3] << "]\npoint (" << p[0] << "," << p[1] << "," << p[2] << "," << p[3]
                << ") value " << v << " not in [" << range.lo << ", " << range.hi
                << "] nan=" << range.nan;
        }
    }
}

TEST(IntervalProperty, RandomFormulasContainEveryPointValue) {
    std::mt19937_64 rng(20261122);
    for (int f = 0; f < 400; ++f) {
        std::string src = testing::randomFormula(rng, 1 + f % 5);
        checkContainment(src, rng, 12, 24);
    }
}

TEST(IntervalProperty, PaperFormulasContainEveryPointValue) {
    std::mt19937_64 rng(7);
    const char* formulas[] = {
        "(1-x^2-y^2-z^2) & (-((z-x) & y & z))",
        "0.01*(sin(12*atan(x, z + 0.04*sin(25*y))) - 0.7)",
        "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
        "0.3 + 0.2*sin(120*pi*x)*sin(120*pi*y)*sin(120*pi*z)",
        "1 - x^2 - (y - abs(sin(pi*t)))^2 - z^2",
        "sphere(0.5) + 0.1*noise(4*x, 4*y, 4*z)",
        "blend_union(sphere(0.5), box(0.3, 0.8, 0.3), 0.2, 0.5, 0.5)",
        "torus(1, 0.3) | cylinder(0.2, 3) \\ cone(0.5, 1)",
        "superellipsoid(0, 0, 0, 1, 1, 1, 0.5, 0.5)",
    };
    for (const char* f : formulas)
        checkContainment(f, rng, 200, 32);
}

TEST(IntervalProperty, TightForSquaresOfSignChangingIntervals) {
    CompileResult r = compile("x^2");
    ASSERT_TRUE(r.ok());
    IntervalEvaluator e(*r.tape);
    Interval v = e.evaluate(boxXYZ(-1, 1, 0, 0, 0, 0));
    EXPECT_LE(v.lo, 0.0);
    EXPECT_GE(v.lo, -1e-300); // no dependency problem: not [-1, 1]
    EXPECT_NEAR(v.hi, 1.0, 1e-12);
}

TEST(IntervalProperty, ProvesEmptySpaceForASphere) {
    CompileResult r = compile("1 - x^2 - y^2 - z^2");
    ASSERT_TRUE(r.ok());
    IntervalEvaluator e(*r.tape);
    Interval far = e.evaluate(boxXYZ(2, 3, 2, 3, 2, 3));
    EXPECT_LT(far.hi, 0.0);
    Interval inside = e.evaluate(boxXYZ(-0.1, 0.1, -0.1, 0.1, -0.1, 0.1));
    EXPECT_GT(inside.lo, 0.0);
}

} // namespace
} // namespace fl::formula
