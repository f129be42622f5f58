// Containment alone would be passed by [-inf, inf]. On small boxes, each
// operation's interval must be nearly as narrow as the values really spread
// (the spread sampled densely). (Issue 18; the mesher's use of the intervals
// is tested in tests/mesh/interval_pruning_test.cpp.)
#include "formula/compiler.h"
#include "formula/eval_interval.h"
#include "formula/eval_scalar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace fl::formula {
namespace {

struct Spread {
    double intervalWidth = 0;
    double sampledWidth = 0;
};

// The interval of `src` over x, y in [c - w, c + w] (z = 0.3, t = 0) and the
// spread of 40 x 40 sampled values there.
Spread spreadOf(const std::string& src, double cx, double cy, double w) {
    CompileResult r = compile(src);
    EXPECT_TRUE(r.ok()) << src;
    if (!r.ok()) return {};
    IntervalEvaluator interval(*r.tape);
    ScalarEvaluator scalar(*r.tape);
    Box box = boxXYZ(cx - w, cx + w, cy - w, cy + w, 0.3, 0.3);
    box[3] = Interval::point(0);
    const Interval range = interval.evaluate(box);
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            const double v = scalar.evaluate(
                pointXYZ(cx - w + 2 * w * i / 40.0, cy - w + 2 * w * j / 40.0, 0.3, 0));
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    return {range.hi - range.lo, hi - lo};
}

// Each operation on a box of half-width 1e-3 away from its singular points:
// the interval is at most `factor` times the sampled spread (plus rounding).
void expectTight(const std::string& src, double cx, double cy, double factor) {
    const Spread s = spreadOf(src, cx, cy, 1e-3);
    EXPECT_LE(s.intervalWidth, factor * s.sampledWidth + 1e-12)
        << src << ": interval width " << s.intervalWidth << ", values spread " << s.sampledWidth;
    EXPECT_GT(s.intervalWidth, 0) << src;
}

TEST(IntervalTightness, EachOperationOnASmallBox) {
    // One variable, monotone on the box: the interval is the exact image.
    for (const char* f :
         {"x + 1",     "x - 1",   "2*x",     "x/3",          "-x",      "exp(x)", "log(x)",
          "sqrt(x)",   "atan(x)", "tanh(x)", "sin(x)",       "cos(x)",  "tan(x)", "asin(x/2)",
          "acos(x/2)", "abs(x)",  "x^3",     "floor(x) + x", "sinh(x)", "cosh(x)"})
        expectTight(f, 0.6, 0.2, 1.05);
    // Two variables: sums, products, quotients, min/max, powers, hypot.
    for (const char* f : {"x + y", "x - y", "x*y", "x/y", "min(x, y)", "max(x, y)", "x^y",
                          "hypot(x, y)", "atan2(y, x)", "x & y", "x | y", "x \\ y"})
        expectTight(f, 0.6, 0.2, 1.05);
    // Dependent uses of one variable: interval arithmetic over-estimates
    // (x*x - x counts x twice), but by a bounded factor on a small box where
    // the terms do not nearly cancel (near x = 0.5 the true spread of
    // x*x - x vanishes while the terms' widths do not: that is the price of
    // intervals, not a defect).
    for (const char* f : {"x*x - x", "sin(x)*cos(x)", "x*x + y*y - 1"})
        expectTight(f, 2.0, 0.2, 3);
    // Where the slope is zero inside the box, the image is a sliver: the
    // interval must still end at the true extremum, not at the box's corners'
    // linear estimate.
    expectTight("sin(x)", 1.5707963267948966, 0.2, 1.05);
    expectTight("x*x", 0, 0.2, 1.05);
}

} // namespace
} // namespace fl::formula
