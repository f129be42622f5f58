// Assignments: every manifest that comes with FunctionLab loads, its
// reference solutions score full marks and its starters load; a broken
// manifest says what is wrong at manifest.json:LINE:COL.
#include "courseware/catalogue.h"
#include "grading/checker.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace fl;
using namespace fl::courseware;

namespace {

const std::filesystem::path kAssignments =
    std::filesystem::path(FUNCTIONLAB_COURSEWARE_DIR) / "assignments";

AssignmentLoad parse(const std::string& text) {
    return parseAssignment(text, kAssignments / "implicit-fantasies");
}

std::string firstProblem(const AssignmentLoad& load) {
    if (load.diagnostics.empty()) return "(none)";
    const auto& d = load.diagnostics.front();
    return std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + " " + d.message;
}

const char* kGood = R"({
  "schema": "functionlab-assignment/1",
  "id": "implicit-fantasies",
  "title": "T",
  "instructions": "instructions.md",
  "starters": ["starter.x3d"],
  "requirements": [
    {"id": "a", "kind": "explicit-solid", "points": 5, "description": "d"}
  ]
})";

} // namespace

// Tests outside this repository rely on these ids.
TEST(Assignments, ImplicitFantasiesHasTheRequiredIds) {
    const AssignmentLoad load = findAssignment("implicit-fantasies");
    ASSERT_TRUE(load.assignment) << firstProblem(load);
    std::vector<std::string> ids;
    for (const auto& r : load.assignment->requirements)
        ids.push_back(r.id);
    EXPECT_EQ(ids,
              (std::vector<std::string>{"implicit", "explicit", "parametric", "set-operations",
                                        "morphing", "animation", "level-of-detail", "colour"}));
    EXPECT_EQ(load.assignment->title,
              "Implicit Fantasies and Parametric Metamorphoses in Cyberworlds");
    EXPECT_EQ(load.assignment->automaticPoints(), 100);
    EXPECT_EQ(load.assignment->manualPoints(), 20);
}

TEST(Assignments, EveryAssignmentLoadsItsSolutionsScoreFullMarksItsStartersRead) {
    const auto all = listAssignments(kAssignments);
    ASSERT_FALSE(all.empty());
    for (const AssignmentLoad& load : all) {
        ASSERT_TRUE(load.assignment) << firstProblem(load);
        EXPECT_TRUE(load.diagnostics.empty()) << firstProblem(load);
        const Assignment& a = *load.assignment;
        ASSERT_FALSE(a.solutions.empty()) << a.id;
        for (const auto& solution : a.solutions) {
            const grading::CheckReport r = grading::checkSubmission(solution, a.requirements);
            EXPECT_TRUE(r.gradable) << solution;
            EXPECT_EQ(r.score, r.maxScore) << solution;
            for (const auto& q : r.requirements)
                EXPECT_TRUE(q.met) << a.id << " " << q.id << ": " << q.evidence;
        }
        for (const auto& starter : a.starters)
            EXPECT_TRUE(scene::readSceneFile(starter).ok()) << starter;
    }
}

TEST(Assignments, TheCatalogueFindsTheExamplesWithTheirOwnTitles) {
    const auto examples =
        listExamples(std::filesystem::path(FUNCTIONLAB_COURSEWARE_DIR) / "examples");
    ASSERT_GE(examples.size(), 8u);
    bool melon = false;
    for (const auto& e : examples) {
        EXPECT_NE(e.title, e.path.filename().string()) << "a title from the scene: " << e.path;
        melon = melon || e.path.filename() == "watermelon.x3d";
    }
    EXPECT_TRUE(melon);
}

TEST(Manifest, ProblemsAreLocated) {
    ASSERT_TRUE(parse(kGood).assignment) << firstProblem(parse(kGood));
    // A syntax error: where Qt stopped reading.
    std::string bad = kGood;
    bad.replace(bad.find("\"T\","), 4, "\"T\" ");
    AssignmentLoad load = parse(bad);
    EXPECT_FALSE(load.assignment);
    EXPECT_EQ(firstProblem(load).substr(0, 2), "5:") << firstProblem(load);
    // An unknown kind: at its value, with the list of kinds.
    bad = kGood;
    bad.replace(bad.find("explicit-solid"), 14, "explicit-solids");
    load = parse(bad);
    EXPECT_FALSE(load.assignment);
    EXPECT_EQ(firstProblem(load), "8:25 requirements/0/kind: unknown kind 'explicit-solids'");
    EXPECT_NE(load.diagnostics.front().suggestion.find("explicit-solid"), std::string::npos);
    // A missing key: at the object that lacks it.
    bad = kGood;
    bad.replace(bad.find(", \"points\": 5"), 13, "");
    load = parse(bad);
    EXPECT_EQ(firstProblem(load), "8:5 requirements/0: \"points\" is missing");
    // Points that are not a number; a negative one.
    bad = kGood;
    bad.replace(bad.find("\"points\": 5"), 11, "\"points\": -5");
    EXPECT_EQ(firstProblem(parse(bad)),
              "8:53 requirements/0/points: must be a number from 0 to 1e+06");
    // Another schema.
    bad = kGood;
    bad.replace(bad.find("assignment/1"), 12, "assignment/2");
    EXPECT_EQ(firstProblem(parse(bad)).substr(0, 13), "2:13 schema: ") << firstProblem(parse(bad));
    // A file outside the folder; a file that is not there.
    bad = kGood;
    bad.replace(bad.find("starter.x3d"), 11, "../../../etc/passwd");
    EXPECT_EQ(firstProblem(parse(bad)).substr(0, 19), "6:16 starters/0: '.")
        << firstProblem(parse(bad));
    bad = kGood;
    bad.replace(bad.find("starter.x3d"), 11, "nothere.x3d");
    EXPECT_NE(firstProblem(parse(bad)).find("is not a file"), std::string::npos);
    // Not an object at all; not JSON at all; empty.
    EXPECT_FALSE(parse("[1, 2]").assignment);
    EXPECT_FALSE(parse("").assignment);
    EXPECT_FALSE(parse("\xff\xfe{").assignment);
}

