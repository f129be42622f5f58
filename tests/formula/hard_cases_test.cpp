// Numerically hard cases, each named: what the engine does is written down in
// docs/numerics.md and pinned here.
#include "formula/batch_jit.h"
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_interval.h"
#include "formula/noise.h"
#include "formula/nonfinite_report.h"
#include "formula/rfunctions.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace fl::formula {
namespace {

using testing::eval;
constexpr double kPi = std::numbers::pi;

TEST(HardCases, IntegerPowersOfNegatives) {
    EXPECT_EQ(eval("(-2)^3"), -8.0);
    EXPECT_EQ(eval("x^3", -2), -8.0);
    EXPECT_EQ(eval("x^4", -2), 16.0);
    EXPECT_EQ(eval("x^-3", -2), -0.125);
    EXPECT_EQ(eval("pow(x, 5)", -1.5), std::pow(-1.5, 5));
    EXPECT_EQ(eval("-x^2", 3), -9.0); // unary minus binds looser than ^
    EXPECT_EQ(eval("2^3^2"), 512.0);  // right-associative
    EXPECT_TRUE(std::isnan(eval("x^2.5", -1)));
    EXPECT_EQ(eval("cbrt(x)", -8), -2.0);
    EXPECT_EQ(eval("x^0", NAN), 1.0); // IEEE pow(x, 0) = 1
}

TEST(HardCases, HugeAndTinyMagnitudes) {
    EXPECT_EQ(eval("x*x", 1e300), INFINITY);
    EXPECT_EQ(eval("x*x", 1e-300), 0.0);
    EXPECT_NEAR(eval("hypot(x, y)", 1e300, 1e300), std::sqrt(2.0) * 1e300, 1e286);
    EXPECT_NEAR(eval("hypot(x, y)", 1e-300, 1e-300), std::sqrt(2.0) * 1e-300, 1e-314);
    EXPECT_EQ(eval("exp(x)", 1000), INFINITY);
    EXPECT_EQ(eval("exp(x)", -1000), 0.0);
    EXPECT_NEAR(eval("sphere(1e6) / 1e12", 0, 0, 0), 1.0, 1e-15);
    EXPECT_NEAR(eval("sphere(1e-6) * 1e12", 0, 0, 0), 1.0, 1e-15);
    // the lexer refuses what does not fit a double instead of making it infinite
    EXPECT_FALSE(compile("1e999").ok());
}

TEST(HardCases, PolesAndDivisionByZero) {
    EXPECT_EQ(eval("1/x", 0.0), INFINITY);
    EXPECT_EQ(eval("1/x", -0.0), -INFINITY);
    EXPECT_TRUE(std::isnan(eval("x/x", 0.0)));
    EXPECT_TRUE(std::isfinite(eval("tan(x)", kPi / 2))); // pi/2 is not exact in binary
    EXPECT_EQ(eval("x^-1", 0.0), INFINITY);
    IntervalEvaluator iv(*compile("1/x").tape);
    Interval r = iv.evaluate(boxXYZ(-1, 1, 0, 0, 0, 0));
    EXPECT_EQ(r.lo, -INFINITY);
    EXPECT_EQ(r.hi, INFINITY);
}

TEST(HardCases, LogOfZeroAndSqrtOfNegatives) {
    EXPECT_EQ(eval("log(x)", 0.0), -INFINITY);
    EXPECT_TRUE(std::isnan(eval("log(x)", -1.0)));
    EXPECT_TRUE(std::isnan(eval("sqrt(x)", -1.0)));
    EXPECT_EQ(eval("sqrt(x)", -0.0), -0.0);
    // constant arguments are folded and reported at compile time, once, located
    CompileResult r = compile("1 + log(-1)");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.diagnostics[0].range.begin.column, 5);
    // variable arguments: located by the reporter when a point goes non-finite
    CompileResult s = compile("x + sqrt(y)");
    ASSERT_TRUE(s.ok());
    auto d = explainNonFinite(*s.tape, {}, pointXYZ(1, -4, 0));
    ASSERT_TRUE(d.has_value());
    EXPECT_EQ(d->range.begin.column, 5);
    EXPECT_NE(d->message.find("NaN"), std::string::npos);
    EXPECT_FALSE(explainNonFinite(*s.tape, {}, pointXYZ(1, 4, 0)).has_value());
}

