// The batch evaluator agrees with the scalar one bit for bit, whatever mix of
// array and uniform inputs, block boundaries or parameters.
#include "formula/eval_batch.h"
#include "random_formula.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>

namespace fl::formula {
namespace {

using testing::sameBits;

void checkAgainstScalar(const std::string& src, std::mt19937_64& rng, std::size_t n,
                        bool uniformZ) {
    CompileResult r = compile(src);
    ASSERT_TRUE(r.ok()) << src;
    std::uniform_real_distribution<double> v(-3, 3);
    std::vector<double> xs(n), ys(n), zs(n), out(n);
    for (std::size_t i = 0; i < n; ++i) {
        xs[i] = v(rng);
        ys[i] = v(rng);
        zs[i] = v(rng);
    }
    double zu = v(rng), t = v(rng);
    BatchEvaluator batch(*r.tape);
    BatchInputs in;
    in.set(Input::X, xs.data());
    in.set(Input::Y, ys.data());
    if (uniformZ)
        in.set(Input::Z, zu);
    else
        in.set(Input::Z, zs.data());
    in.set(Input::T, t);
    batch.evaluate(in, n, out.data());
    ScalarEvaluator scalar(*r.tape);
    for (std::size_t i = 0; i < n; ++i) {
        double s = scalar.evaluate(pointXYZ(xs[i], ys[i], uniformZ ? zu : zs[i], t));
        ASSERT_TRUE(sameBits(s, out[i]))
            << src << " at " << i << ": scalar " << s << " batch " << out[i];
    }
}

TEST(Batch, MatchesScalarOnRandomFormulas) {
    std::mt19937_64 rng(3);
    for (int i = 0; i < 300; ++i) {
        std::string src = testing::randomFormula(rng, 1 + i % 5);
        checkAgainstScalar(src, rng, i % 3 == 0 ? 1000 : 77, i % 2 == 0);
    }
}

TEST(Batch, TrigonometryNextToHugeOrUndefinedArgumentsMatchesScalar) {
    // SLEEF reduces a whole vector the slow way when one lane is large or
    // NaN; small lanes beside it must still give the scalar bits.
    for (const char* src : {"sin(x)", "cos(x)", "tan(x)", "sin(x) * cos(x)",
                            "cos(2*x) - sin(2*x) + sin(x)", "sin(x) * cos(x) - sin(3*x)"}) {
        CompileResult r = compile(src);
        ASSERT_TRUE(r.ok());
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> small(-3, 3);
        std::vector<double> xs(40000), out(40000);
        for (std::size_t i = 0; i < xs.size(); ++i)
            xs[i] = i % 4 == 1 ? (i % 8 == 1 ? 1e17 * small(rng) : std::nan("")) : small(rng);
        BatchEvaluator batch(*r.tape);
        BatchInputs in;
        in.set(Input::X, xs.data());
        batch.evaluate(in, xs.size(), out.data());
        ScalarEvaluator scalar(*r.tape);
        for (std::size_t i = 0; i < xs.size(); ++i)
            ASSERT_TRUE(sameBits(scalar.evaluate(pointXYZ(xs[i], 0, 0, 0)), out[i]))
                << src << " at x = " << xs[i];
    }
}

TEST(Batch, BlockBoundariesAndEmptyCalls) {
    std::mt19937_64 rng(4);
    for (std::size_t n :
         {std::size_t{0}, std::size_t{1}, BatchEvaluator::kBlock - 1, BatchEvaluator::kBlock,
          BatchEvaluator::kBlock + 1, 3 * BatchEvaluator::kBlock + 17})
        checkAgainstScalar("sin(x) * y - z^3 & x", rng, n, false);
}

TEST(Batch, ParametersAndUniformSubexpressions) {
    CompileResult r = compile("param R = 1; return R^2 - x^2 - (y - abs(sin(pi*t)))^2;");
    ASSERT_TRUE(r.ok());
    BatchEvaluator b(*r.tape);
    double xs[3] = {0, 0.5, 1}, ys[3] = {1, 1, 1}, out[3];
    BatchInputs in;
    in.set(Input::X, xs);
    in.set(Input::Y, ys);
    in.set(Input::T, 0.5);
    b.evaluate(in, 3, out);
    EXPECT_DOUBLE_EQ(out[0], 1.0);
    b.parameters().set("R", 2.0);
    b.evaluate(in, 3, out);
    EXPECT_DOUBLE_EQ(out[0], 4.0);
    in.set(Input::T, 0.0); // re-specialises for the new t
    b.evaluate(in, 3, out);
    EXPECT_DOUBLE_EQ(out[0], 3.0);
}

TEST(Batch, MultipleOutputsAndConstantOutputs) {
    CompileOptions o;
    o.kind = DefinitionKind::Parametric;
    CompileResult r = compile("x = cos(u); y = 2; z = t;", o);
    ASSERT_TRUE(r.ok());
    BatchEvaluator b(*r.tape);
    double us[2] = {0, 3.141592653589793}, ox[2], oy[2], oz[2];
    double* outs[3] = {ox, oy, oz};
    BatchInputs in;
    in.set(Input::U, us);
    in.set(Input::T, 0.7);
    b.evaluate(in, 2, outs);
    EXPECT_EQ(ox[0], 1.0);
    EXPECT_EQ(ox[1], -1.0);
    EXPECT_EQ(oy[1], 2.0);
    EXPECT_EQ(oz[0], 0.7);
}

} // namespace
} // namespace fl::formula

