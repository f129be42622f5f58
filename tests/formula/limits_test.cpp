// Every limit gives a clear, located error instead of exhausting the machine.
#include "test_helpers.h"

#include <gtest/gtest.h>

namespace fl::formula {
namespace {

TEST(Limits, SourceSize) {
    CompileOptions o;
    o.limits.maxSourceBytes = 100;
    CompileResult r = compile(std::string(200, '1'), o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("too long"), std::string::npos);
}

TEST(Limits, NestingDepthOfParentheses) {
    std::string src = std::string(5000, '(') + "x" + std::string(5000, ')');
    CompileResult r = compile(src);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("nested too deeply"), std::string::npos);
}

TEST(Limits, NestingDepthOfOperatorChains) {
    std::string src = "x";
    for (int i = 0; i < 20000; ++i)
        src += "+x";
    CompileResult r = compile(src);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("nested too deeply"), std::string::npos);
    std::string unary(20000, '-');
    CompileResult u = compile(unary + "x");
    ASSERT_FALSE(u.ok());
    EXPECT_NE(u.diagnostics[0].message.find("nested too deeply"), std::string::npos)
        << u.diagnostics[0].message;
}

TEST(Limits, UnrolledLoopSize) {
    CompileResult r = compile("s = 0; for (i = 0; i < 1e9; i++) { s += x; } return s;");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("iterations"), std::string::npos);
    EXPECT_EQ(r.diagnostics[0].range.begin.line, 1);
    EXPECT_EQ(r.diagnostics[0].range.begin.column, 8);
}

TEST(Limits, TapeSize) {
    CompileOptions o;
    o.limits.maxTapeSize = 500;
    CompileResult r = compile("s = x; for (i = 0; i < 2000; i++) { s = sin(s + i); } return s;", o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("too large"), std::string::npos);
}

TEST(Limits, NestedLoopsCountTogether) {
    CompileResult r = compile("s = 0; for (i = 0; i < 100; i++) { for (j = 0; j < 100; j++) { s += "
                              "i * j * x; } } return s;");
    ASSERT_FALSE(r.ok());
    // 100 x 100 passes the 4096 iterations the loops may unroll to together
    EXPECT_NE(r.diagnostics[0].message.find("iterations"), std::string::npos)
        << r.diagnostics[0].message;
}

TEST(Limits, ExpansionWorkThroughRepeatedInlining) {
    // every level doubles the work while the tape stays tiny (shared subexpressions)
    std::string src = "function f0(a) { return sin(a); } ";
    for (int i = 1; i <= 40; ++i)
        src += "function f" + std::to_string(i) + "(a) { return f" + std::to_string(i - 1) +
               "(a) + f" + std::to_string(i - 1) + "(a); } ";
    src += "return f40(x);";
    CompileResult r = compile(src);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("too much work"), std::string::npos);
}

TEST(Limits, DefaultsAdmitRealFormulas) {
    std::string src = "0";
    for (int i = 0; i < 150; ++i)
        src += " | sphere(" + std::to_string(i) + ", 0, 0, 0.5)";
    EXPECT_TRUE(compile(src).ok());
}

} // namespace
} // namespace fl::formula