TEST(HardCases, Atan2Quadrants) {
    EXPECT_DOUBLE_EQ(eval("atan2(y, x)", 1, 1), kPi / 4);
    EXPECT_DOUBLE_EQ(eval("atan2(y, x)", -1, 1), 3 * kPi / 4);
    EXPECT_DOUBLE_EQ(eval("atan2(y, x)", -1, -1), -3 * kPi / 4);
    EXPECT_DOUBLE_EQ(eval("atan2(y, x)", 1, -1), -kPi / 4);
    EXPECT_DOUBLE_EQ(eval("atan2(y, x)", -1, 0.0), kPi);
    EXPECT_DOUBLE_EQ(eval("atan2(y, x)", -1, -0.0), -kPi);
    EXPECT_DOUBLE_EQ(eval("atan(y, x)", -1, 1), 3 * kPi / 4); // two-argument atan is atan2
    EXPECT_EQ(eval("atan2(y, x)", 0, 0), 0.0);
    // the interval of a box straddling the branch cut covers both sides
    IntervalEvaluator iv(*compile("atan2(y, x)").tape);
    Interval r = iv.evaluate(boxXYZ(-2, -1, -0.5, 0.5, 0, 0));
    EXPECT_LE(r.lo, -kPi + 0.5);
    EXPECT_GE(r.hi, kPi - 0.5);
}

TEST(HardCases, ZeroAndUndefinedGradients) {
    // Interpreted, and as machine code where the CPU has it (gradient_jit.h).
    for (const ScalarCode code : {ScalarCode::Interpreted, ScalarCode::Compiled}) {
        SCOPED_TRACE(code == ScalarCode::Compiled ? "machine code" : "interpreted");
        auto grad = [code](const char* src, double x, double y, double z) {
            GradientEvaluator g(*compile(src).tape, {Input::X, Input::Y, Input::Z}, code);
            const Dual d = g.evaluate(pointXYZ(x, y, z));
            if (code == ScalarCode::Compiled && BatchJit::available()) {
                EXPECT_TRUE(g.compiledLast()) << src;
            }
            return d;
        };
        Dual d = grad("sqrt(x^2 + y^2 + z^2)", 0, 0, 0);
        for (double c : d.d)
            EXPECT_EQ(c, 0.0); // not NaN from 0 * inf
        d = grad("abs(x)", 0, 0, 0);
        EXPECT_EQ(d.d[0], 0.0);
        d = grad("7", 1, 2, 3);
        EXPECT_EQ(d.d[0], 0.0);
        d = grad("rintersect(x, y)", 0, 0, 0);
        EXPECT_EQ(d.d[0], 0.5);
        EXPECT_EQ(d.d[1], 0.5);
        d = grad("rintersect(x, y, 1)", 0, 0, 0);
        EXPECT_EQ(d.d[0], 0.0);
        d = grad("min(x, y)", 1, 1, 0); // tie: the average, symmetric like the value
        EXPECT_EQ(d.d[0], 0.5);
        EXPECT_EQ(d.d[1], 0.5);
        d = grad("min(x, y)", 1, 2, 0);
        EXPECT_EQ(d.d[0], 1.0);
        EXPECT_EQ(d.d[1], 0.0);
        d = grad("sqrt(x)^0", -1, 0, 0); // NaN^0 = 1: a constant, so no NaN gradient
        EXPECT_EQ(d.v, 1.0);
        EXPECT_EQ(d.d[0], 0.0);
        d = grad("floor(x) + (x > 0)", 0.5, 0, 0);
        EXPECT_EQ(d.d[0], 0.0);
        d = grad("sqrt(x)", 0, 0, 0); // vertical tangent
        EXPECT_EQ(d.d[0], INFINITY);
    }
}

TEST(HardCases, NaNAndInfinityInputsNeverCrashAndStayLocal) {
    CompileResult r = compile("min(sqrt(x), 1) + y");
    ASSERT_TRUE(r.ok());
    BatchEvaluator b(*r.tape);
    double xs[4] = {-1, 4, NAN, INFINITY};
    double ys[4] = {1, 1, 1, -INFINITY};
    double out[4];
    BatchInputs in;
    in.set(Input::X, xs);
    in.set(Input::Y, ys);
    in.set(Input::Z, 0.0);
    b.evaluate(in, 4, out);
    EXPECT_TRUE(std::isnan(out[0]));
    EXPECT_EQ(out[1], 2.0); // a NaN neighbour does not spread
    EXPECT_TRUE(std::isnan(out[2]));
    EXPECT_EQ(out[3], -INFINITY);
}

