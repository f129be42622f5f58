// The checker against submissions with known verdicts: the reference
// solution meets everything; dead, hidden, constant and broken variants do
// not, with reasons that name the place; verdicts are the same every time.
#include "grading/checker.h"

#include "pde/pde_file.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace fl;
using namespace fl::grading;

namespace {

const std::string kSolution = std::string(FUNCTIONLAB_COURSEWARE_DIR) +
                              "/assignments/implicit-fantasies/solution/fantasy.x3d";

std::vector<Requirement> fantasies() {
    using K = RequirementKind;
    return {{"implicit", K::ImplicitSurface, "", 10},
            {"explicit", K::ExplicitSolid, "", 10},
            {"parametric", K::Parametric, "", 10},
            {"set-operations", K::SetOperations, "", 20, 3, 2},
            {"morphing", K::Morphing, "", 15},
            {"animation", K::Animation, "", 15},
            {"level-of-detail", K::LevelOfDetail, "", 10},
            {"colour", K::FunctionColour, "", 10}};
}

const RequirementResult& result(const CheckReport& r, const std::string& id) {
    for (const auto& q : r.requirements)
        if (q.id == id) return q;
    throw std::runtime_error("no requirement " + id);
}

CheckReport checkText(const std::string& x3dv) {
    auto read = scene::readSceneBytes(
        "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n" + x3dv, "submission.x3dv");
    EXPECT_TRUE(read.ok());
    return checkScene(*read.scene, fantasies());
}

} // namespace

TEST(Checker, TheReferenceSolutionScoresFullMarks) {
    const CheckReport r = checkSubmission(kSolution, fantasies());
    ASSERT_TRUE(r.gradable);
    for (const auto& q : r.requirements) {
        EXPECT_TRUE(q.met) << q.id << ": " << q.evidence;
        EXPECT_FALSE(q.locations.empty()) << q.id;
    }
    EXPECT_EQ(r.score, r.maxScore);
    EXPECT_EQ(r.maxScore, 100);
    EXPECT_FALSE(r.budgetExceeded);
    const auto& ops = result(r, "set-operations");
    // & \ | in the carved solid, and the rounded cube's two min()s.
    EXPECT_NE(ops.evidence.find("5 set operations of 3 kinds"), std::string::npos) << ops.evidence;
    EXPECT_NE(ops.evidence.find("intersection `ball & slab` at line 28"), std::string::npos)
        << ops.evidence;
    EXPECT_EQ(ops.locations.size(), 5u);
    EXPECT_EQ(ops.locations.front().line, 28) << "the line the operators are written on";
}

TEST(Checker, VerdictsAreTheSameEveryTime) {
    const CheckReport a = checkSubmission(kSolution, fantasies());
    const CheckReport b = checkSubmission(kSolution, fantasies());
    ASSERT_EQ(a.requirements.size(), b.requirements.size());
    for (std::size_t i = 0; i < a.requirements.size(); ++i) {
        EXPECT_EQ(a.requirements[i].met, b.requirements[i].met);
        EXPECT_EQ(a.requirements[i].evidence, b.requirements[i].evidence);
        EXPECT_EQ(a.requirements[i].locations, b.requirements[i].locations);
    }
}

// The issue's example: an intersection with 5 - x*x in [-1,1]^3 does nothing.
TEST(Checker, ADeadOperationIsNotCountedAndSaysWhy) {
    const CheckReport r = checkText(R"x(FShape { geometry FGeometry { type "explicit"
  definition "((0.64 - x*x - y*y - z*z) & (5 - x*x)) | (0.3 - abs(y)) & (0.9 - abs(x))" } })x");
    const auto& ops = result(r, "set-operations");
    EXPECT_FALSE(ops.met);
    EXPECT_NE(ops.evidence.find("the intersection with `5 - x*x` changes nothing in the box "
                                "[-1,1]³: that operand is positive everywhere there"),
              std::string::npos)
        << ops.evidence;
    EXPECT_NE(ops.evidence.find("(line 5)"), std::string::npos) << ops.evidence;
}

TEST(Checker, HiddenShapesDoNotCount) {
    const CheckReport r = checkText(R"x(Switch { whichChoice -1 choice [
  FShape { geometry FGeometry { type "implicit" definition "0.5 - x*x - y*y - z*z" } } ] }
FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" }
  appearance FAppearance { material FMaterial { type "parametric"
    definition "r = 1; g = 1; b = 1;" transparency 1 } } })x");
    EXPECT_FALSE(result(r, "implicit").met) << result(r, "implicit").evidence;
    EXPECT_FALSE(result(r, "explicit").met) << "fully transparent, nothing tangible";
}

TEST(Checker, ConstantColourAndTimeFactorsDoNotCount) {
    const CheckReport r = checkText(R"x(FShape {
  geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z + 0*t" cycleInterval 2 loop TRUE }
  appearance FAppearance { material FMaterial { type "parametric"
    definition "r = 0.5 + 0*x; g = 0.2; b = 0.1 + 0*t;" } } })x");
    EXPECT_FALSE(result(r, "colour").met) << result(r, "colour").evidence;
    EXPECT_FALSE(result(r, "morphing").met) << result(r, "morphing").evidence;
    EXPECT_FALSE(result(r, "animation").met);
    EXPECT_TRUE(result(r, "explicit").met);
}

