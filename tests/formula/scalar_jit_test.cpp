// The scalar evaluator as machine code (issue 31 §1: BatchEvaluator's one-point
// code) against its interpreter: every operation the JIT writes or calls, on
// the values where semantics bite (±0, ±inf, NaN, subnormals, huge and tiny),
// random formulas deep enough to spill, every output of a script, and the
// parameters changing under it must give the interpreter's bits exactly. An
// evaluator asked for a few points stays interpreted (it never pays for
// compiling); FUNCTIONLAB_NO_JIT's switch leaves every one interpreted.
// Skipped where the CPU has no AVX2.
#include "formula/batch_jit.h"
#include "formula/compiler.h"
#include "formula/eval_batch.h"
#include "formula/eval_scalar.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace fl::formula {
namespace {

using testing::sameBits;

const std::vector<double>& specials() {
    return testing::specialValues();
}

class ScalarJitTest : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!BatchJit::available()) GTEST_SKIP() << "no AVX2 here (or FUNCTIONLAB_NO_JIT)";
    }
};

// Both ways at every pair of special values (z a mix, t and u v w set):
// true when the compiled one ran as machine code.
bool agreeOnSpecials(const std::string& src) {
    CompileResult r = compile(src);
    EXPECT_TRUE(r.ok()) << src;
    if (!r.ok()) return false;
    ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
    ScalarEvaluator interpreted(*r.tape, ScalarCode::Interpreted);
    bool ran = true;
    for (double a : specials())
        for (double b : specials()) {
            const Point p{a, b, a * 0.5 - b, 0.25, 0.1, -0.2, 0.3};
            const double x = compiled.evaluate(p), y = interpreted.evaluate(p);
            ran = ran && compiled.compiledLast();
            EXPECT_FALSE(interpreted.compiledLast());
            if (!sameBits(x, y)) {
                ADD_FAILURE() << src << " at x=" << a << " y=" << b << ": compiled " << x
                              << ", interpreted " << y;
                return ran;
            }
        }
    return ran;
}

// Past the warm-up: the next point runs as code.
void warmUp(ScalarEvaluator& e) {
    for (unsigned i = 0; i <= kScalarWarmUp; ++i)
        e.evaluate(pointXYZ(1, 0, 0));
}

TEST_F(ScalarJitTest, EveryOperationGivesTheInterpretersBits) {
    std::vector<std::string> sources = testing::jitOperationFormulas();
    sources.insert(sources.end(), {"sin(x) * cos(y) + sin(y) * cos(x)",
                                   "sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)",
                                   "x + t * u - v / w"});
    int ran = 0;
    for (const std::string& src : sources)
        ran += agreeOnSpecials(src) ? 1 : 0;
    EXPECT_EQ(ran, int(sources.size())); // every one ran as machine code
}

TEST_F(ScalarJitTest, RandomFormulasThatSpillGiveTheInterpretersBits) {
    // Sums of products of many values live at once: more than the sixteen
    // vector registers hold, so values go to their rows and come back.
    std::mt19937_64 rng(311);
    std::uniform_real_distribution<double> v(-3, 3);
    static const char* leaves[] = {"x", "y", "z", "t", "0.5", "-1.25", "3"};
    static const char* ops[] = {" + ", " - ", " * ", " / "};
    for (int i = 0; i < 200; ++i) {
        std::string src;
        const int terms = 2 + i % 24;
        for (int k = 0; k < terms; ++k) {
            std::string term =
                "(" + std::string(leaves[rng() % 7]) + ops[rng() % 4] + leaves[rng() % 7] + ")";
            if (k % 5 == 4) term = "sin(" + term + ")";
            if (k % 7 == 6) term = "min(" + term + ", " + leaves[rng() % 7] + ")";
            src += (k ? ops[rng() % 3] : "") + term;
        }
        CompileResult r = compile(src);
        ASSERT_TRUE(r.ok()) << src;
        ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
        ScalarEvaluator interpreted(*r.tape, ScalarCode::Interpreted);
        for (int k = 0; k < 20; ++k) {
            const Point p{v(rng), v(rng), k % 5 ? v(rng) : -0.0, 0.7, 0, 0, 0};
            const double a = compiled.evaluate(p), b = interpreted.evaluate(p);
            ASSERT_TRUE(sameBits(a, b))
                << src << ": compiled " << a << ", interpreted " << b << " at " << k;
        }
    }
}

