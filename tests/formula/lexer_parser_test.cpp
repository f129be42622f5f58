#include "formula/lexer.h"
#include "formula/parser.h"
#include "test_helpers.h"

#include <gtest/gtest.h>

namespace fl::formula {
namespace {

TEST(Lexer, ExactLineAndColumnRanges) {
    std::vector<Diagnostic> d;
    auto toks = tokenize("a +\n  sin(2.5e-1)", d);
    ASSERT_TRUE(d.empty());
    ASSERT_EQ(toks.size(), 7u);
    EXPECT_EQ(toks[0].range.begin.line, 1);
    EXPECT_EQ(toks[0].range.begin.column, 1);
    EXPECT_EQ(toks[2].text, "sin");
    EXPECT_EQ(toks[2].range.begin.line, 2);
    EXPECT_EQ(toks[2].range.begin.column, 3);
    EXPECT_EQ(toks[2].range.end.column, 6);
    EXPECT_EQ(toks[4].kind, TokenKind::Number);
    EXPECT_DOUBLE_EQ(toks[4].number, 0.25);
    EXPECT_EQ(toks.back().kind, TokenKind::End);
}

TEST(Lexer, CommentsAndBadCharacters) {
    std::vector<Diagnostic> d;
    auto toks = tokenize("x // note\n + /* block */ y # z", d);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].range.begin.line, 2);
    EXPECT_EQ(d[0].range.begin.column, 18);
    EXPECT_NE(d[0].suggestion.find("//"), std::string::npos);
    d.clear();
    tokenize("x /* never closed", d);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NE(d[0].message.find("never closed"), std::string::npos);
    d.clear();
    tokenize("x \xc3\xa9 y", d); // one UTF-8 character, one diagnostic
    EXPECT_EQ(d.size(), 1u);
}

TEST(Parser, PrecedenceAndAssociativity) {
    using testing::eval;
    EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
    EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
    EXPECT_EQ(eval("8 / 4 / 2"), 1.0);
    EXPECT_EQ(eval("2 - 3 - 4"), -5.0);
    EXPECT_EQ(eval("-2^2"), -4.0);
    EXPECT_EQ(eval("2^-1"), 0.5);
    EXPECT_EQ(eval("1 < 2 && 3 > 2"), 1.0);
    EXPECT_EQ(eval("0 || 0 ? 5 : 6"), 6.0);
    EXPECT_EQ(eval("1--1"), 2.0); // minus minus, not a decrement
    EXPECT_EQ(eval("x & y | z", 1, 2, 3), 3.0);
    EXPECT_EQ(eval("x | y & z", 5, 2, 3), 5.0); // & binds tighter than |
}

TEST(Parser, ReportsEveryRecoverableErrorWithItsPlace) {
    std::vector<Diagnostic> d;
    parse("a = 1 +;\nb = (2;\nreturn a + b;", d);
    ASSERT_GE(d.size(), 2u);
    EXPECT_EQ(d[0].range.begin.line, 1);
    EXPECT_EQ(d[0].range.begin.column, 8);
    EXPECT_EQ(d[1].range.begin.line, 2);
}

TEST(Parser, MissingCloseParenPointsWhereToType) {
    Diagnostic d = testing::firstError("sin(x");
    EXPECT_EQ(d.range.begin.column, 6);
    EXPECT_NE(d.message.find("')'"), std::string::npos);
}

TEST(Parser, ImplicitMultiplicationIsExplained) {
    Diagnostic d = testing::firstError("2x + 1");
    EXPECT_NE(d.suggestion.find("2*x"), std::string::npos);
}

TEST(Parser, ScriptsParse) {
    std::vector<Diagnostic> d;
    Program p = parse(R"(
        param R = 1 in [0.5, 2];
        function sq(a) { return a * a; }
        s = 0;
        for (i = 0; i < 3; i++) { s += sq(i); }
        if (s > 4) { s = s - 1; } else s = 0;
        return s;
    )",
                      d);
    EXPECT_TRUE(d.empty()) << d[0].message;
    EXPECT_EQ(p.functions.size(), 1u);
    EXPECT_EQ(p.params.size(), 1u);
    EXPECT_FALSE(p.isExpression);
    EXPECT_EQ(testing::eval(R"(
        function sq(a) { return a * a; }
        s = 0;
        for (i = 0; i < 3; i++) { s += sq(i); }
        if (s > 4) { s = s - 1; } else s = 0;
        return s;)"),
              4.0);
}

} // namespace
} // namespace fl::formula
