#include "test_helpers.h"

#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/eval_interval.h"
#include "formula/vector_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

namespace fl::formula {
namespace {

TEST(Compiler, FoldsConstants) {
    CompileResult r = compile("2 * pi * 3 + sin(0)");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.tape->code.empty());
    ASSERT_TRUE(r.tape->outputs[0].value.isConst());
    EXPECT_DOUBLE_EQ(r.tape->outputs[0].value.value, 6 * 3.141592653589793);
}

TEST(Compiler, SharesCommonSubexpressions) {
    CompileResult r = compile("sin(x*y) + sin(y*x) + sin(x*y)");
    ASSERT_TRUE(r.ok());
    // mul, sin, add, add: the three sines are one
    EXPECT_EQ(r.tape->code.size(), 4u) << r.tape->disassemble();
}

TEST(Compiler, PowersBecomeCheapOperations) {
    CompileResult r = compile("x^2 + y^3 + x^1");
    ASSERT_TRUE(r.ok());
    std::string text = r.tape->disassemble();
    EXPECT_NE(text.find("square"), std::string::npos);
    EXPECT_NE(text.find("powi"), std::string::npos);
    EXPECT_EQ(text.find("pow "), std::string::npos);
    // x^0.5 stays pow: sqrt differs at -inf and -0
    EXPECT_NE(compile("z^0.5").tape->disassemble().find("pow "), std::string::npos);
}

TEST(Compiler, RegistersAreReusedSoLongFormulasStaySmall) {
    std::string src = "0";
    for (int i = 0; i < 50; ++i)
        src = "max(" + src + ", sphere(" + std::to_string(i * 0.1) + ", 0.2, -0.1, 0.3))";
    CompileResult r = compile(src);
    ASSERT_TRUE(r.ok());
    EXPECT_GT(r.tape->code.size(), 250u); // (y - 0.2) and (z + 0.1) are shared by all 50
    EXPECT_LT(r.tape->registerCount, kInputCount + 8);
}

TEST(Compiler, NoInstructionWritesARegisterItReads) {
    CompileResult r = compile("sin(x) * cos(x) + sin(y) * (x - y) / (z + 1)");
    ASSERT_TRUE(r.ok());
    for (const Instruction& ins : r.tape->code) {
        EXPECT_NE(ins.out, ins.a.reg);
        EXPECT_NE(ins.out, ins.b.reg);
    }
}

// sin(a) and cos(a) become one sincos: paired opcodes, side by side (the
// batch evaluator makes one call of them), whose value is sincos's in every
// evaluator; a sine or cosine without its partner stays as it was.
TEST(Compiler, ASineAndACosineOfOneValueBecomeAPairSideBySide) {
    CompileResult r = compile("sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x) + cos(t)");
    ASSERT_TRUE(r.ok());
    const std::vector<Instruction>& code = r.tape->code;
    int pairs = 0, cosines = 0;
    for (std::size_t i = 0; i < code.size(); ++i) {
        EXPECT_NE(code[i].op, Op::Sin) << r.tape->disassemble();
        if (code[i].op == Op::Cos) ++cosines;
        if (code[i].op != Op::SinOfPair && code[i].op != Op::CosOfPair) continue;
        ASSERT_LT(i + 1, code.size());
        const Op other = code[i].op == Op::SinOfPair ? Op::CosOfPair : Op::SinOfPair;
        EXPECT_EQ(code[i + 1].op, other) << r.tape->disassemble();
        EXPECT_EQ(code[i + 1].a.reg, code[i].a.reg);
        ++pairs;
        ++i;
    }
    EXPECT_EQ(pairs, 3) << r.tape->disassemble();
    EXPECT_EQ(cosines, 1); // cos(t) has no sine beside it
    // the values are sincos's, in the scalar evaluator as in every other
    for (double x : {0.3, -2.0, 17.5, 1e15}) {
        const vmath::SinCos s = vmath::sinCos(x);
        EXPECT_EQ(testing::eval("sin(x) * 3 + cos(x)", x), s.sin * 3 + s.cos) << x;
        EXPECT_EQ(testing::eval("sin(x)", x), vmath::eval(vmath::Unary::Sin, x)) << x;
    }
    // both branches of a choice are computed: they pair too
    EXPECT_EQ(testing::eval("x > 0 ? sin(x) : cos(x)", 0.7), vmath::sinCos(0.7).sin);
}

TEST(Compiler, UnrollsLoopsAndInlinesFunctions) {
    CompileResult r = compile(R"(
        function bump(cx) { return exp(-(x - cx)^2); }
        s = 0;
        for (i = 0; i < 4; i += 1) { s = s + bump(i); }
        return s;)");
    ASSERT_TRUE(r.ok());
    ScalarEvaluator e(*r.tape);
    double x = 1.3, expected = 0;
    for (int i = 0; i < 4; ++i)
        expected += std::exp(-(x - i) * (x - i));
    EXPECT_NEAR(e.evaluate(pointXYZ(x, 0, 0)), expected, 1e-15);
}

TEST(Compiler, ConditionalReturnsAndAssignments) {
    const char* src = R"(
        function f(a) {
            if (a < 0) { return -a; }
            b = a * 2;
            if (a > 10) return 100;
            return b;
        }
        return f(x);)";
    EXPECT_EQ(testing::eval(src, -3), 3.0);
    EXPECT_EQ(testing::eval(src, 4), 8.0);
    EXPECT_EQ(testing::eval(src, 11), 100.0);
}

