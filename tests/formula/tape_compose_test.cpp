// Inlining tapes into a builder: the composed tape computes exactly what the
// pieces compute at the substituted inputs, for random formulas too.
#include "formula/compiler.h"
#include "formula/eval_gradient.h"
#include "formula/eval_scalar.h"
#include "formula/tape_compose.h"
#include "random_formula.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

using namespace fl::formula;

namespace {

Tape compileTape(const std::string& source, DefinitionKind kind = DefinitionKind::Implicit) {
    CompileOptions o;
    o.kind = kind;
    auto r = fl::formula::compile(source, o);
    if (!r.ok()) throw std::runtime_error("does not compile: " + source);
    return *r.tape;
}

std::array<Val, kInputCount> plainInputs(TapeBuilder& b) {
    std::array<Val, kInputCount> in{};
    for (int i = 0; i < kInputCount; ++i)
        in[std::size_t(i)] = b.input(Input(i));
    return in;
}

} // namespace

TEST(TapeCompose, UnionOfTwoShapesUnderAnAffineMap) {
    const Tape a = compileTape("0.25 - x*x - y*y - z*z");
    const Tape c = compileTape("min(min(0.3 - abs(x), 0.3 - abs(y)), 0.3 - abs(z)) + 0*t");
    TapeBuilder b;
    auto in = plainInputs(b);
    const Val fa = inlineTape(b, a, in)[0];
    // The second shape moved by (0.5, 0, 0) and seen at time 2: inputs x - 0.5, t = 2.
    auto moved = in;
    moved[std::size_t(Input::X)] = b.sub(in[std::size_t(Input::X)], Val::constant(0.5));
    moved[std::size_t(Input::T)] = Val::constant(2);
    const Val fc = inlineTape(b, c, moved)[0];
    const Tape both = b.finish({{"value", b.max(fa, fc)}}, {});
    ScalarEvaluator ea(a), ec(c), e(both);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> d(-1, 1);
    for (int i = 0; i < 500; ++i) {
        const double x = d(rng), y = d(rng), z = d(rng);
        const double expected =
            std::max(ea.evaluate(pointXYZ(x, y, z)), ec.evaluate(pointXYZ(x - 0.5, y, z, 2)));
        EXPECT_EQ(e.evaluate(pointXYZ(x, y, z, 7)), expected);
    }
}

TEST(TapeCompose, ParametersAreFixedAndScriptsInlineWhole) {
    CompileOptions o;
    o.parameters.push_back({"r", 0.5, false, 0, 0});
    auto r =
        fl::formula::compile("function s(q) { return q*q; } k = r*r; k - s(x) - s(y) - s(z)", o);
    ASSERT_TRUE(r.ok());
    TapeBuilder b;
    const Val f = inlineTape(b, *r.tape, plainInputs(b), std::vector<double>{0.8})[0];
    const Tape t = b.finish({{"value", f}}, {});
    ScalarEvaluator e(t);
    EXPECT_DOUBLE_EQ(e.evaluate(pointXYZ(0.1, 0.2, 0.3)), 0.64 - 0.01 - 0.04 - 0.09);
}

TEST(TapeCompose, RandomFormulasInlineToTheSameValues) {
    std::mt19937_64 rng(11);
    int compiled = 0;
    for (int i = 0; i < 200; ++i) {
        const std::string source = fl::formula::testing::randomFormula(rng, 4);
        CompileOptions o;
        auto r = fl::formula::compile(source, o);
        if (!r.ok()) continue;
        ++compiled;
        TapeBuilder b;
        const Val f = inlineTape(b, *r.tape, plainInputs(b))[0];
        const Tape t = b.finish({{"value", f}}, {});
        ScalarEvaluator e0(*r.tape), e1(t);
        for (double x : {-0.7, 0.1, 0.9}) {
            const Point p{x, 0.3, -0.4, 0.5, 0.2, 0.6, 0.7};
            const double v0 = e0.evaluate(p), v1 = e1.evaluate(p);
            if (std::isnan(v0))
                EXPECT_TRUE(std::isnan(v1)) << source;
            else
                EXPECT_EQ(v0, v1) << source;
        }
    }
    // The generator makes formulas that compile; a test that skipped them all
    // would pass while checking nothing.
    EXPECT_GE(compiled, 180) << "of 200";
}

TEST(GradientMany, SameBitsAsPointByPointForRandomFormulas) {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> d(-1.5, 1.5);
    int compiled = 0;
    for (int i = 0; i < 300; ++i) {
        const std::string source = fl::formula::testing::randomFormula(rng, 4);
        CompileOptions o;
        auto r = fl::formula::compile(source, o);
        if (!r.ok()) continue;
        ++compiled;
        // (many: rows or, where the tape mostly lacks them, machine code)
        GradientEvaluator one(*r.tape, {Input::X, Input::Y, Input::Z}, ScalarCode::Interpreted);
        GradientEvaluator many(*r.tape, {Input::X, Input::Y, Input::Z}, ScalarCode::Compiled);
        std::vector<Point> points(150); // more than one block of 64
        // Some coordinates exactly 0, -0, 1 or huge: the zero rule of the
        // derivatives (0 times anything is 0) and ties of min/max at work.
        static constexpr double kSpecial[] = {0.0, -0.0, 1.0, -1.0, 1e300, 0.5};
        std::uniform_int_distribution<int> pick(0, 17);
        auto coordinate = [&] {
            const int k = pick(rng);
            return k < 6 ? kSpecial[k] : d(rng);
        };
        for (Point& p : points)
            p = {coordinate(), coordinate(), coordinate(), d(rng), d(rng), d(rng), d(rng)};
        std::vector<Dual> out(points.size());
        many.evaluateMany(points.data(), points.size(), out.data());
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Dual a = one.evaluate(points[k]);
            const auto same = [](double x, double y) { // bit for bit (-0 is not +0)
                return (std::isnan(x) && std::isnan(y)) ||
                       std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
            };
            ASSERT_TRUE(same(a.v, out[k].v) && same(a.d[0], out[k].d[0]) &&
                        same(a.d[1], out[k].d[1]) && same(a.d[2], out[k].d[2]))
                << source << " at point " << k;
        }
    }
    EXPECT_GE(compiled, 270) << "of 300";
}
