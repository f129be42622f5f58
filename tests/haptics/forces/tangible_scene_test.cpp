// The snapshot the servo loop touches (haptics/tangible_scene.h), on the
// paper's tangible examples.
#include "haptics/probe.h"
#include "haptics/tangible_scene.h"

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
    // A parametric solid with collision "polygonal": its triangles hold it.
    EXPECT_EQ(wind->field, nullptr);
    ASSERT_NE(wind->triangles, nullptr);
    EXPECT_GT(wind->triangles->triangleCount(), 100u);
    // The room's FShape lends its surface to the carpet, the cabinet and the
    // fan's parts: each felt by its triangles.
    std::size_t borrowed = 0;
    for (const TangibleShape& s : t.shapes)
        if (s.triangles && s.surface && s.effect(scene::TangibleKind::Friction)) ++borrowed;
    EXPECT_GE(borrowed, 5u);
    for (const std::string& n : t.notes)
        ADD_FAILURE() << "nothing of the fan should be left out: " << n;
}

TEST(TangibleScene, TheFansCarpetIsRoughAndItsCabinetSmooth) {
    // The room's friction: 0.8 below y = 0.05 (the carpet), 0.3 above.
    const auto scene = example("fan.x3d");
    ProbeOptions o;
    o.duration = 0.4;
    // Down onto the carpet (top at y = 0.02), 0.05 mm in — its tension is
    // 0.8 of the device's force, far more than 0.05 mm of spring — then
    // sideways along it.
    o.path = {{1.2, 0.3, 0.9}, {1.2, 0.01995, 0.9}, {1.3, 0.01995, 0.9}};
    auto r = runProbe(*scene, o);
    ASSERT_TRUE(r);
    const ProbeTick& end = r->ticks.back();
    ASSERT_EQ(end.contact, ContactKind::Surface);
    EXPECT_NEAR(end.proxy[1], 0.02, 1e-6);
    // The friction cone: the proxy lags 0.8 * 0.05 mm behind the tool.
    EXPECT_NEAR(end.device[0] - end.proxy[0], 0.8 * 0.00005, 1e-6);
}

TEST(TangibleScene, TheSharksTailIsTangible) {
    const auto scene = example("shark.x3d");
    const TangibleScene t = makeTangibleScene(*scene, 0);
    EXPECT_FALSE(t.empty());
}

TEST(TangibleScene, BorrowedPhysicsIsReadInTheLendersOwnCoordinates) {
    // The group stands at x = 10; its friction is x in its own coordinates.
    auto r = scene::readSceneBytes(R"(#X3D V3.3 utf8
PROFILE Immersive
Transform { translation 10 0 0 children [
  Shape { geometry Box { size 2 2 2 } }
  FShape { bboxCenter 0 0 0 bboxSize 4 4 4 physics FPhysics { surface FSurface {
    friction FFriction { definition "x" domainMin -2 -2 -2 domainMax 2 2 2 } } } }
] }
)",
                                   "group.x3dv");
    ASSERT_TRUE(r.ok());
    ProbeOptions o;
    // Onto the box's top at the group's x = 0.5, 0.1 mm deep, then along +x.
    o.path = {{10.5, 1.5, 0}, {10.5, 0.9999, 0}, {10.6, 0.9999, 0}};
    const auto run = runProbe(*r.scene, o);
    ASSERT_TRUE(run);
    const ProbeTick& end = run->ticks.back();
    ASSERT_EQ(end.contact, ContactKind::Surface);
    // The cone: friction about 0.6 at the proxy (x = 0.6 in the group), 0.1 mm deep.
    EXPECT_NEAR(end.device[0] - end.proxy[0], 0.6 * 0.0001, 1e-5);
}
