// A grader fair both ways (issue 27): honest work written in any of the
// styles the labs teach is judged — FTransform operations on primitives,
// R-functions, cuts by a plane, FTransform composites, small shapes — and
// work that is not shown, not written by the student or not felt does not
// count. Each named case is one the issue found.
#include "grading/checker.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl;
using namespace fl::grading;

namespace {

using K = RequirementKind;

CheckReport check(const std::string& x3dv, const std::vector<Requirement>& requirements,
                  const CheckOptions& options = {}) {
    auto read = scene::readSceneBytes(
        "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n" + x3dv, "submission.x3dv");
    EXPECT_TRUE(read.ok());
    return checkScene(*read.scene, requirements, options);
}

RequirementResult checkOne(const std::string& x3dv, Requirement requirement) {
    const CheckReport r = check(x3dv, {requirement});
    EXPECT_FALSE(r.budgetExceeded) << x3dv;
    return r.requirements.at(0);
}

Requirement setOperations(int minimum = 1, int kinds = 1) {
    return {"set-operations", K::SetOperations, "", 20, minimum, kinds};
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

const char* kBoxAndBall = R"x(FTransform { operation "union" children [
  FShape { geometry FGeometry { type "explicit" definition "box(0.5, 0.4, 0.5)" } }
  FShape { geometry FGeometry { type "explicit" definition "0.45^2 - x^2 - (y - 0.4)^2 - z^2" } } ] })x";

} // namespace

// The issue's honest FTransform style: the ball rises above the box.
TEST(Fairness, AnFTransformUnionOfALibraryBoxAndABallIsJudged) {
    const RequirementResult ops = checkOne(kBoxAndBall, setOperations());
    EXPECT_TRUE(ops.met) << ops.evidence;
    EXPECT_TRUE(has(ops.evidence, "union of the FTransform at line 4's children") ||
                has(ops.evidence, "union of an FTransform's children at line 4"))
        << ops.evidence;
    EXPECT_FALSE(has(ops.evidence, "the the")) << ops.evidence;
}

TEST(Fairness, RFunctionOperationsAreJudgedLikeMinAndMax) {
    for (const char* kind : {"rfunction", "minmax"}) {
        const std::string scene =
            std::string(R"x(FShape { geometry FGeometry { type "explicit" setOperations ")x") +
            kind + R"x(" definition "keep = min(min(0.5 - abs(x), 0.6 - abs(y)), 0.5 - abs(z));
  door = min(min(0.15 - abs(x), -0.3 - y), z - 0.3);
  towers = (0.2^2 - (x - 0.6)^2 - z*z | 0.2^2 - (x + 0.6)^2 - z*z) & (0.8 - abs(y));
  (keep \\ door) | towers" } })x";
        const RequirementResult ops = checkOne(scene, setOperations(4, 3));
        EXPECT_TRUE(ops.met) << kind << ": " << ops.evidence;
    }
}

// −0.10 with the cut and +0.04 without it at (−0.6, 0.1, 0): the cut is live.
TEST(Fairness, ACutByAPlaneIsJudged) {
    for (const char* scene : {R"x(FShape { geometry FGeometry { type "explicit"
  definition "sphere(-0.4, 0.2, 0, 0.3) & halfspace(0, 1, 0, -0.2)" } })x",
                              R"x(FTransform { operation "intersection" children [
  FShape { geometry FGeometry { type "explicit" definition "sphere(-0.4, 0.2, 0, 0.3)" } }
  FShape { geometry FGeometry { type "explicit" definition "halfspace(0, 1, 0, -0.2)" } } ] })x"}) {
        const RequirementResult ops = checkOne(scene, setOperations());
        EXPECT_TRUE(ops.met) << scene << "\n" << ops.evidence;
    }
}

TEST(Fairness, LibraryPrimitivesAreSingleShapes) {
    const RequirementResult ops = checkOne(R"x(FShape { geometry FGeometry { type "explicit"
  definition "box(0.3, 0.3, 0.3) | cylinder(0.6, 0, 0, 0.2, 1.2) | sphere(-0.55, 0.1, 0, 0.3)" } })x",
                                           setOperations(3, 2));
    EXPECT_FALSE(ops.met) << ops.evidence;
    EXPECT_TRUE(has(ops.evidence, "2 set operations of 1 kind")) << ops.evidence;
}

