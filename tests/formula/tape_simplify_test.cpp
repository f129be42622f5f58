// Law: a tape simplified for a box (tape_simplify.h) gives the full tape's
// bits at every point of the box — values, gradients and batches — and its
// intervals over sub-boxes still contain every point value.
#include "formula/compiler.h"
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_interval.h"
#include "formula/eval_scalar.h"
#include "formula/tape_simplify.h"
#include "random_formula.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

namespace fl::formula {
namespace {

using testing::sameBits;

Tape compiled(const std::string& src) {
    CompileResult r = compile(src);
    EXPECT_TRUE(r.ok()) << src;
    return r.ok() ? *r.tape : Tape{};
}

struct Simplification {
    Tape tape;
    std::vector<Keep> keep;
    std::size_t decided = 0;
};

Simplification simplifyOver(const Tape& full, const Box& box) {
    IntervalEvaluator interval(full);
    Simplification s;
    (void)interval.evaluate(box, s.keep);
    s.decided = std::size_t(
        std::count_if(s.keep.begin(), s.keep.end(), [](Keep k) { return k != Keep::All; }));
    s.tape = simplifyTape(full, s.keep);
    return s;
}

// Compares the two tapes at `samples` points of the box (its corners first)
// with every evaluator; returns whether any instruction was dropped.
void expectSameInBox(const std::string& src, const Tape& full, const Tape& simple,
                     const double lo[3], const double hi[3], double t, std::mt19937_64& rng,
                     int samples) {
    ScalarEvaluator fullScalar(full), simpleScalar(simple);
    GradientEvaluator fullGradient(full), simpleGradient(simple);
    IntervalEvaluator simpleInterval(simple);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xs, ys, zs;
    std::vector<double> expected;
    for (int s = 0; s < samples; ++s) {
        Point p{};
        for (int i = 0; i < 3; ++i) {
            const double u = s < 8 ? double((s >> i) & 1) : unit(rng);
            p[std::size_t(i)] = std::min(hi[i], lo[i] + u * (hi[i] - lo[i]));
        }
        p[3] = t;
        const double f = fullScalar.evaluate(p);
        ASSERT_TRUE(sameBits(simpleScalar.evaluate(p), f))
            << src << " at (" << p[0] << ", " << p[1] << ", " << p[2] << "): simplified "
            << simpleScalar.evaluate(p) << ", full " << f << "\n"
            << simple.disassemble();
        const Dual g = fullGradient.evaluate(p), h = simpleGradient.evaluate(p);
        ASSERT_TRUE(sameBits(g.v, h.v)) << src;
        for (std::size_t k = 0; k < 3; ++k)
            ASSERT_TRUE(sameBits(g.d[k], h.d[k])) << src << " d/d"
                                                  << "xyz"[k];
        xs.push_back(p[0]);
        ys.push_back(p[1]);
        zs.push_back(p[2]);
        expected.push_back(f);
    }
    // The batch evaluator (machine code where it compiles) on the simplified tape.
    BatchEvaluator batch(simple);
    BatchInputs in;
    in.set(Input::X, xs.data());
    in.set(Input::Y, ys.data());
    in.set(Input::Z, zs.data());
    in.set(Input::T, t);
    std::vector<double> out(xs.size());
    batch.evaluate(in, xs.size(), out.data());
    for (std::size_t i = 0; i < out.size(); ++i)
        ASSERT_TRUE(sameBits(out[i], expected[i])) << src << " batch point " << i;
    // Intervals of the simplified tape over a sub-box still contain its points.
    const Interval r = simpleInterval.evaluate(boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], t));
    for (double f : expected)
        ASSERT_TRUE(r.contains(f)) << src;
}

