// The checker's messages: located, understandable, with suggestions.
#include "test_helpers.h"

#include <gtest/gtest.h>

namespace fl::formula {
namespace {

using testing::firstError;

TEST(Checker, UnknownFunctionSuggestsTheNearestName) {
    Diagnostic d = firstError("sine(x) + 1");
    EXPECT_EQ(d.message, "unknown function 'sine'");
    EXPECT_EQ(d.suggestion, "did you mean 'sin'?");
    EXPECT_EQ(d.range.begin.column, 1);
    EXPECT_EQ(d.range.end.column, 5);
    EXPECT_EQ(firstError("sqr(x)").suggestion, "did you mean 'sqrt'?");
    EXPECT_EQ(firstError("spehre(1)").suggestion, "did you mean 'sphere'?");
}

TEST(Checker, UnknownNameSuggestsVariablesAndInputs) {
    Diagnostic d = firstError("radius = 2; return radus * x;");
    EXPECT_EQ(d.message, "unknown name 'radus'");
    EXPECT_EQ(d.suggestion, "did you mean 'radius'?");
    EXPECT_EQ(d.range.begin.column, 20);
    EXPECT_EQ(firstError("p1 + 1").suggestion, "did you mean 'pi'?");
    EXPECT_EQ(firstError("banana + 1").suggestion.find("did you mean"), std::string::npos);
}

TEST(Checker, WrongArityNamesTheSignature) {
    Diagnostic d = firstError("sin(x, y)");
    EXPECT_EQ(d.message, "'sin' takes 1 argument but was given 2");
    EXPECT_EQ(d.suggestion, "use sin(a)");
    d = firstError("min(x)");
    EXPECT_NE(d.message.find("at least 2"), std::string::npos);
    d = firstError("function f(a, b) { return a + b; } return f(1);");
    EXPECT_NE(d.message.find("'f' takes 2 arguments"), std::string::npos);
}

TEST(Checker, OutputsAreCheckedAgainstTheKindOfDefinition) {
    Diagnostic d = firstError("x = 1; return x;", DefinitionKind::Implicit);
    EXPECT_NE(d.message.find("input coordinate"), std::string::npos);
    d = firstError("x = cos(u); y = sin(u);", DefinitionKind::Parametric);
    EXPECT_NE(d.message.find("missing: z"), std::string::npos);
    d = firstError("x = cos(u); y = x + z; z = v;", DefinitionKind::Parametric);
    EXPECT_NE(d.message.find("'z' is an output"), std::string::npos);
    d = firstError("x = cos(u); y = sin(v); z = x * y;", DefinitionKind::Parametric);
    EXPECT_TRUE(d.message.empty()) << d.message;
    d = firstError("x + u", DefinitionKind::Implicit);
    EXPECT_NE(d.message.find("'u' is not available"), std::string::npos);
    d = firstError("fx = 0; fy = -1;", DefinitionKind::Force);
    EXPECT_NE(d.message.find("missing: fz"), std::string::npos);
    d = firstError("return 1;", DefinitionKind::Parametric);
    EXPECT_NE(d.message.find("'return'"), std::string::npos);
    d = firstError("sphere(1)", DefinitionKind::Parametric);
    EXPECT_NE(d.message.find("reads x, y, z"), std::string::npos);
}

TEST(Checker, ConditionalAssignmentsAreTracked) {
    Diagnostic d = firstError("if (x > 0) { a = 1; } return a;");
    EXPECT_NE(d.message.find("only on some paths"), std::string::npos);
    EXPECT_TRUE(firstError("if (x > 0) { a = 1; } else { a = 2; } return a;").message.empty());
    d = firstError("if (u > 0) { x = 1; } y = 0; z = 0;", DefinitionKind::Parametric);
    EXPECT_NE(d.message.find("only on some paths"), std::string::npos);
    d = firstError("function f(a) { if (a > 0) { return 1; } } return f(x);");
    EXPECT_NE(d.message.find("does not return a value on every path"), std::string::npos);
}

TEST(Checker, RecursionAndNonConstantLoopsAreRefused) {
    Diagnostic d = firstError("function f(a) { return f(a - 1); } return f(x);");
    EXPECT_NE(d.message.find("recursion"), std::string::npos);
    d = firstError("s = 0; for (i = 0; i < x; i++) { s += i; } return s;");
    EXPECT_NE(d.message.find("known when the formula is compiled"), std::string::npos);
}

TEST(Checker, ReservedNamesAndParameters) {
    EXPECT_NE(firstError("pi = 3; return pi;").message.find("built-in constant"),
              std::string::npos);
    EXPECT_NE(firstError("sin = 3; return sin;").message.find("built-in function"),
              std::string::npos);
    EXPECT_NE(firstError("param R = 1; R = 2; return R;").message.find("is a parameter"),
              std::string::npos);
    EXPECT_NE(firstError("param R = x; return R;").message.find("constant"), std::string::npos);
    EXPECT_NE(firstError("param R = 1 in [2, 0]; return R;").message.find("empty"),
              std::string::npos);
    EXPECT_NE(firstError("sin + 1").message.find("is a function"), std::string::npos);
    EXPECT_NE(firstError("x(2)").message.find("not a function"), std::string::npos);
}

TEST(Checker, RFunctionContinuityMustBeConstant) {
    Diagnostic d = firstError("rintersect(x, y, z)");
    EXPECT_NE(d.message.find("must be a constant"), std::string::npos);
    EXPECT_EQ(d.range.begin.column, 18);
}

TEST(Checker, FormatsACaretUnderTheColumn) {
    CompileResult r = compile("1 + sine(x)");
    ASSERT_FALSE(r.ok());
    std::string text = formatDiagnostic(r.diagnostics[0], "1 + sine(x)");
    EXPECT_EQ(text, "1:5: error: unknown function 'sine' (did you mean 'sin'?)\n"
                    "  1 + sine(x)\n"
                    "      ^~~~\n");
}

TEST(Checker, ReturnsInsideLoopsAndBranches) {
    using testing::eval;
    const char* loopReturn = "for (i = 0; i < 4; i++) { if (x < i) return i; } return 10;";
    EXPECT_EQ(eval(loopReturn, 1.5), 2.0);
    EXPECT_EQ(eval(loopReturn, 7), 10.0);
    EXPECT_EQ(eval("if (x > 0) return 1; s = 0; for (i = 0; i < 4; i++) { s += i; } return s;", -1),
              6.0);
    EXPECT_EQ(eval("if (x > 0) { return 1; } else { a = 2; } return a;", -1), 2.0);
    EXPECT_EQ(eval("if (x > 0) { return 1; } else { a = 2; } return a;", 1), 1.0);
}

TEST(Checker, CodeThatIsNeverCompiledIsStillChecked) {
    Diagnostic d = firstError("function g(a) { return sine(a) + q; } return x;");
    EXPECT_EQ(d.message, "unknown function 'sine'");
    d = firstError("if (0) { return sine(x); } return x;");
    EXPECT_EQ(d.message, "unknown function 'sine'");
    CompileResult r = compile("function g(a) { return a; } return x;");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("never called"), std::string::npos);
}

TEST(Checker, DeadBranchesInUnrolledLoopsSeeLaterAssignments) {
    using testing::eval;
    EXPECT_EQ(
        eval("acc = 0; for (i = 0; i < 3; i++) { if (i > 0) { acc += prev; } prev = x * i; } acc",
             2),
        0.0 + 2.0 * 0 + 2.0 * 1);
    CompileResult r = compile("function f(n) { if (n > 5) { return zz; } return n; } f(1) + f(2)");
    ASSERT_FALSE(r.ok());
    int reports = 0;
    for (const Diagnostic& d : r.diagnostics)
        reports += d.message == "unknown name 'zz'";
    EXPECT_EQ(reports, 1);
}

TEST(Checker, ColourDefinitionsDoNotMixReturnAndOutputs) {
    Diagnostic d = firstError("r = 0; g = 0; b = 0; if (x > 0) return 0.5; r = 1; g = 1; b = 1;",
                              DefinitionKind::Colour);
    EXPECT_NE(d.message.find("not both"), std::string::npos);
    d = firstError("if (x > 0) { r = 1; g = 1; b = 1; } else { return 0.2; }",
                   DefinitionKind::Colour);
    EXPECT_NE(d.message.find("not both"), std::string::npos);
    EXPECT_TRUE(
        firstError("if (x > 0) return 0.5; return 0.1;", DefinitionKind::Colour).message.empty());
}

TEST(Checker, AlwaysUndefinedConstantsWhereNumbersAreNeeded) {
    CompileResult p = compile("param k = sqrt(-1); x + k");
    ASSERT_TRUE(p.ok());
    ASSERT_FALSE(p.diagnostics.empty());
    EXPECT_EQ(p.diagnostics[0].severity, Severity::Warning);
    CompileResult loop = compile("s = 1; for (i = 0; i < log(-1); i++) { s += 1; } x + s");
    ASSERT_TRUE(loop.ok());
    EXPECT_EQ(testing::eval("s = 1; for (i = 0; i < log(-1); i++) { s += 1; } x + s", 1), 2.0);
    EXPECT_FALSE(loop.diagnostics.empty());
}

TEST(Checker, LoopStepMustChangeTheLoopVariable) {
    Diagnostic d = firstError("j = 0; for (i = 0; i < 3; j++) { } return x;");
    EXPECT_NE(d.message.find("changes 'j', not the loop variable 'i'"), std::string::npos);
}

TEST(Checker, MissingSemicolonAtTheEndOfALine) {
    Diagnostic d = firstError("a = 1\nb = 2;\nreturn a + b;");
    EXPECT_EQ(d.message, "expected ';' at the end of line 1");
    EXPECT_EQ(d.range.begin.line, 1);
    EXPECT_EQ(d.range.begin.column, 6);
}

TEST(Checker, ParametersCannotSetTheContinuity) {
    Diagnostic d = firstError("param k = 1; return rintersect(x, y, k);");
    EXPECT_NE(d.suggestion.find("use a number"), std::string::npos);
}

TEST(Checker, ErrorsStopAfterTheLimit) {
    std::string src;
    for (int i = 0; i < 500; ++i)
        src += "a" + std::to_string(i) + " = zz" + std::to_string(i) + ";\n";
    src += "return x;";
    CompileResult r = compile(src);
    ASSERT_FALSE(r.ok());
    EXPECT_LE(r.diagnostics.size(), 51u);
    EXPECT_EQ(r.diagnostics.back().message, "too many errors; stopping here");
}

} // namespace
} // namespace fl::formula
