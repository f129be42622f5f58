// Names in a class (issue 26 §2): what others see must read as what it is.
#include "classroom/member_name.h"

#include <gtest/gtest.h>

namespace fl::classroom {
namespace {

bool allowed(const std::string& name) {
    return !memberNameProblem(name, 40).has_value();
}

TEST(MemberName, OrdinaryNamesInAnyScriptPass) {
    for (const char* name :
         {"Ada", "Ben Okafor", "José", "Zoë-Jane", "李雷", "Дарья", "محمد", "דנה", "Ana (2)",
          "<img src=/dev/zero>", "O'Brien & Sons", "Niña 🙂"})
        EXPECT_TRUE(allowed(name)) << name;
}

TEST(MemberName, ControlAndDirectionCharactersAreRefused) {
    for (const char* name :
         {"Ada\nBen", "Ada\tB", "A\x7f", "Ada\u0085", "Ada\u2028x", "\u202Eadmin", "Ada\u202Dx",
          "Ada\u2066x\u2069", "Ada\u200F", "Ada\u061C"})
        EXPECT_FALSE(allowed(name)) << name;
}

TEST(MemberName, InvisibleNamesAreRefused) {
    for (const char* name : {"", " ", "\u200B", "\u200B\u200C\u200D", "\u00A0", "\u3000", "\u0301",
                             "\u3164", "\u2060"})
        EXPECT_FALSE(allowed(name)) << name;
}

TEST(MemberName, SpacesAtEitherEndAreRefused) {
    EXPECT_FALSE(allowed(" Ada"));
    EXPECT_FALSE(allowed("Ada "));
    EXPECT_FALSE(allowed("Ada\u00A0"));
    EXPECT_TRUE(allowed("Ada Lovelace"));
}

TEST(MemberName, RolesAndAliasesAreNotNames) {
    for (const char* name : {"Instructor", "INSTRUCTOR", "student", "Observer", "server",
                             "Learner 3", "learner  12", "Everyone"})
        EXPECT_FALSE(allowed(name)) << name;
    EXPECT_TRUE(allowed("Instructor Ada"));
    EXPECT_TRUE(allowed("Learner Ben"));
}

TEST(MemberName, LengthCountsCharactersNotBytesOrUtf16Units) {
    std::string emoji; // 40 characters, 80 UTF-16 units, 160 bytes
    for (int i = 0; i < 40; ++i)
        emoji += "🙂";
    EXPECT_EQ(characterCount(emoji), 40u);
    EXPECT_TRUE(allowed(emoji));
    EXPECT_FALSE(allowed(emoji + "x"));
    EXPECT_TRUE(allowed(std::string(40, 'a')));
    EXPECT_FALSE(allowed(std::string(41, 'a')));
}

TEST(MemberName, KeysAreNormalisedAndCaseFolded) {
    EXPECT_EQ(memberNameKey("Ada"), memberNameKey("ADA"));
    EXPECT_EQ(memberNameKey("Jos\u00e9"), memberNameKey("Jose\u0301")); // é, two ways
    EXPECT_NE(memberNameKey("Ada"), memberNameKey("Ben"));
}

} // namespace
} // namespace fl::classroom