TEST_F(ScalarJitTest, SixteenValuesLiveAtOnceSpillAndComeBack) {
    // Sixteen values made before any is used: more than the eleven vector
    // registers that hold values, so some go to their rows and come back.
    const std::string src = testing::sixteenLiveValues();
    CompileResult r = compile(src);
    ASSERT_TRUE(r.ok()) << src;
    ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
    ScalarEvaluator interpreted(*r.tape, ScalarCode::Interpreted);
    for (double a : specials())
        for (double b : {0.5, -3.0, 1e-310}) {
            const Point p{a, b, 1.5 - a, 0, 0, 0, 0};
            const double x = compiled.evaluate(p), y = interpreted.evaluate(p);
            ASSERT_TRUE(compiled.compiledLast());
            ASSERT_TRUE(sameBits(x, y)) << "x=" << a << " y=" << b << ": " << x << " vs " << y;
        }
}

TEST_F(ScalarJitTest, EveryOutputOfAScriptAndNewParametersGiveTheInterpretersBits) {
    CompileOptions options;
    options.kind = DefinitionKind::Colour;
    CompileResult r =
        compile("param k = 2; r = sin(k * x) * y; g = max(r, z * k); b = 0.5;", options);
    ASSERT_TRUE(r.ok());
    ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
    ScalarEvaluator interpreted(*r.tape, ScalarCode::Interpreted);
    const std::size_t n = r.tape->outputs.size();
    ASSERT_EQ(n, 3u);
    for (double k : {2.0, -1.5, 2.0, 0.0}) {
        ASSERT_TRUE(compiled.parameters().set("k", k));
        ASSERT_TRUE(interpreted.parameters().set("k", k));
        for (double x : {-1.0, 0.25, 3.5}) {
            const Point p = pointXYZ(x, 0.5 * x, 1 - x, 0.1);
            std::vector<double> a(n), b(n);
            compiled.evaluateAll(p, a.data());
            interpreted.evaluateAll(p, b.data());
            EXPECT_TRUE(compiled.compiledLast());
            for (std::size_t o = 0; o < n; ++o)
                EXPECT_TRUE(sameBits(a[o], b[o])) << "k = " << k << " x = " << x << " output " << o
                                                  << ": " << a[o] << " vs " << b[o];
        }
    }
}

TEST_F(ScalarJitTest, OutputsThatAreInputsConstantsOrOneRegisterTwiceComeBack) {
    // The code returns the first output when it computes it and leaves the
    // rest in their rows: an input, a constant, a value named twice and a
    // value only a call computes must all come back as the interpreter's.
    CompileOptions options;
    options.kind = DefinitionKind::Colour;
    const char* scripts[] = {"r = x; g = sin(y) * z; b = g;", "r = 0.25; g = y * z; b = t;",
                             "r = sin(x); g = r; b = atan2(y, z);",
                             "r = x * y; g = cos(x * y); b = r;"};
    for (const char* src : scripts) {
        CompileResult r = compile(src, options);
        ASSERT_TRUE(r.ok()) << src;
        ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
        ScalarEvaluator interpreted(*r.tape, ScalarCode::Interpreted);
        const std::size_t n = r.tape->outputs.size();
        for (double a : specials()) {
            const Point p{a, 0.5 - a, a * 3, -0.75, 0, 0, 0};
            std::vector<double> all(n), expected(n);
            compiled.evaluateAll(p, all.data());
            interpreted.evaluateAll(p, expected.data());
            const double first = compiled.evaluate(p);
            for (std::size_t o = 0; o < n; ++o)
                ASSERT_TRUE(sameBits(all[o], expected[o]))
                    << src << " output " << o << " at " << a << ": " << all[o] << " vs "
                    << expected[o];
            ASSERT_TRUE(sameBits(first, expected[0])) << src << " at " << a;
        }
    }
}