TEST(Fairness, WorkUnderAZeroOrVanishingScaleIsNotShown) {
    const std::string ball = R"x(FShape { geometry FGeometry { type "explicit"
  definition "0.5 - x*x - y*y - z*z" } })x";
    for (const std::string& scene :
         {"Transform { scale 0 0 0 children " + ball + " }",
          "Transform { scale 1e-6 1e-6 1e-6 children " + ball + " }",
          "Transform { scale 1 0 1 children " + ball + " }",
          R"x(FTransform { scale "x = 0; y = 0; z = 0;" children )x" + ball + " }"}) {
        const RequirementResult r = checkOne(scene, {"explicit", K::ExplicitSolid, "", 10});
        EXPECT_FALSE(r.met) << scene << "\n" << r.evidence;
    }
    const RequirementResult shown =
        checkOne("Transform { scale 0.05 0.05 0.05 children " + ball + " }",
                 {"explicit", K::ExplicitSolid, "", 10});
    EXPECT_TRUE(shown.met) << "small, but shown: " << shown.evidence;
}

TEST(Fairness, ALevelOfDetailRangeMustReallyVary) {
    const Requirement lod{"level-of-detail", K::LevelOfDetail, "", 10};
    const auto withRange = [](const char* range) {
        return std::string(
                   R"x(FShape { geometry FGeometry { type "explicit" lod TRUE lodRange )x") +
               range + R"x( definition "0.5 - x*x - y*y - z*z" } })x";
    };
    const RequirementResult narrow = checkOne(withRange("32 32.0001"), lod);
    EXPECT_FALSE(narrow.met) << narrow.evidence;
    EXPECT_TRUE(has(narrow.evidence, "at least twice")) << narrow.evidence;
    EXPECT_TRUE(checkOne(withRange("16 32"), lod).met);
    EXPECT_TRUE(checkOne(withRange("8 128"), lod).met);
}

TEST(Fairness, EvidenceNamesEachNodeOnce) {
    const RequirementResult colour = checkOne(R"x(FShape { geometry FGeometry { type "explicit"
  definition "0.5 - x*x - y*y - z*z" }
  appearance FAppearance { material DEF M FMaterial { type "parametric" definition "r = 1; g = 0; b = 0;" } } })x",
                                              {"colour", K::FunctionColour, "", 10});
    EXPECT_FALSE(colour.met);
    EXPECT_TRUE(has(colour.evidence, "FMaterial M at line 6")) << colour.evidence;
    EXPECT_FALSE(has(colour.evidence, "at line 6 at line 6")) << colour.evidence;
}

// The colour reason points at the FMaterial that varies, not at a plain one.
TEST(Fairness, TheColourThatVariesIsTheOneNamed) {
    const RequirementResult colour =
        checkOne(R"x(Shape { appearance Appearance { material Material {} } geometry Box {} }
FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" }
  appearance FAppearance { material FMaterial { diffuseColor 1 0 0 } } }
FShape { geometry FGeometry { type "explicit" definition "0.3 - (x-0.5)^2 - y*y - z*z" }
  appearance FAppearance { material FMaterial { type "parametric"
    definition "r = 0.5 + 0.5*x; g = 0.2; b = 0.1;" } } })x",
                 {"colour", K::FunctionColour, "", 10});
    EXPECT_TRUE(colour.met) << colour.evidence;
    ASSERT_FALSE(colour.locations.empty());
    EXPECT_EQ(colour.locations.front().line, 9) << colour.evidence;
}

TEST(Fairness, FTransformCompositesAreExplicitSolidsAndKeepTheirColour) {
    const RequirementResult solid = checkOne(kBoxAndBall, {"explicit", K::ExplicitSolid, "", 10});
    EXPECT_TRUE(solid.met) << solid.evidence;
    const RequirementResult colour = checkOne(R"x(FTransform { operation "morph"
  morphFactor "0.5 - 0.5*cos(2*pi*t)" cycleInterval 4 loop TRUE children [
  FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" }
    appearance FAppearance { material FMaterial { type "parametric"
      definition "r = 0.2 + 0.6*t; g = 0.8 - 0.6*t; b = 0.2 + 0.3*y;" cycleInterval 4 loop TRUE } } }
  FShape { geometry FGeometry { type "explicit" definition "box(0.5, 0.5, 0.5)" } } ] })x",
                                              {"colour", K::FunctionColour, "", 10});
    EXPECT_TRUE(colour.met) << colour.evidence;
}

// A ball of radius 0.2 in the default box is smaller than the checker's
// coarse mesh: its colour is looked at where the ball is.
TEST(Fairness, TheColourOfASmallShapeIsSampledWhereItIs) {
    for (const char* radius : {"0.2", "0.1"}) {
        const RequirementResult colour = checkOne(
            std::string(R"x(FShape { geometry FGeometry { type "explicit" definition ")x") +
                radius +
                R"x(^2 - x*x - y*y - z*z" }
  appearance FAppearance { material FMaterial { type "parametric"
    definition "r = 0.5 + 0.5*x; g = 0.5 + 0.5*y; b = 0.2;" } } })x",
            {"colour", K::FunctionColour, "", 10});
        EXPECT_TRUE(colour.met) << radius << ": " << colour.evidence;
    }
}