TEST(HardCases, NoiseIsDeterministicBoundedAndFiniteEverywhere) {
    EXPECT_EQ(eval("noise(x, y, z)", 0.3, 0.7, 1.1), eval("noise(x, y, z)", 0.3, 0.7, 1.1));
    EXPECT_EQ(eval("noise(x, y, z)", 1, 2, 3), 0.0); // zero on the integer lattice
    EXPECT_TRUE(std::isfinite(eval("noise(x, y, z)", 1e300, -1e300, INFINITY)));
    double maxAbs = 0;
    for (int i = 0; i < 20000; ++i) {
        double v = eval("noise(x, y, z)", i * 0.0137, i * 0.031, i * 0.0071);
        maxAbs = std::max(maxAbs, std::abs(v));
    }
    EXPECT_LE(maxAbs, kNoiseBound);
    EXPECT_GT(maxAbs, 0.3); // it really varies
}

TEST(HardCases, ComparisonsWithNaNAreFalse) {
    EXPECT_EQ(eval("x < 1", NAN), 0.0);
    EXPECT_EQ(eval("x != x", NAN), 1.0);
    EXPECT_EQ(eval("x ? 1 : 2", NAN), 2.0);
    EXPECT_EQ(eval("!x", NAN), 1.0);
    EXPECT_TRUE(std::isnan(eval("min(x, 1)", NAN)));
    EXPECT_TRUE(std::isnan(eval("max(1, x)", NAN)));
}

} // namespace
} // namespace fl::formula

namespace fl::formula {
namespace {

// Found by the fuzzer: inf - inf, 0 * inf and inf / inf inside a box are NaN
// even when no endpoint computation is; the interval must say "may be NaN".
TEST(HardCases, IntervalsFlagNaNFromInfiniteArithmetic) {
    auto range = [](const char* src, double lo, double hi) {
        IntervalEvaluator e(*compile(src).tape);
        return e.evaluate(boxXYZ(lo, hi, lo, hi, lo, hi));
    };
    EXPECT_TRUE(range("0^-z^21 - 0^-z^2", -1, 1).nan);
    EXPECT_TRUE(range("x * (1 / y)", -1, 1).nan);    // 0 * inf
    EXPECT_TRUE(range("(1/x) / (1/y)", -1, 1).nan);  // inf / inf
    EXPECT_TRUE(range("1/x^2 + -1/y^2", -1, 1).nan); // inf + -inf
    EXPECT_FALSE(range("x * y - z", -1, 1).nan);     // finite boxes stay clean
    ScalarEvaluator s(*compile("0^-z^21 - 0^-z^2").tape);
    EXPECT_TRUE(std::isnan(s.evaluate(pointXYZ(0, 0, 0.5))));
}

} // namespace
} // namespace fl::formula