TEST_F(ScalarJitTest, ParametersSetToTheirOwnValuesKeepTheCode) {
    // A set() of the same value changes the parameters' version but not
    // their bits: the code stays, with no new warm-up.
    CompileResult r = compile("param k = 1; k * x - y");
    ASSERT_TRUE(r.ok());
    ScalarEvaluator e(*r.tape);
    warmUp(e);
    ASSERT_TRUE(e.compiledLast());
    ASSERT_TRUE(e.parameters().set("k", 1.0));
    EXPECT_EQ(e.evaluate(pointXYZ(2, 0.5, 0)), 1.5);
    EXPECT_TRUE(e.compiledLast());
    ASSERT_TRUE(e.parameters().set("k", 3.0)); // a new value: interpreted while it warms up
    EXPECT_EQ(e.evaluate(pointXYZ(2, 0.5, 0)), 5.5);
    EXPECT_FALSE(e.compiledLast());
}

TEST_F(ScalarJitTest, WorkOnTimeAloneRunsOncePerMomentWithTheInterpretersBits) {
    // What depends on t alone runs only when t's bits change (batch_hoist.h):
    // moments repeated, changed, signed zeros, NaN and infinity between
    // points must still give the interpreter's bits, for every output.
    CompileOptions colour;
    colour.kind = DefinitionKind::Colour;
    const auto& moments = testing::momentsToVisit();
    for (const testing::TimeCase& c : testing::timeOnlyCases()) {
        CompileResult r = c.colour ? compile(c.src, colour) : compile(c.src);
        ASSERT_TRUE(r.ok()) << c.src;
        ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
        ScalarEvaluator interpreted(*r.tape, ScalarCode::Interpreted);
        const std::size_t n = r.tape->outputs.size();
        int k = 0;
        for (double t : moments)
            for (double x : {-0.5, 0.75, 2.0}) {
                const Point p{x, 0.5 - x, x * x, t, 0, 0, 0};
                std::vector<double> all(n), expected(n);
                // Either call may be the first at a new t (the one that runs
                // the hoisted steps): they take turns.
                double first = 0;
                if (++k % 2) {
                    compiled.evaluateAll(p, all.data());
                    first = compiled.evaluate(p);
                } else {
                    first = compiled.evaluate(p);
                    compiled.evaluateAll(p, all.data());
                }
                ASSERT_TRUE(compiled.compiledLast());
                interpreted.evaluateAll(p, expected.data());
                ASSERT_TRUE(sameBits(first, expected[0])) << c.src << " at t=" << t << " x=" << x
                                                          << ": " << first << " vs " << expected[0];
                for (std::size_t o = 0; o < n; ++o)
                    ASSERT_TRUE(sameBits(all[o], expected[o]))
                        << c.src << " output " << o << " at t=" << t << " x=" << x;
            }
    }
}

TEST_F(ScalarJitTest, TheBouncingSpheresSineRunsOncePerMoment) {
    // The test above passes with nothing hoisted too: this one says the
    // work on t alone really is put in front.
    CompileResult r = compile("0.25 - x^2 - (y - (abs(sin(pi*t)) - 0.5))^2 - z^2");
    ASSERT_TRUE(r.ok());
    BatchEvaluator e(*r.tape, false);
    ASSERT_TRUE(e.prepareOne());
    EXPECT_GE(e.onePointHoisted(), 2u); // sin(pi * t), abs of it, minus 0.5: in front
    CompileResult still = compile("1 - x^2 - y^2 - z^2 + x * t");
    ASSERT_TRUE(still.ok());
    BatchEvaluator none(*still.tape, false);
    ASSERT_TRUE(none.prepareOne());
    EXPECT_EQ(none.onePointHoisted(), 0u);
}