TEST(Compiler, ParametersAreInputsWithDefaultsAndRanges) {
    CompileResult r = compile("param R = 0.5 in [0.1, 2]; return R^2 - x^2;");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.tape->params.size(), 1u);
    EXPECT_EQ(r.tape->params[0].name, "R");
    EXPECT_TRUE(r.tape->params[0].hasRange);
    EXPECT_EQ(r.tape->params[0].hi, 2.0);
    ScalarEvaluator e(*r.tape);
    EXPECT_DOUBLE_EQ(e.evaluate(pointXYZ(0, 0, 0)), 0.25);
    EXPECT_TRUE(e.parameters().set("R", 2.0));
    EXPECT_FALSE(e.parameters().set("Q", 2.0));
    EXPECT_DOUBLE_EQ(e.evaluate(pointXYZ(1, 0, 0)), 3.0);
}

// Evaluators copy the tape: their parameters must name the copy's, not the
// tape they were made from (which may be gone: ASan saw the read after free).
TEST(Compiler, ParametersOutliveTheTapeAnEvaluatorWasMadeFrom) {
    std::optional<ScalarEvaluator> scalar;
    std::optional<IntervalEvaluator> interval;
    std::optional<GradientEvaluator> gradient;
    std::optional<BatchEvaluator> batch;
    {
        CompileResult r = compile("param R = 0.5 in [0.1, 2]; return R^2 - x^2;");
        ASSERT_TRUE(r.ok());
        scalar.emplace(*r.tape);
        interval.emplace(*r.tape);
        gradient.emplace(*r.tape);
        batch.emplace(*r.tape);
    }
    EXPECT_TRUE(scalar->parameters().set("R", 2.0));
    EXPECT_TRUE(interval->parameters().set("R", 2.0));
    EXPECT_TRUE(gradient->parameters().set("R", 2.0));
    EXPECT_TRUE(batch->parameters().set("R", 2.0));
    EXPECT_DOUBLE_EQ(scalar->evaluate(pointXYZ(1, 0, 0)), 3.0);
    EXPECT_DOUBLE_EQ(gradient->evaluate(pointXYZ(1, 0, 0)).v, 3.0);
    EXPECT_TRUE(interval->evaluate(boxXYZ(1, 1, 0, 0, 0, 0)).contains(3.0));
    const double x = 1, y = 0, z = 0;
    double out = 0;
    BatchInputs in;
    in.set(Input::X, &x);
    in.set(Input::Y, &y);
    in.set(Input::Z, &z);
    in.set(Input::T, 0.0);
    batch->evaluate(in, 1, &out);
    EXPECT_DOUBLE_EQ(out, 3.0);
}

TEST(Compiler, ExternalParametersFromTheScene) {
    CompileOptions o;
    o.parameters.push_back({"wR", 0.3, false, 0, 0});
    CompileResult r = compile("wR * 2", o);
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].message;
    ScalarEvaluator e(*r.tape);
    EXPECT_DOUBLE_EQ(e.evaluate({}), 0.6);
}

TEST(Compiler, MultipleOutputs) {
    CompileOptions o;
    o.kind = DefinitionKind::Colour;
    CompileResult r = compile("r = x; g = 1 - x; b = 0.5;", o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.tape->outputs.size(), 3u);
    EXPECT_EQ(r.tape->outputs[1].name, "g");
    ScalarEvaluator e(*r.tape);
    double out[3];
    e.evaluateAll(pointXYZ(0.25, 0, 0), out);
    EXPECT_EQ(out[0], 0.25);
    EXPECT_EQ(out[1], 0.75);
    EXPECT_EQ(out[2], 0.5);
    // a colour definition may instead be one value for a colour map
    CompileResult one = compile("sqrt(x^2 + y^2)", o);
    ASSERT_TRUE(one.ok());
    EXPECT_EQ(one.tape->outputs.size(), 1u);
}

} // namespace
} // namespace fl::formula
