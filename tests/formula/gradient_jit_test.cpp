// The gradient evaluator's one point as machine code (issue 31 §1:
// gradient_jit.h) against its interpreter: the value and the three slopes of
// every operation the code writes or calls out for, at the values where
// semantics bite (±0, ±inf, NaN, subnormals, huge and tiny), random formulas
// deep enough to keep more duals than registers, every output of a script,
// slopes along u v w, parameters changing under it — each the interpreter's
// bits exactly (or NaN where it is NaN). An evaluator asked for a few points
// stays interpreted; FUNCTIONLAB_NO_JIT's switch leaves every one
// interpreted. Skipped where the CPU has no AVX2.
#include "formula/batch_jit.h"
#include "formula/compiler.h"
#include "formula/eval_gradient.h"
#include "formula/gradient_jit.h"

#include "random_formula.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>
#include <vector>

namespace fl::formula {
namespace {

using testing::sameBits;

constexpr std::array<Input, 3> kXyz = {Input::X, Input::Y, Input::Z};

class GradientJitTest : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!BatchJit::available()) GTEST_SKIP() << "no AVX2 here (or FUNCTIONLAB_NO_JIT)";
    }
};

// An empty string when the duals agree bit for bit (or both NaN), else what differs.
std::string differs(const Dual& a, const Dual& b) {
    if (!sameBits(a.v, b.v)) return "value " + std::to_string(a.v) + " vs " + std::to_string(b.v);
    for (int i = 0; i < 3; ++i)
        if (!sameBits(a.d[std::size_t(i)], b.d[std::size_t(i)]))
            return "slope " + std::to_string(i) + " " + std::to_string(a.d[std::size_t(i)]) +
                   " vs " + std::to_string(b.d[std::size_t(i)]);
    return {};
}

// Both ways at every pair of special values: true when every compiled point
// ran as machine code.
bool agreeOnSpecials(const std::string& src, std::array<Input, 3> wrt = kXyz) {
    CompileResult r = compile(src);
    EXPECT_TRUE(r.ok()) << src;
    if (!r.ok()) return false;
    GradientEvaluator compiled(*r.tape, wrt, ScalarCode::Compiled);
    GradientEvaluator interpreted(*r.tape, wrt, ScalarCode::Interpreted);
    bool ran = true;
    for (double a : testing::specialValues())
        for (double b : testing::specialValues()) {
            const Point p{a, b, a * 0.5 - b, 0.25, b, -0.2, a};
            const Dual x = compiled.evaluate(p), y = interpreted.evaluate(p);
            ran = ran && compiled.compiledLast();
            EXPECT_FALSE(interpreted.compiledLast());
            if (std::string d = differs(x, y); !d.empty()) {
                ADD_FAILURE() << src << " at x=" << a << " y=" << b << ": " << d;
                return ran;
            }
        }
    return ran;
}

TEST_F(GradientJitTest, EveryOperationGivesTheInterpretersValueAndSlopes) {
    std::vector<std::string> sources = testing::jitOperationFormulas();
    sources.insert(sources.end(),
                   {"sin(x) * cos(y) + sin(y) * cos(x)",
                    "sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)",
                    "x + t * u - v / w", "x * x", "y / x", "x + x", "x - x", "x / x",
                    "min(x, x + 0)", "max(x + 0, x)", "-x", "-(x * y)", "max(y, -y)",
                    "x^7 - x^-5 + x^1", "sqrt(x * y)", "abs(x - y) * abs(x)", "(x ? y : z) * x",
                    "2 * x / 3 - (1 - y) * (z + 0.5)", "x ? 2 * y : -z"});
    int ran = 0;
    for (const std::string& src : sources)
        ran += agreeOnSpecials(src) ? 1 : 0;
    EXPECT_EQ(ran, int(sources.size())); // every one ran as machine code
}

TEST_F(GradientJitTest, SlopesThatUnderflowToMinusZeroFollowTheZeroRule) {
    // A slope times a tiny f' underflows to -0 (the square of x * 1e-200 at
    // x < 0); the interpreter's zero rule makes a sum of two such, or of one
    // and a +0 slope subtracted, +0 — the code's "+ (-0, +0, +0, +0)".
    const char* sources[] = {"(x * 1e-200)^2 + (x * 1e-200)^2",
                             "(x * 1e-200)^2 - y",
                             "(x * 1e-200)^2 + (y * 1e-200)^2 - (z * 1e-200)^2",
                             "min((x * 1e-200)^2, y) + z",
                             "-(x * 1e-200)^2 - (y * 1e-200)^2",
                             "abs(x) * (y * 1e-200)^2"};
    const double tiny[] = {1e-200, -1e-200, 1e-160, -1e-160, 1.0, -1.0, 0.0, -0.0};
    for (const char* src : sources) {
        CompileResult r = compile(src);
        ASSERT_TRUE(r.ok()) << src;
        GradientEvaluator compiled(*r.tape, kXyz, ScalarCode::Compiled);
        GradientEvaluator interpreted(*r.tape, kXyz, ScalarCode::Interpreted);
        for (double x : tiny)
            for (double y : tiny)
                for (double z : tiny) {
                    const Point p = pointXYZ(x, y, z);
                    ASSERT_EQ(differs(compiled.evaluate(p), interpreted.evaluate(p)), "")
                        << src << " at " << x << ", " << y << ", " << z;
                    ASSERT_TRUE(compiled.compiledLast());
                }
    }
}