namespace fl::formula {
namespace {

// Found in review: each pins an exactness or containment promise.
TEST(HardCases, ReviewFindings) {
    // x^n beyond the PowI range is pow: its interval must contain pow's value
    {
        IntervalEvaluator iv(*compile("x^100").tape);
        ScalarEvaluator sc(*compile("x^100").tape);
        const double x = 1.0134319161723075;
        EXPECT_TRUE(iv.evaluate(boxXYZ(x, x, 0, 0, 0, 0)).contains(sc.evaluate(pointXYZ(x, 0, 0))));
    }
    // pow(-0, -1) = -inf lies in the interval of a box whose base starts at 0
    {
        IntervalEvaluator iv(*compile("x^y").tape);
        Box box = boxXYZ(-0.0, 1.0, -1.5, -0.5, 0, 0);
        EXPECT_TRUE(iv.evaluate(box).contains(-INFINITY));
    }
    // NaN^0 = 1 even when the whole box is undefined for the base
    {
        IntervalEvaluator iv(*compile("sqrt(x)^0").tape);
        EXPECT_TRUE(iv.evaluate(boxXYZ(-2, -1, 0, 0, 0, 0)).contains(1.0));
    }
    // R-functions near the largest double keep min/max's sign and are accurate
    EXPECT_GT(rIntersect0(1.3e308, 1.3e308), 0.0);
    EXPECT_LT(rUnion0(-1.3e308, -1.3e308), 0.0);
    EXPECT_NEAR(rIntersect0(1e308, 1e308) / 1e308, 2.0 - std::sqrt(2.0), 1e-15);
    {
        IntervalEvaluator iv(*compile("rintersect(x, y)").tape);
        Interval r = iv.evaluate(boxXYZ(1e308, 1.3e308, 1e308, 1.3e308, 0, 0));
        EXPECT_FALSE(r.empty());
        EXPECT_TRUE(r.contains(rIntersect0(1.2e308, 1.1e308)));
    }
    // x^0.5 is pow, not sqrt: they differ at -inf and -0
    EXPECT_EQ(eval("x^0.5", -INFINITY), INFINITY);
    EXPECT_EQ(eval("1/x^0.5", -0.0), INFINITY);
    // min and max are symmetric for signed zeros, whatever order the compiler picks
    EXPECT_EQ(eval("a = x; return 1/min(y, x);", -0.0, 0.0), -INFINITY);
    EXPECT_EQ(eval("1/min(y, x)", -0.0, 0.0), -INFINITY);
    EXPECT_EQ(eval("1/max(x, y)", -0.0, 0.0), INFINITY);
}

TEST(HardCases, NonFiniteReportFollowsTheValueThatReachedTheOutput) {
    CompileResult r = compile("(x > 0 ? sqrt(x) : 0) + log(x)");
    ASSERT_TRUE(r.ok());
    auto d = explainNonFinite(*r.tape, {}, pointXYZ(-1, 0, 0));
    ASSERT_TRUE(d.has_value());
    EXPECT_NE(d->message.find("'log'"), std::string::npos) << d->message; // not the sqrt not taken
    EXPECT_NE(d->message.find("x = -1"), std::string::npos);
    EXPECT_EQ(d->message.find("y ="), std::string::npos); // only the inputs the formula reads
}

TEST(HardCases, NonFiniteReportNamesConstantsAndMatchesTheKindOfValue) {
    CompileResult c = compile("x + 1/0");
    auto d = explainNonFinite(*c.tape, {}, pointXYZ(1, 0, 0));
    ASSERT_TRUE(d.has_value());
    EXPECT_NE(d->message.find("constant or parameter"), std::string::npos) << d->message;
    CompileResult m = compile("min(exp(x*1000), sqrt(-x))");
    d = explainNonFinite(*m.tape, {}, pointXYZ(1, 0, 0));
    ASSERT_TRUE(d.has_value());
    EXPECT_NE(d->message.find("NaN) from 'sqrt'"), std::string::npos) << d->message;
}

TEST(HardCases, RFunctionsKeepTinyOperandsNextToHugeOnes) {
    EXPECT_LT(rIntersect0(1e308, -1e-315), 0.0);
    EXPECT_EQ(rIntersect0(1e308, -1e-300), -1e-300);
    EXPECT_GT(rUnion0(-1e308, 1e-315), 0.0);
}

TEST(HardCases, PowerIntervalsStayTightForPositiveExponents) {
    IntervalEvaluator iv(*compile("(x^2 + y^2)^0.5").tape);
    Interval r = iv.evaluate(boxXYZ(-1, 1, -1, 1, 0, 0));
    EXPECT_GE(r.lo, -1e-300);
    EXPECT_FALSE(r.nan);
}

TEST(HardCases, AlwaysUndefinedOperationsAreReportedOnceAndOnlyWhenLive) {
    CompileResult loop = compile("s = 0; for (i = 0; i < 5; i++) { s += log(-1) * x; } return s;");
    ASSERT_TRUE(loop.ok());
    EXPECT_EQ(loop.diagnostics.size(), 1u);
    CompileResult dead = compile("0 ? log(-1) : 2");
    ASSERT_TRUE(dead.ok());
    EXPECT_TRUE(dead.diagnostics.empty());
    EXPECT_EQ(eval("0 ? log(-1) : 2"), 2.0);
}

} // namespace
} // namespace fl::formula
