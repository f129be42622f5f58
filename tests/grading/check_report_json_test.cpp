// The `grade check` document has one owner (grading/check_report_json):
// what it writes reads back as it was (a property over random reports full
// of hostile text), and what is not a report is refused with the field that
// is wrong, never read as zeros.
#include "grading/check_report_json.h"

#include <gtest/gtest.h>

#include <random>

using namespace fl::grading;

namespace {

std::string randomText(std::mt19937& random) {
    // Quotes, escapes, control characters, markup, a bidi override,
    // non-ASCII letters: all valid UTF-8 (text from files is).
    static const std::vector<std::string> pieces = {
        "a",    "Z",   " ",     "\"", "\\",           "\n", "\t",   "\x01",
        "\x1f", "<b>", "&amp;", "é",  "\xE2\x80\xAE", "∪",  "🙂", "/",
        "{",    "]",   ":",     ","};
    std::string out;
    for (unsigned n = random() % 8; n > 0; --n)
        out += pieces[random() % pieces.size()];
    return out;
}

CheckReportDocument randomDocument(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0, 1);
    CheckReportDocument d;
    d.assignment = randomText(random);
    d.checkerVersion = randomText(random);
    d.manualMax = std::floor(unit(random) * 40);
    CheckReport& r = d.report;
    r.gradable = random() % 2;
    r.budgetExceeded = random() % 2;
    for (unsigned i = random() % 5; i > 0; --i) {
        RequirementResult q;
        q.id = randomText(random);
        q.met = random() % 2;
        q.maxPoints = unit(random) * 30;
        q.points = q.met ? q.maxPoints : unit(random) * q.maxPoints;
        q.evidence = randomText(random);
        for (unsigned k = random() % 3; k > 0; --k)
            q.locations.push_back(
                {randomText(random), int(random() % 100000), int(random() % 500)});
        r.score += q.points;
        r.maxScore += q.maxPoints;
        r.requirements.push_back(std::move(q));
    }
    for (unsigned i = random() % 3; i > 0; --i) {
        fl::scene::SceneDiagnostic diagnostic;
        diagnostic.severity = fl::formula::Severity(random() % 3);
        diagnostic.file = randomText(random);
        diagnostic.pos = {int(random() % 1000), int(random() % 80)};
        diagnostic.message = randomText(random);
        diagnostic.suggestion = randomText(random);
        r.diagnostics.push_back(std::move(diagnostic));
    }
    return d;
}

} // namespace

TEST(CheckReportJson, WriteThenReadIsTheIdentity) {
    std::mt19937 random(27);
    for (int round = 0; round < 500; ++round) {
        const CheckReportDocument d = randomDocument(random);
        const std::string json = checkReportJson(d);
        std::string error;
        const auto back = readCheckReportJson(json, &error);
        ASSERT_TRUE(back) << error << "\n" << json;
        EXPECT_EQ(back->assignment, d.assignment);
        EXPECT_EQ(back->checkerVersion, d.checkerVersion);
        EXPECT_EQ(back->manualMax, d.manualMax);
        const CheckReport &a = d.report, &b = back->report;
        EXPECT_EQ(b.gradable, a.gradable);
        EXPECT_EQ(b.budgetExceeded, a.budgetExceeded);
        EXPECT_EQ(b.score, a.score); // %.17g: doubles come back exactly
        EXPECT_EQ(b.maxScore, a.maxScore);
        ASSERT_EQ(b.requirements.size(), a.requirements.size());
        for (std::size_t i = 0; i < a.requirements.size(); ++i) {
            EXPECT_EQ(b.requirements[i].id, a.requirements[i].id);
            EXPECT_EQ(b.requirements[i].met, a.requirements[i].met);
            EXPECT_EQ(b.requirements[i].points, a.requirements[i].points);
            EXPECT_EQ(b.requirements[i].maxPoints, a.requirements[i].maxPoints);
            EXPECT_EQ(b.requirements[i].evidence, a.requirements[i].evidence);
            EXPECT_EQ(b.requirements[i].locations, a.requirements[i].locations);
        }
        ASSERT_EQ(b.diagnostics.size(), a.diagnostics.size());
        for (std::size_t i = 0; i < a.diagnostics.size(); ++i) {
            EXPECT_EQ(b.diagnostics[i].severity, a.diagnostics[i].severity);
            EXPECT_EQ(b.diagnostics[i].file, a.diagnostics[i].file);
            EXPECT_EQ(b.diagnostics[i].pos.line, a.diagnostics[i].pos.line);
            EXPECT_EQ(b.diagnostics[i].pos.column, a.diagnostics[i].pos.column);
            EXPECT_EQ(b.diagnostics[i].message, a.diagnostics[i].message);
            EXPECT_EQ(b.diagnostics[i].suggestion, a.diagnostics[i].suggestion);
        }
    }
}

TEST(CheckReportJson, WhatIsNotAReportIsRefusedWithTheField) {
    auto why = [](const std::string& json) {
        std::string error;
        EXPECT_FALSE(readCheckReportJson(json, &error)) << json;
        return error;
    };
    EXPECT_NE(why("").find("not JSON"), std::string::npos);
    EXPECT_NE(why("[1]").find("not a JSON object"), std::string::npos);
    EXPECT_NE(why(R"({"gradable": 3, "requirements": []})").find("gradable"), std::string::npos);
    // A number past a double's range: refused (QJson stops at it).
    EXPECT_FALSE(
        why(R"({"gradable": true, "score": 1e999, "max_score": 1, "requirements": []})").empty());
    EXPECT_NE(
        why(R"({"gradable": true, "score": -1, "max_score": 1, "requirements": []})").find("score"),
        std::string::npos);
    const std::string more =
        R"({"gradable": true, "score": 1, "max_score": 1, "requirements": [{"id": "r",
            "met": true, "points": 5, "max_points": 1}]})";
    EXPECT_NE(why(more).find("requirements[0].points"), std::string::npos);
    const std::string line =
        R"({"gradable": true, "score": 1, "max_score": 1, "requirements": [{"id": "r",
            "met": true, "points": 1, "max_points": 1,
            "locations": [{"file": "a", "line": 3000000000, "column": 1}]}]})";
    EXPECT_NE(why(line).find("requirements[0].locations[0].line"), std::string::npos);
    const std::string severity =
        R"({"gradable": false, "score": 0, "max_score": 0, "requirements": [],
            "diagnostics": [{"file": "a", "line": 1, "column": 1, "severity": "fatal",
                             "message": "m"}]})";
    EXPECT_NE(why(severity).find("severity"), std::string::npos);
    EXPECT_NE(why(std::string(kMaxCheckReportBytes + 1, ' ')).find("16 MiB"), std::string::npos);
}

TEST(CheckReportJson, LocationsKeepTheGradebooksStoredForm) {
    // The gradebook's log verifies its tables against a rebuild: the stored
    // text of locations must never change form.
    EXPECT_EQ(locationsJson({{"a.x3d", 2, 7}}), R"([{"column":7,"file":"a.x3d","line":2}])");
    EXPECT_EQ(locationsOf(R"([{"file":"a.x3d","line":2,"column":7},{"file":3}])"),
              (std::vector<Location>{{"a.x3d", 2, 7}}));
}
