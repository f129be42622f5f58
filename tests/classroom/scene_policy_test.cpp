// What a class scene may hold: checked by the scene reader and the formula
// checker, no urls, bounded size, nodes and formulas.
#include "classroom/scene_policy.h"
#include "classroom/starter_scene.h"

#include "pde/pde_data_url.h"
#include "scenes.h"

#include <gtest/gtest.h>

namespace fl::classroom {
namespace {

bool mentions(const SceneCheck& c, const std::string& word, int line = -1) {
    for (const auto& d : c.diagnostics)
        if (d.message.find(word) != std::string::npos && (line < 0 || d.pos.line == line))
            return true;
    return false;
}

TEST(ClassroomScene, StarterAndPlainScenesPass) {
    EXPECT_TRUE(checkClassroomScene(starterScene()).ok);
    EXPECT_TRUE(checkClassroomScene(test::classScene("sphere(0, 0, 0, 1)")).ok);
    EXPECT_TRUE(
        checkClassroomScene("#X3D V3.3 utf8\nPROFILE Immersive\nShape { geometry Box {} }\n").ok);
}

// Issue 30: a PDE shape in a class carries its model in a data: url.
std::string pdeScene(const std::string& url, const std::string& fields = "") {
    return "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT FunctionLab:1\n"
           "FShape { geometry FPdeSurface { url \"" +
           url + "\" " + fields + " } }\n";
}

pde::Model patches(std::size_t count) {
    pde::Patch p;
    p.cap = true;
    p.setRadii(1);
    p.spine = {pde::Vec3{0, 1, 0}, pde::Vec3{0, -1, 0}, pde::Vec3{}, pde::Vec3{}};
    p.cosines[0][1] = {1, 0, 0};
    p.sines[0][1] = {0, 0, 1};
    pde::completeCap(p);
    pde::Model m;
    m.hi = {1, 1, 1};
    m.patches.assign(count, p);
    return m;
}

TEST(ClassroomScene, APdeShapeCarriedInTheSceneIsAllowedANamedFileIsNot) {
    const SceneCheck carried = checkClassroomScene(pdeScene(pde::dataUrlOf(patches(3))));
    EXPECT_TRUE(carried.ok) << (carried.diagnostics.empty() ? "" : carried.diagnostics[0].message);
    const SceneCheck named = checkClassroomScene(pdeScene("bunny.pde"));
    EXPECT_FALSE(named.ok);
    EXPECT_TRUE(mentions(named, "may not hold urls"));
    // Many patches at a fine level of detail: more meshing than a class allows.
    const std::string many = pdeScene(pde::dataUrlOf(patches(4000)), "lodRange 8 256");
    ASSERT_LT(many.size(), ClassroomLimits{}.maxSceneBytes);
    const SceneCheck costly = checkClassroomScene(many);
    EXPECT_FALSE(costly.ok);
    EXPECT_TRUE(costly.tooCostly);
    EXPECT_TRUE(mentions(costly, "grid cells"));
}

TEST(ClassroomScene, FormulaErrorsAreLocated) {
    const SceneCheck c = checkClassroomScene(test::classScene("sphere(0, 0, 0, 1) + sine(x)"));
    ASSERT_FALSE(c.ok);
    ASSERT_FALSE(c.diagnostics.empty());
    EXPECT_EQ(c.diagnostics.front().pos.line, 4);
    EXPECT_GT(c.diagnostics.front().pos.column, 0);
    EXPECT_TRUE(mentions(c, "sine", 4));
}

TEST(ClassroomScene, SyntaxErrorsAreLocated) {
    const SceneCheck c = checkClassroomScene(
        "<X3D profile='Immersive' version='3.3'><Scene>\n<Shape>\n<Box size='1 1'\n</Scene></X3D>");
    EXPECT_FALSE(c.ok);
    EXPECT_GT(c.diagnostics.front().pos.line, 0);
}

TEST(ClassroomScene, InlineIsRefused) {
    const SceneCheck c =
        checkClassroomScene("<X3D profile='Immersive' version='3.3'><Scene>\n<Inline "
                            "url='\"other.x3d\"'/>\n</Scene></X3D>");
    EXPECT_FALSE(c.ok);
    EXPECT_TRUE(mentions(c, "Inline", 2));
}

TEST(ClassroomScene, ExternProtoIsRefused) {
    const SceneCheck c = checkClassroomScene(
        "#X3D V3.3 utf8\nPROFILE Immersive\nEXTERNPROTO Thing [] \"lib.x3dv#Thing\"\n");
    EXPECT_FALSE(c.ok);
    EXPECT_TRUE(mentions(c, "EXTERNPROTO", 3));
}

TEST(ClassroomScene, ScriptIsRefused) {
    const SceneCheck c = checkClassroomScene(
        "#X3D V3.3 utf8\nPROFILE Immersive\nScript { url \"ecmascript: function f() {}\" }\n");
    EXPECT_FALSE(c.ok);
    EXPECT_TRUE(mentions(c, "Script", 3));
}

TEST(ClassroomScene, TextureUrlsAreRefused) {
    const SceneCheck c = checkClassroomScene(
        "<X3D profile='Immersive' version='3.3'><Scene>\n<Shape><Appearance>\n<ImageTexture "
        "url='\"http://example.org/a.png\"'/>\n"
        "</Appearance><Box/></Shape>\n</Scene></X3D>");
    EXPECT_FALSE(c.ok);
    EXPECT_TRUE(mentions(c, "url", 3));
}

TEST(ClassroomScene, LimitsAreEnforced) {
    ClassroomLimits limits;
    limits.maxSceneBytes = 100;
    EXPECT_FALSE(checkClassroomScene(starterScene(), limits).ok);

    limits = {};
    limits.maxNodes = 3;
    EXPECT_FALSE(checkClassroomScene(starterScene(), limits).ok);

    limits = {};
    limits.maxFormulaBytes = 10;
    const SceneCheck c = checkClassroomScene(test::classScene("sphere(0, 0, 0, 1)"), limits);
    EXPECT_FALSE(c.ok);
    EXPECT_TRUE(mentions(c, "at most 10", 4));
}

TEST(ClassroomScene, GarbageNeverCrashes) {
    for (const std::string& s : {std::string(), std::string("\0\0\0", 3), std::string("<<<<"),
                                 std::string("\x1f\x8b\x08\x00garbage"), std::string(5000, '{')})
        EXPECT_FALSE(checkClassroomScene(s).ok);
}

} // namespace
} // namespace fl::classroom
