// The paper's scenes (courseware/examples) load cleanly in every encoding they
// ship in, and their effects plans say what each scene means.
#include "scene/effects_plan.h"
#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl::scene;

namespace {

const std::string kExamples = FUNCTIONLAB_EXAMPLES_DIR;

EffectsPlan planOf(const std::string& file) {
    ReadResult r = readSceneFile(kExamples + "/" + file);
    std::string all;
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) all += formatSceneDiagnostic(d) + "\n";
    EXPECT_TRUE(r.ok()) << file << "\n" << all;
    EXPECT_TRUE(all.empty()) << all;
    return r.ok() ? makeEffectsPlan(*r.scene) : EffectsPlan{};
}

TEST(Examples, TexturedSphereIsStatic) {
    EffectsPlan p = planOf("textured_sphere.x3d");
    EXPECT_EQ(p.timeVarying, kStatic);
    EXPECT_FALSE(p.needsHaptics);
    EXPECT_EQ(p.functionShapes, 1u);
}

TEST(Examples, BouncingSphereRemeshesAndRecolours) {
    for (const char* f : {"bouncing_sphere.x3d", "bouncing_sphere.x3dv"}) {
        EffectsPlan p = planOf(f);
        EXPECT_EQ(p.timeVarying, kGeometry | kColour) << f;
        EXPECT_FALSE(p.needsHaptics) << f;
        EXPECT_FALSE(p.usesWallClock) << f;
    }
}

TEST(Examples, WatermelonIsStaticAndTangible) {
    for (const char* f : {"watermelon.x3d", "watermelon.x3dv"}) {
        EffectsPlan p = planOf(f);
        EXPECT_EQ(p.timeVarying, kStatic) << f;
        EXPECT_TRUE(p.needsHaptics) << f;
        ASSERT_EQ(p.entries.size(), 1u) << f;
        std::vector<std::string> kinds;
        for (const auto& t : p.entries[0].tangible)
            kinds.emplace_back(tangibleKindName(t.kind));
        EXPECT_EQ(kinds, (std::vector<std::string>{"friction", "tension", "density"})) << f;
    }
}

TEST(Examples, ClockOnlyTurnsItsHandsByTheWallClock) {
    EffectsPlan p = planOf("clock.x3d");
    EXPECT_EQ(p.timeVarying, kTransform); // never re-meshes, never recolours
    EXPECT_TRUE(p.usesWallClock);
    EXPECT_FALSE(p.needsHaptics);
}

TEST(Examples, FanTurnsItsBladesAndBlowsATimeDependentForce) {
    EffectsPlan p = planOf("fan.x3d");
    EXPECT_EQ(p.timeVarying, kTransform | kPhysics);
    EXPECT_TRUE(p.needsHaptics);
    bool force = false, lends = false;
    for (const auto& e : p.entries) {
        for (const auto& t : e.tangible)
            force |= t.kind == TangibleKind::Force && t.timeVarying;
        lends |= e.appliesToSiblings && !e.tangible.empty();
    }
    EXPECT_TRUE(force);
    EXPECT_TRUE(lends); // standard shapes made tangible by grouping
}

TEST(Examples, SharkIsTangibleWithAForceAroundItsTail) {
    EffectsPlan p = planOf("shark.x3d");
    EXPECT_EQ(p.timeVarying, kTransform | kPhysics);
    EXPECT_TRUE(p.needsHaptics);
}

TEST(Examples, ImplicitGalleryIsStatic) {
    EffectsPlan p = planOf("implicit_gallery.x3d");
    EXPECT_EQ(p.timeVarying, kStatic);
    EXPECT_GE(p.functionShapes, 3u);
}

} // namespace

TEST(Examples, SurfacesLoadWithoutAWarning) {
    // The paper's sphere and a torus, negative inside, as implicit surfaces
    // that take part in nothing needing an inside: no warning to give.
    ReadResult r = readSceneFile(kExamples + "/surfaces.x3d");
    ASSERT_TRUE(r.ok());
    for (const auto& d : r.diagnostics)
        ADD_FAILURE() << formatSceneDiagnostic(d);
    EffectsPlan p = makeEffectsPlan(*r.scene);
    EXPECT_EQ(p.timeVarying, kStatic);
    EXPECT_EQ(p.functionShapes, 4u);
}