// Hard case: a morph whose two shapes are the same morphs nothing.
TEST(Checker, AMorphBetweenTwoEqualShapesIsNotMorphing) {
    const CheckReport r = checkText(R"x(FTransform { operation "morph"
  morphFactor "0.5 - 0.5*cos(2*pi*t)" cycleInterval 4 loop TRUE children [
  FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" } }
  FShape { geometry FGeometry { type "explicit" definition "0.5 - z*z - y*y - x*x" } } ] })x");
    EXPECT_FALSE(result(r, "morphing").met) << result(r, "morphing").evidence;
}

TEST(Checker, StandardAnimationCounts) {
    const CheckReport r = checkText(R"x(DEF T Transform { children Shape { geometry Box {} } }
DEF C TimeSensor { cycleInterval 4 loop TRUE }
DEF P PositionInterpolator { key [ 0 1 ] keyValue [ 0 0 0, 1 0 0 ] }
ROUTE C.fraction_changed TO P.set_fraction
ROUTE P.value_changed TO T.set_translation)x");
    EXPECT_TRUE(result(r, "animation").met) << result(r, "animation").evidence;
}

TEST(Checker, FTransformOperationsCountEachChild) {
    const CheckReport r = checkText(R"x(FTransform { operation "union" children [
  FShape { geometry FGeometry { type "explicit" definition "0.2 - (x-0.5)^2 - y*y - z*z" } }
  FShape { geometry FGeometry { type "explicit" definition "0.2 - (x+0.5)^2 - y*y - z*z" } }
  FShape { geometry FGeometry { type "explicit" definition "0.2 - x*x - (y-0.5)^2 - z*z" } } ] }
FShape { geometry FGeometry { type "explicit" definition "(0.5 - x*x - y*y - z*z) & (0.5 - abs(z))" } })x");
    const auto& ops = result(r, "set-operations");
    EXPECT_TRUE(ops.met) << ops.evidence;
    EXPECT_NE(ops.evidence.find("3 set operations of 2 kinds"), std::string::npos) << ops.evidence;
}

TEST(Checker, AnUnreadableSubmissionIsNotGradable) {
    const std::string path = testing::TempDir() + "/broken.x3d";
    std::ofstream(path) << "<X3D><Scene><FShape>";
    const CheckReport r = checkSubmission(path, fantasies());
    EXPECT_FALSE(r.gradable);
    EXPECT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.maxScore, 100);
    const CheckReport none = checkSubmission(testing::TempDir(), fantasies());
    EXPECT_FALSE(none.gradable);
}

// The corpus of submissions with known verdicts (tests/grading/submissions).
TEST(Checker, SubmissionsWithKnownVerdicts) {
    const std::string folder = FUNCTIONLAB_SUBMISSIONS_DIR;
    std::ifstream list(folder + "/expected.txt");
    ASSERT_TRUE(list);
    std::map<std::string, CheckReport> reports;
    std::string line;
    int checked = 0;
    while (std::getline(list, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::string file, id, verdict;
        fields >> file >> id >> verdict;
        if (!reports.count(file)) reports[file] = checkSubmission(folder + "/" + file, fantasies());
        const CheckReport& r = reports.at(file);
        ASSERT_TRUE(r.gradable) << file;
        EXPECT_EQ(result(r, id).met, verdict == "met")
            << file << " " << id << ": " << result(r, id).evidence;
        ++checked;
    }
    EXPECT_GE(checked, 16);
    EXPECT_TRUE(reports.at("hostile_huge.x3dv").budgetExceeded ||
                result(reports.at("hostile_huge.x3dv"), "set-operations").met);
}

TEST(Checker, APdeSurfaceCountsAsAParametricShape) {
    // Issue 30: a PDE model is parametric (each patch a function of u, v).
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "functionlab-checker-pde";
    fs::remove_all(dir);
    fs::create_directories(dir);
    pde::Patch p;
    p.cap = true;
    p.setRadii(1);
    p.spine = {pde::Vec3{0, 1, 0}, pde::Vec3{0, -1, 0}, pde::Vec3{}, pde::Vec3{}};
    p.cosines[0][1] = {1.2, 0, 0};
    p.sines[0][1] = {0, 0, 1.2};
    pde::completeCap(p);
    pde::Model m;
    m.hi = {1, 1, 1};
    m.patches = {p};
    std::ofstream(dir / "dome.pde", std::ios::binary) << pde::encodeBinary(m);
    std::ofstream(dir / "dome.x3dv")
        << "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n"
           "FShape { geometry FPdeSurface { url \"dome.pde\" } }\n";
    auto requirements = fantasies();
    requirements.push_back({"pde", RequirementKind::PdeSurface, "", 10});
    const CheckReport r = checkSubmission((dir / "dome.x3dv").string(), requirements);
    const auto& q = result(r, "parametric");
    EXPECT_TRUE(q.met) << q.evidence;
    EXPECT_NE(q.evidence.find("PDE patches of dome.pde"), std::string::npos) << q.evidence;
    ASSERT_FALSE(q.locations.empty());
    const auto& shown = result(r, "pde");
    EXPECT_TRUE(shown.met) << shown.evidence;
    EXPECT_NE(shown.evidence.find("PDE patches from dome.pde"), std::string::npos)
        << shown.evidence;
    // A url that reads nothing shows nothing: not met.
    std::ofstream(dir / "dome.x3dv", std::ios::trunc)
        << "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n"
           "FShape { geometry FPdeSurface { url \"missing.pde\" } }\n";
    EXPECT_FALSE(
        result(checkSubmission((dir / "dome.x3dv").string(), fantasies()), "parametric").met);
    fs::remove_all(dir);
}