TEST(Fairness, AColourThatOnlyChangesInTimeDoesNotVaryOverTheShape) {
    const std::string scene =
        R"x(FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" }
  appearance FAppearance { material FMaterial { type "parametric" cycleInterval 4 loop TRUE
    definition "r = 0.5 + 0.5*sin(2*pi*t); g = 0.5; b = 0.5;" } } })x";
    Requirement overShape{"colour", K::FunctionColour, "", 10};
    overShape.variesOverShape = true;
    const RequirementResult r = checkOne(scene, overShape);
    EXPECT_FALSE(r.met);
    EXPECT_TRUE(has(r.evidence, "changes only in time")) << r.evidence;
    EXPECT_TRUE(checkOne(scene, {"colour", K::FunctionColour, "", 10}).met)
        << "over the shape or in time: the time lab's colour";
}

// An effect counts where it can be felt on the shown solid.
TEST(Fairness, EffectsThatCannotBeFeltAreNotTangible) {
    const Requirement tangible{"tangible", K::Tangible, "", 60};
    const std::string ball =
        R"x(geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" })x";
    for (
        const std::string& scene : {
            // zero effects
            "FShape { " + ball + R"x( physics FPhysics { surface FSurface {
  friction FFriction { definition "0*x" } tension FTension { definition "0" } }
  density FDensity { definition "0*sin(x*y)" } } })x",
            // an empty solid
            std::string(R"x(FShape { geometry FGeometry { type "explicit" definition "-1 + 0*x" }
  physics FPhysics { surface FSurface { friction FFriction { definition "0.3" } } } })x"),
            // zero wherever the ball is (|x| <= 0.71 there)
            "FShape { " + ball + R"x( physics FPhysics {
  surface FSurface { friction FFriction { definition "x > 2 ? 0.3 : 0" } }
  density FDensity { definition "abs(x) > 0.9 ? 0.5 : 0" } } })x",
            // under scale 0
            "Transform { scale 0 0 0 children FShape { " + ball +
                R"x( physics FPhysics { surface FSurface { friction FFriction { definition "0.3" } } } } })x",
        }) {
        const RequirementResult r = checkOne(scene, tangible);
        EXPECT_FALSE(r.met) << scene << "\n" << r.evidence;
    }
}

TEST(Fairness, EffectsThatCanBeFeltAreTangible) {
    Requirement twoKinds{"tangible", K::Tangible, "", 60, 2};
    const RequirementResult r = checkOne(
        R"x(FShape { geometry FGeometry { type "explicit" definition "0.5 - x*x - y*y - z*z" }
  physics FPhysics { surface FSurface { friction FFriction { definition "x > 0.3 ? 0.5 : 0" } }
    force FForce { definition "fx = 0; fy = 0.2*u; fz = 0;" } } })x",
        twoKinds);
    EXPECT_TRUE(r.met) << r.evidence;
    EXPECT_TRUE(has(r.evidence, "friction, force")) << r.evidence;
}

// The paper's way: an FShape without geometry lends its physics to the
// standard shapes grouped with it.
TEST(Fairness, AStandardBoxMadeTangibleByItsGroupsFShapeCounts) {
    const RequirementResult r = checkOne(R"x(Group { children [
  FShape { physics FPhysics { surface FSurface { friction FFriction { definition "0.3" }
    tension FTension { definition "0.8" } } } }
  Shape { geometry Box { size 1 1 1 } } ] })x",
                                         {"tangible", K::Tangible, "", 60, 2});
    EXPECT_TRUE(r.met) << r.evidence;
    EXPECT_TRUE(has(r.evidence, "physics lent by the FShape at line 5")) << r.evidence;
}

// A verdict cut short is reported: budget_exceeded, and a warning that says
// so. A union of a ball with itself, written so that intervals cannot see
// the two are equal (a term times zero), cannot be proven dead or live.
TEST(Fairness, AVerdictCutShortSetsBudgetExceeded) {
    const CheckReport r = check(R"x(FShape { geometry FGeometry { type "explicit"
  definition "(0.5 - x*x - y*y - z*z) | (0.5 - x*x - y*y - z*z + 0*sin(x*y*z))" } })x",
                                {setOperations()});
    EXPECT_FALSE(r.requirements.at(0).met);
    EXPECT_TRUE(has(r.requirements.at(0).evidence, "could not be judged"))
        << r.requirements.at(0).evidence;
    EXPECT_TRUE(r.budgetExceeded);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_TRUE(has(r.diagnostics.back().message, "set-operations"))
        << r.diagnostics.back().message;
}