TEST(TapeSimplify, RandomFormulasKeepTheirBitsInTheirBox) {
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> centre(-3.0, 3.0);
    std::uniform_real_distribution<double> logWidth(-4.0, 0.5);
    std::size_t tapes = 0, simplified = 0, dropped = 0, before = 0;
    for (int f = 0; f < 400; ++f) {
        const std::string src = testing::randomFormula(rng, 2 + f % 5);
        const Tape full = compiled(src);
        if (full.code.empty()) continue;
        for (int b = 0; b < 8; ++b) {
            double lo[3], hi[3];
            for (int i = 0; i < 3; ++i) {
                const double c = centre(rng), w = std::pow(10.0, logWidth(rng));
                lo[i] = c - w;
                hi[i] = c + w;
            }
            const double t = 0.3;
            const Simplification s =
                simplifyOver(full, boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], t));
            ASSERT_LE(s.tape.code.size(), full.code.size()) << src;
            ++tapes;
            if (s.decided > 0) ++simplified;
            dropped += full.code.size() - s.tape.code.size();
            before += full.code.size();
            expectSameInBox(src, full, s.tape, lo, hi, t, rng, 24);
        }
    }
    // The law must have been put to work, not passed by doing nothing.
    EXPECT_GT(simplified, tapes / 10) << simplified << " of " << tapes;
    EXPECT_GT(dropped, before / 20) << dropped << " of " << before;
}

TEST(TapeSimplify, TheWatermelonAwayFromItsCutIsItsSphere) {
    const std::string melon = "(1-x^2-y^2-z^2) & (-((z-x) & y & z))";
    const Tape full = compiled(melon);
    // Around (0, -0.8, -0.6): y and z are far below 0, so the cut's inner
    // min is below them and its negation far above the sphere's values.
    const Simplification s = simplifyOver(full, boxXYZ(-0.05, 0.05, -0.85, -0.75, -0.65, -0.55));
    const Tape sphere = compiled("1-x^2-y^2-z^2");
    EXPECT_EQ(s.tape.code.size(), sphere.code.size()) << s.tape.disassemble();
    EXPECT_FALSE(s.tape.usesInput[3]);
    std::mt19937_64 rng(1);
    const double lo[3] = {-0.05, -0.85, -0.65}, hi[3] = {0.05, -0.75, -0.55};
    expectSameInBox(melon, full, s.tape, lo, hi, 0, rng, 64);
    // Over the whole melon, where the sphere's surface meets the cut,
    // nothing can be decided at the outer min.
    const Simplification whole = simplifyOver(full, boxXYZ(-1, 1, -1, 1, -1, 1));
    EXPECT_EQ(whole.keep.back(), Keep::All);
    EXPECT_EQ(whole.decided, 0u);
}

TEST(TapeSimplify, AnOperandThatMayBeNaNIsNeverDropped) {
    // min(a, b) is NaN where b is, however far below b a lies.
    const Tape full = compiled("min(x - 10, sqrt(x))");
    const Simplification s = simplifyOver(full, boxXYZ(-1, 1, 0, 0, 0, 0));
    EXPECT_EQ(s.decided, 0u) << s.tape.disassemble();
    ScalarEvaluator e(s.tape);
    EXPECT_TRUE(std::isnan(e.evaluate(pointXYZ(-0.5, 0, 0))));
    // The kept operand may be NaN itself: min(NaN, b) is NaN either way.
    const Tape other = compiled("min(sqrt(x) - 10, x)");
    const Simplification t = simplifyOver(other, boxXYZ(-1, 1, 0, 0, 0, 0));
    EXPECT_EQ(t.decided, 1u) << t.tape.disassemble();
    std::mt19937_64 rng(2);
    const double lo[3] = {-1, 0, 0}, hi[3] = {1, 0, 0};
    expectSameInBox("min(sqrt(x) - 10, x)", other, t.tape, lo, hi, 0, rng, 32);
    // A tie allowed at the boundary is not decided (the signed zero of
    // min(+0, -0) depends on which operand is kept).
    // (min(-x, x) at x = 0 is min(-0, +0) = +0: keeping -x would give -0.)
    for (const char* src : {"max(x, -x)", "min(-x, x)", "max(-x, x)", "min(x, -x)"})
        EXPECT_EQ(simplifyOver(compiled(src), boxXYZ(0, 1, 0, 0, 0, 0)).decided, 0u) << src;
}