// "varies": a colour requirement can ask for a colour that varies over the
// shape itself (parametric-colour), not only in time.
TEST(Manifest, AColourRequirementSaysHowItMustVary) {
    const auto load = [](const std::string& extra) {
        std::string text = R"({
  "schema": "functionlab-assignment/1", "id": "implicit-fantasies", "title": "T",
  "instructions": "instructions.md", "starters": ["starter.x3d"],
  "requirements": [
    {"id": "c", "kind": "function-colour", "points": 5, "description": "d")" +
                           extra + R"(}
  ]
})";
        return parse(text);
    };
    const AssignmentLoad plain = load("");
    ASSERT_TRUE(plain.assignment) << firstProblem(plain);
    EXPECT_FALSE(plain.assignment->requirements.at(0).variesOverShape);
    const AssignmentLoad shape = load(R"(, "varies": "over-shape")");
    ASSERT_TRUE(shape.assignment) << firstProblem(shape);
    EXPECT_TRUE(shape.assignment->requirements.at(0).variesOverShape);
    const AssignmentLoad wrong = load(R"(, "varies": "sometimes")");
    ASSERT_FALSE(wrong.diagnostics.empty());
    EXPECT_EQ(wrong.diagnostics.front().pos.line, 5) << firstProblem(wrong);
    EXPECT_NE(wrong.diagnostics.front().suggestion.find("over-shape"), std::string::npos);
    // The course's parametric-colour lab asks for it.
    const AssignmentLoad lab = findAssignment("parametric-colour");
    ASSERT_TRUE(lab.assignment);
    bool found = false;
    for (const auto& r : lab.assignment->requirements)
        found = found || (r.kind == grading::RequirementKind::FunctionColour && r.variesOverShape);
    EXPECT_TRUE(found);
}

TEST(Manifest, UnknownKeysAreWarnedAboutNotFatal) {
    std::string text = kGood;
    text.insert(text.find("\"title\""), "\"colour_scheme\": 1,\n  ");
    const AssignmentLoad load = parse(text);
    EXPECT_TRUE(load.assignment);
    ASSERT_EQ(load.diagnostics.size(), 1u);
    EXPECT_EQ(load.diagnostics.front().severity, scene::Severity::Warning);
}

TEST(Manifest, LatePolicy) {
    LatePolicy p{10, 24, 50};
    EXPECT_EQ(p.factor(0), 1);
    EXPECT_EQ(p.factor(-5), 1);
    EXPECT_DOUBLE_EQ(p.factor(0.5), 0.9) << "a started day counts";
    EXPECT_DOUBLE_EQ(p.factor(24), 0.9);
    EXPECT_DOUBLE_EQ(p.factor(24.01), 0.8);
    EXPECT_DOUBLE_EQ(p.factor(24 * 30), 0.5) << "the floor";
    EXPECT_EQ(LatePolicy{}.factor(100), 1) << "no policy: no deduction";
}

TEST(Manifest, AnIdOrAFolderThatIsNotThereSaysWhichAreThere) {
    const AssignmentLoad load = findAssignment("no-such-lab");
    EXPECT_FALSE(load.assignment);
    ASSERT_FALSE(load.diagnostics.empty());
    EXPECT_NE(load.diagnostics.front().suggestion.find("implicit-fantasies"), std::string::npos);
    EXPECT_FALSE(findAssignment("../../etc").assignment);
}

// Five labs make a course, each with its own requirements.
// In the course's order (issue 29 §7): the labs by their numbers, the final last.
TEST(Assignments, ACourseHasSixLabsInTheirOrder) {
    std::vector<std::string> ids;
    for (const AssignmentLoad& a : listAssignments(kAssignments))
        if (a.assignment) ids.push_back(a.assignment->id);
    EXPECT_EQ(ids,
              (std::vector<std::string>{"implicit-shapes", "parametric-colour", "time",
                                        "tangible-physics", "pde-surfaces", "implicit-fantasies"}));
}

// Each lab's starter scene is not yet a full-marks solution: there is work to do.
TEST(Assignments, StartersLeaveWorkToDo) {
    for (const AssignmentLoad& load : listAssignments(kAssignments)) {
        ASSERT_TRUE(load.assignment);
        for (const auto& starter : load.assignment->starters) {
            const grading::CheckReport r =
                grading::checkSubmission(starter, load.assignment->requirements);
            EXPECT_TRUE(r.gradable) << starter;
            EXPECT_LT(r.score, r.maxScore) << starter;
        }
    }
}
