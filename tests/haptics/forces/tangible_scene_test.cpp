// The snapshot the servo loop touches (haptics/tangible_scene.h), on the
// paper's tangible examples.
#include "tangible_scene.h"

#include "scene/scene_reader.h"

#include <gtest/gtest.h>

using namespace fl;
using namespace fl::haptics;

namespace {
std::unique_ptr<scene::Scene> example(const char* name) {
    auto r = scene::readSceneFile(std::string(FUNCTIONLAB_EXAMPLES_DIR) + "/" + name);
    EXPECT_TRUE(r.ok()) << name;
    return std::move(r.scene);
}
} // namespace

TEST(TangibleScene, TheWatermelonIsOneSurfaceWithFrictionTensionAndDensity) {
    const auto scene = example("watermelon.x3d");
    const TangibleScene t = makeTangibleScene(*scene, 0);
    ASSERT_EQ(t.shapes.size(), 1u);
    const TangibleShape& s = t.shapes[0];
    EXPECT_TRUE(s.surface);
    EXPECT_TRUE(s.effect(scene::TangibleKind::Friction));
    EXPECT_TRUE(s.effect(scene::TangibleKind::Tension));
    EXPECT_TRUE(s.effect(scene::TangibleKind::Density));
    EXPECT_FALSE(s.effect(scene::TangibleKind::Force));
    EXPECT_FALSE(t.geometryVaries);
    EXPECT_NE(s.effect(scene::TangibleKind::Density)->location.find("watermelon.x3d:"),
              std::string::npos);
}

TEST(TangibleScene, TheFansWindIsAForceFieldThatReadsTimeInsideItsBox) {
    const auto scene = example("fan.x3d");
    const TangibleScene t = makeTangibleScene(*scene, 0.25);
    const TangibleShape* wind = nullptr;
    for (const TangibleShape& s : t.shapes)
        if (s.name.find("WIND") != std::string::npos) wind = &s;
    ASSERT_NE(wind, nullptr);
    EXPECT_FALSE(wind->surface);
    EXPECT_EQ(wind->field, nullptr); // a parametric solid: its box is its container
    const EffectField* f = wind->effect(scene::TangibleKind::Force);
    ASSERT_NE(f, nullptr);
    EXPECT_TRUE(f->readsTime);
    // The room's FShape lends its surface to standard shapes: said, not hidden.
    bool noted = false;
    for (const std::string& n : t.notes)
        noted = noted || n.find("polygon contact") != std::string::npos;
    EXPECT_TRUE(noted);
}

TEST(TangibleScene, TheSharksTailIsTangible) {
    const auto scene = example("shark.x3d");
    const TangibleScene t = makeTangibleScene(*scene, 0);
    EXPECT_FALSE(t.empty());
}