TEST(TapeSimplify, ASelectKeepsTheBranchItsConditionDecides) {
    const std::string src = "(x > 0) ? y * y : z * z * z";
    const Tape full = compiled(src);
    std::mt19937_64 rng(3);
    for (const double side : {1.0, -1.0}) {
        const double lo[3] = {side > 0 ? 0.5 : -2.0, -1, -1}, hi[3] = {side > 0 ? 2.0 : -0.5, 1, 1};
        const Simplification s =
            simplifyOver(full, boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]));
        EXPECT_EQ(s.decided, 1u);
        EXPECT_EQ(s.tape.usesInput[std::size_t(side > 0 ? Input::Z : Input::Y)], false)
            << s.tape.disassemble();
        expectSameInBox(src, full, s.tape, lo, hi, 0, rng, 32);
    }
}

TEST(TapeSimplify, AConstantBranchLeavesItsUsersReadingTheConstant) {
    // max(x, 5) is 5 for x below 5: what reads it reads the constant.
    const Tape full = compiled("max(x, 5) * y + max(x, 5)");
    const Simplification s = simplifyOver(full, boxXYZ(-1, 1, -1, 1, 0, 0));
    EXPECT_FALSE(s.tape.usesInput[0]) << s.tape.disassemble();
    EXPECT_EQ(s.tape.code.size(), 2u) << s.tape.disassemble(); // 5 * y, + 5
    ScalarEvaluator e(s.tape);
    EXPECT_EQ(e.evaluate(pointXYZ(0.3, 0.5, 0)), 7.5);
    // A box where the whole formula is one operand's constant: no code at all.
    const Simplification c = simplifyOver(compiled("max(x, 5)"), boxXYZ(-1, 1, 0, 0, 0, 0));
    EXPECT_TRUE(c.tape.code.empty());
    ASSERT_EQ(c.tape.outputs.size(), 1u);
    EXPECT_TRUE(c.tape.outputs[0].value.isConst());
    EXPECT_EQ(c.tape.outputs[0].value.value, 5.0);
}

// An operation left with constant operands is kept, not folded: its interval
// is widened as the full tape widens it (sin([0, 0]) is not exactly [0, 0]),
// so the simplified tape's intervals over the box are the full tape's — the
// mesher then prunes the same blocks and warns the same.
TEST(TapeSimplify, IntervalsOverTheBoxAreTheFullTapes) {
    std::mt19937_64 rng(5);
    const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    for (const char* src : {"sin(max(x - 10, 0)) - y*y", "sqrt(min(x + 10, 2)) * y - z",
                            "(x > 5) ? y : cos(max(x, 3)) + z"}) {
        const Tape full = compiled(src);
        const Box box = boxXYZ(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        const Simplification s = simplifyOver(full, box);
        EXPECT_GT(s.decided, 0u) << src;
        IntervalEvaluator a(full), b(s.tape);
        const Interval ra = a.evaluate(box), rb = b.evaluate(box);
        EXPECT_EQ(ra.lo, rb.lo) << src;
        EXPECT_EQ(ra.hi, rb.hi) << src;
        EXPECT_EQ(ra.nan, rb.nan) << src;
        expectSameInBox(src, full, s.tape, lo, hi, 0, rng, 16);
    }
}

TEST(TapeSimplify, ParametersKeepTheirNamesAndRegisters) {
    const Tape full = compiled("param R = 0.5; return min(R - x, 3 + y);");
    const Simplification s = simplifyOver(full, boxXYZ(0, 1, 0, 1, 0, 0));
    EXPECT_EQ(s.decided, 1u);
    ScalarEvaluator e(s.tape);
    ASSERT_TRUE(e.parameters().set("R", 0.75));
    EXPECT_EQ(e.evaluate(pointXYZ(0.25, 0, 0)), 0.5);
}

} // namespace
} // namespace fl::formula