TEST_F(ScalarJitTest, AParameterFromPlusToMinusZeroIsANewValue) {
    // The batch evaluator compared parameters with ==, for which -0 is +0:
    // k * x kept +0's sign after k became -0.
    CompileResult r = compile("param k = 0; k * x");
    ASSERT_TRUE(r.ok());
    ScalarEvaluator compiled(*r.tape, ScalarCode::Compiled);
    BatchEvaluator batch(*r.tape);
    const double xs[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    double out[8];
    BatchInputs in;
    in.set(Input::X, xs);
    for (double k : {0.0, -0.0, 0.0}) {
        ASSERT_TRUE(compiled.parameters().set("k", k));
        ASSERT_TRUE(batch.parameters().set("k", k));
        for (unsigned i = 0; i <= kScalarWarmUp; ++i) // compiled for this k
            compiled.evaluate(pointXYZ(1, 0, 0));
        EXPECT_TRUE(sameBits(compiled.evaluate(pointXYZ(1, 0, 0)), k)) << k;
        batch.evaluate(in, 8, out);
        for (double v : out)
            EXPECT_TRUE(sameBits(v, k)) << k;
    }
}

TEST_F(ScalarJitTest, AFewPointsStayInterpretedAndTheSwitchTurnsItOff) {
    CompileResult r = compile("1 - x^2 - y^2 - z^2");
    ASSERT_TRUE(r.ok());
    ScalarEvaluator e(*r.tape); // after its warm-up
    for (unsigned i = 0; i < kScalarWarmUp; ++i) {
        e.evaluate(pointXYZ(0.1 * i, 0, 0));
        ASSERT_FALSE(e.compiledLast()) << i;
    }
    e.evaluate(pointXYZ(0.5, 0, 0));
    EXPECT_TRUE(e.compiledLast());
    ScalarEvaluator copy(e); // a copy warms up anew
    copy.evaluate(pointXYZ(0.5, 0, 0));
    EXPECT_FALSE(copy.compiledLast());
    // New parameter values (a slider moving) start the warm-up again
    // rather than compiling at each; a NaN value is still the same value.
    CompileResult withK = compile("param k = 1; k * x - y");
    ASSERT_TRUE(withK.ok());
    ScalarEvaluator slider(*withK.tape);
    warmUp(slider);
    EXPECT_TRUE(slider.compiledLast());
    ASSERT_TRUE(slider.parameters().set("k", std::numeric_limits<double>::quiet_NaN()));
    for (unsigned i = 0; i < kScalarWarmUp; ++i) {
        EXPECT_TRUE(std::isnan(slider.evaluate(pointXYZ(1, 0, 0))));
        ASSERT_FALSE(slider.compiledLast()) << i;
    }
    EXPECT_TRUE(std::isnan(slider.evaluate(pointXYZ(1, 0, 0))));
    EXPECT_TRUE(slider.compiledLast());
    EXPECT_TRUE(std::isnan(slider.evaluate(pointXYZ(1, 0, 0))));
    EXPECT_TRUE(slider.compiledLast()); // not made again at each call
    ScalarEvaluator moved(std::move(slider));
    EXPECT_TRUE(std::isnan(moved.evaluate(pointXYZ(1, 0, 0))));
    EXPECT_TRUE(moved.compiledLast());

    BatchJit::setAllowed(false);
    ScalarEvaluator off(*r.tape, ScalarCode::Compiled);
    EXPECT_EQ(off.evaluate(pointXYZ(0.5, 0, 0)), 0.75);
    EXPECT_FALSE(off.compiledLast());
    BatchJit::setAllowed(true);
}

} // namespace
} // namespace fl::formula