TEST_F(GradientJitTest, SlopesAlongUvwAndRepeatedInputsGiveTheInterpretersBits) {
    EXPECT_TRUE(agreeOnSpecials("u * v - sin(w) * u + x", {Input::U, Input::V, Input::W}));
    EXPECT_TRUE(agreeOnSpecials("x * y - z", {Input::X, Input::X, Input::Y}));
    EXPECT_TRUE(agreeOnSpecials("t * x + y", {Input::T, Input::Z, Input::X}));
}

TEST_F(GradientJitTest, RandomFormulasGiveTheInterpretersBits) {
    // Every operator family, deep enough that more duals are live than the
    // eight registers that keep them.
    std::mt19937_64 rng(3131);
    std::uniform_real_distribution<double> v(-3, 3);
    int compiled = 0;
    for (int i = 0; i < 300; ++i) {
        const std::string src = testing::randomFormula(rng, 2 + i % 6);
        CompileResult r = compile(src);
        if (!r.ok()) continue;
        GradientEvaluator jit(*r.tape, kXyz, ScalarCode::Compiled);
        GradientEvaluator interpreted(*r.tape, kXyz, ScalarCode::Interpreted);
        for (int k = 0; k < 12; ++k) {
            const Point p{v(rng), k % 4 ? v(rng) : -0.0, k % 5 ? v(rng) : 0.0, 0.7, 0, 0, 0};
            const Dual a = jit.evaluate(p), b = interpreted.evaluate(p);
            ASSERT_EQ(differs(a, b), "") << src << " at point " << k;
        }
        compiled += jit.compiledLast() ? 1 : 0;
    }
    EXPECT_GT(compiled, 250);
}

TEST_F(GradientJitTest, SixteenDualsLiveAtOnceGoToMemoryAndComeBack) {
    const std::string src = testing::sixteenLiveValues();
    EXPECT_TRUE(agreeOnSpecials(src));
}

TEST_F(GradientJitTest, EveryOutputOfAScriptAndNewParametersGiveTheInterpretersBits) {
    CompileOptions options;
    options.kind = DefinitionKind::Colour;
    const char* scripts[] = {"param k = 2; r = sin(k * x) * y; g = max(r, z * k); b = 0.5;",
                             "param k = 1; r = x; g = sin(y) * z; b = g;",
                             "param k = 0; r = 0.25 + k; g = y * z; b = t;"};
    for (const char* script : scripts) {
        CompileResult r = compile(script, options);
        ASSERT_TRUE(r.ok()) << script;
        GradientEvaluator compiled(*r.tape, kXyz, ScalarCode::Compiled);
        GradientEvaluator interpreted(*r.tape, kXyz, ScalarCode::Interpreted);
        const std::size_t n = r.tape->outputs.size();
        ASSERT_EQ(n, 3u);
        for (double k : {2.0, -1.5, 2.0, 0.0, -0.0}) {
            ASSERT_TRUE(compiled.parameters().set("k", k));
            ASSERT_TRUE(interpreted.parameters().set("k", k));
            for (double x : {-1.0, 0.25, 3.5, -0.0}) {
                const Point p = pointXYZ(x, 0.5 * x, 1 - x, 0.1);
                std::vector<Dual> a(n), b(n);
                compiled.evaluateAll(p, a.data());
                interpreted.evaluateAll(p, b.data());
                EXPECT_TRUE(compiled.compiledLast());
                for (std::size_t o = 0; o < n; ++o)
                    EXPECT_EQ(differs(a[o], b[o]), "")
                        << script << " k = " << k << " x = " << x << " output " << o;
                EXPECT_EQ(differs(compiled.evaluate(p), b[0]), "") << script;
            }
        }
    }
}