namespace fl::formula {
namespace {

// The fused passes ((a - c)^2, A +/- (b - c)^2) must round exactly like the
// unfused steps: primitives with centres exercise every pattern.
TEST(Batch, FusedSquarePassesMatchScalar) {
    std::mt19937_64 rng(11);
    const char* formulas[] = {
        "sphere(0.3, -0.2, 0.1, 1)",
        "1 - x^2 - y^2 - z^2",
        "(x + 0.5)^2 + (y - 0.25)^2 - (z + 1)^2",
        "x^2 + x",
        "x + x^2",
        "y - (x - 2)^2",
        "torus(0.1, 0.2, 0.3, 1, 0.25) | ellipsoid(0, 0, 0, 1, 2, 3)",
        "0.25 - x^2 - (y - (abs(sin(pi*t)) - 0.5))^2 - z^2",
        "(x - 1)^2 * (x - 1)", // the difference is used twice: must not be fused away
        "blob(0.1, 0.2, 0.3, 1, 2) + blob(-0.1, 0, 0.3, 1, 3) - 0.5",
        "min(min(min(x, y), z), -x)",
        "max(max(max(max(max(x, -y), z), x * y), y - z), -z)",
        "(1-x^2-y^2-z^2) & (-((z-x) & y & z))",
        "x | y | z | (x - y) | (y \\ z)",
    };
    for (const char* f : formulas) {
        checkAgainstScalar(f, rng, 600, false);
        checkAgainstScalar(f, rng, 600, true);
    }
}

} // namespace
} // namespace fl::formula

namespace fl::formula {
namespace {

std::size_t passes(const char* src) {
    CompileResult r = compile(src);
    EXPECT_TRUE(r.ok());
    BatchEvaluator b(*r.tape);
    double xs[4] = {0, 1, 2, 3}, out[4];
    BatchInputs in;
    in.set(Input::X, xs);
    in.set(Input::Y, xs);
    in.set(Input::Z, xs);
    in.set(Input::T, 0.5);
    b.evaluate(in, 4, out);
    return b.passesPerBlock();
}

TEST(Batch, FusionReducesPasses) {
    EXPECT_EQ(passes("1 - x^2 - y^2 - z^2"), 1u);
    EXPECT_EQ(passes("sphere(0.5, 0.2, -0.1, 1)"), 1u);
    EXPECT_EQ(passes("x^2 + y^2"), 1u);
    EXPECT_EQ(passes("0.25 - x^2 - (y - (abs(sin(pi*t)) - 0.5))^2 - z^2"), 1u); // t is uniform
    EXPECT_EQ(passes("x \\ y"), 1u);                                            // min(x, -y)
    EXPECT_LE(passes("(1-x^2-y^2-z^2) & (-((z-x) & y & z))"), 4u);
    EXPECT_EQ(passes("min(min(min(x, y), z), -x)"), 1u);
}

} // namespace
} // namespace fl::formula