TEST_F(GradientJitTest, WorkOnTimeAloneRunsOncePerMomentWithTheInterpretersBits) {
    // What depends on t alone runs only when t's bits change: moments
    // repeated, changed, signed zeros, NaN and infinity between points, with
    // slopes along x y z and along t, for every output.
    CompileOptions colour;
    colour.kind = DefinitionKind::Colour;
    const auto& moments = testing::momentsToVisit();
    for (const std::array<Input, 3> wrt : {kXyz, std::array{Input::T, Input::X, Input::Y}})
        for (const testing::TimeCase& c : testing::timeOnlyCases()) {
            CompileResult r = c.colour ? compile(c.src, colour) : compile(c.src);
            ASSERT_TRUE(r.ok()) << c.src;
            GradientEvaluator compiled(*r.tape, wrt, ScalarCode::Compiled);
            GradientEvaluator interpreted(*r.tape, wrt, ScalarCode::Interpreted);
            const std::size_t n = r.tape->outputs.size();
            for (double t : moments)
                for (double x : {-0.5, 0.75, 2.0}) {
                    const Point p{x, 0.5 - x, x * x, t, 0, 0, 0};
                    std::vector<Dual> all(n), expected(n);
                    compiled.evaluateAll(p, all.data());
                    ASSERT_TRUE(compiled.compiledLast());
                    interpreted.evaluateAll(p, expected.data());
                    for (std::size_t o = 0; o < n; ++o)
                        ASSERT_EQ(differs(all[o], expected[o]), "")
                            << c.src << " at t=" << t << " x=" << x << " output " << o;
                }
            // A copy keeps the moment's work (at the last t it skips it) and
            // goes on from there.
            GradientEvaluator copy(compiled);
            for (double t : {moments.back(), 0.75}) {
                const Point p{0.3, 0.2, 0.1, t, 0, 0, 0};
                std::vector<Dual> all(n), expected(n);
                copy.evaluateAll(p, all.data());
                interpreted.evaluateAll(p, expected.data());
                for (std::size_t o = 0; o < n; ++o)
                    ASSERT_EQ(differs(all[o], expected[o]), "")
                        << c.src << " (copy) at t=" << t << " output " << o;
            }
        }
}

TEST_F(GradientJitTest, TapesThatDifferOnlyInTheirOutputsGetCodeOfTheirOwn) {
    // Which instructions run once per moment depends on the outputs (one
    // that writes an output stays in place): the same instructions with an
    // output more must not get the other tape's code from the cache.
    CompileOptions colour;
    colour.kind = DefinitionKind::Colour;
    CompileResult r = compile("r = sin(t) * x; g = 0; b = 0;", colour);
    ASSERT_TRUE(r.ok());
    const Tape first = *r.tape;
    Tape second = first;
    std::int32_t sine = -1;
    for (const Instruction& ins : second.code)
        if (ins.op == Op::Sin) sine = ins.out;
    ASSERT_GE(sine, 0) << first.disassemble();
    second.outputs[1].value = Operand::ofReg(sine);
    for (const Tape* tape : {&first, static_cast<const Tape*>(&second)}) { // first, first
        GradientEvaluator compiled(*tape, kXyz, ScalarCode::Compiled);
        GradientEvaluator interpreted(*tape, kXyz, ScalarCode::Interpreted);
        const std::size_t n = tape->outputs.size();
        for (double t : {0.5, 1.5, 1.5}) {
            const Point p = pointXYZ(0.75, 0.1, 0.2, t);
            std::vector<Dual> all(n), expected(n);
            compiled.evaluateAll(p, all.data());
            ASSERT_TRUE(compiled.compiledLast());
            interpreted.evaluateAll(p, expected.data());
            for (std::size_t o = 0; o < n; ++o)
                EXPECT_EQ(differs(all[o], expected[o]), "") << "t=" << t << " output " << o;
        }
    }
    EXPECT_NE(GradientJit::compile(first, kXyz), GradientJit::compile(second, kXyz));
}

TEST_F(GradientJitTest, ManyPointsRunAsCodeWhereRowLoopsWouldNotWithTheSameBits) {
    // evaluateMany keeps its row loops for sums of squares, CSG and trig and
    // runs the code point by point where most operations have no row loop
    // (abs, powers, division); either way each point's bits are evaluate()'s.
    struct Case {
        const char* src;
        bool byCode;
    };
    const Case cases[] = {{"max(abs(x), max(abs(y), abs(z))) - 0.8", true},
                          {"x^4 + y^4 + z^4 - 0.5", true},
                          {"x / (1 + y*y) - z", true},
                          {"1 - x^2 - y^2 - z^2", false},
                          {"(1-x^2-y^2-z^2) & (-((z-x) & y & z))", false},
                          {"sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)", false}};
    std::vector<Point> points;
    for (double a : testing::specialValues())
        for (double b : testing::specialValues())
            points.push_back({a, b, 0.5 * a - b, 0.25, 0, 0, 0});
    for (const Case& c : cases) {
        CompileResult r = compile(c.src);
        ASSERT_TRUE(r.ok()) << c.src;
        GradientEvaluator many(*r.tape, kXyz, ScalarCode::Compiled);
        GradientEvaluator one(*r.tape, kXyz, ScalarCode::Interpreted);
        std::vector<Dual> out(points.size());
        many.evaluateMany(points.data(), points.size(), out.data());
        EXPECT_EQ(many.compiledLast(), c.byCode) << c.src;
        for (std::size_t i = 0; i < points.size(); ++i)
            ASSERT_EQ(differs(out[i], one.evaluate(points[i])), "") << c.src << " point " << i;
    }
    // After the warm-up only: 100 points, then 289 (the warm-up ends inside
    // that call, still rows); the third call is code.
    CompileResult r = compile(cases[0].src);
    ASSERT_TRUE(r.ok());
    GradientEvaluator e(*r.tape);
    std::vector<Dual> out(points.size());
    e.evaluateMany(points.data(), 100, out.data());
    EXPECT_FALSE(e.compiledLast());
    e.evaluateMany(points.data(), points.size(), out.data());
    EXPECT_FALSE(e.compiledLast());
    e.evaluateMany(points.data(), points.size(), out.data());
    EXPECT_TRUE(e.compiledLast());
}

TEST_F(GradientJitTest, ManyPointsAsCodeFollowTimeAndParameters) {
    // evaluateMany through the code: t changing within a call and between
    // calls (work on t alone runs once per moment), a parameter changed
    // between calls; every point as evaluate() gives it.
    CompileResult r = compile("param k = 2; abs(x * k) + abs(t * y) - z / (1 + t * t)");
    ASSERT_TRUE(r.ok());
    GradientEvaluator many(*r.tape, kXyz, ScalarCode::Compiled);
    GradientEvaluator one(*r.tape, kXyz, ScalarCode::Interpreted);
    std::vector<Point> points;
    const auto& moments = testing::momentsToVisit();
    for (std::size_t i = 0; i < 3 * moments.size(); ++i)
        points.push_back({0.25 * double(i % 7) - 0.5, 0.5 - 0.125 * double(i % 5), -0.75,
                          moments[i / 3], 0, 0, 0});
    for (double k : {2.0, -0.5, -0.0}) {
        ASSERT_TRUE(many.parameters().set("k", k));
        ASSERT_TRUE(one.parameters().set("k", k));
        std::vector<Dual> out(points.size());
        many.evaluateMany(points.data(), points.size(), out.data());
        ASSERT_TRUE(many.compiledLast());
        for (std::size_t i = 0; i < points.size(); ++i)
            ASSERT_EQ(differs(out[i], one.evaluate(points[i])), "") << "k=" << k << " point " << i;
    }
}

TEST_F(GradientJitTest, AnEvaluatorAskedForAFewPointsStaysInterpreted) {
    CompileResult r = compile("x * y - z^2");
    ASSERT_TRUE(r.ok());
    GradientEvaluator e(*r.tape);
    for (unsigned i = 0; i < kScalarWarmUp; ++i) {
        e.evaluate(pointXYZ(1, 2, 3));
        ASSERT_FALSE(e.compiledLast()) << i;
    }
    const Dual d = e.evaluate(pointXYZ(1, 2, 3));
    EXPECT_TRUE(e.compiledLast());
    EXPECT_EQ(d.v, 2.0 - 9.0);
    EXPECT_EQ(d.d[0], 2.0);
    EXPECT_EQ(d.d[1], 1.0);
    EXPECT_EQ(d.d[2], -6.0);
    GradientEvaluator copy(e); // shares the code
    EXPECT_EQ(differs(copy.evaluate(pointXYZ(-1, 0.5, 2)), e.evaluate(pointXYZ(-1, 0.5, 2))), "");
}

TEST_F(GradientJitTest, OneTapeIsCompiledOnceAndTheSwitchLeavesItInterpreted) {
    CompileResult r = compile("sqrt(x*x + y*y) - 0.5 + z");
    ASSERT_TRUE(r.ok());
    const auto first = GradientJit::compile(*r.tape, kXyz);
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(GradientJit::compile(*r.tape, kXyz), first);
    EXPECT_NE(GradientJit::compile(*r.tape, {Input::Y, Input::X, Input::Z}), first);
    EXPECT_GT(first->codeBytes(), 0u);
    BatchJit::setAllowed(false);
    GradientEvaluator e(*r.tape, kXyz, ScalarCode::Compiled);
    const Dual d = e.evaluate(pointXYZ(3, 4, 1));
    BatchJit::setAllowed(true);
    EXPECT_FALSE(e.compiledLast());
    EXPECT_EQ(d.v, 5.5);
    EXPECT_DOUBLE_EQ(d.d[0], 0.6);
    EXPECT_DOUBLE_EQ(d.d[1], 0.8);
    EXPECT_EQ(d.d[2], 1.0);
}

} // namespace
} // namespace fl::formula
