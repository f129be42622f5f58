// The contact algorithms behind ForceModel (haptics/contact_algorithm.h):
// each kind of tangible shape gets its algorithm, and an algorithm asks the
// surface's material only through SurfaceMaterial — so a material written
// here (no scene effect at all) drives the same proxy.
#include "force_test_scenes.h"

#include "haptics/contact_algorithm.h"
#include "haptics/god_object_contact.h"
#include "haptics/implicit_proxy_contact.h"
#include "haptics/tangible_scene.h"

#include <gtest/gtest.h>

using namespace fl;
using namespace fl::haptics;

namespace {

constexpr const char* kBall = "1 - x*x - y*y - z*z";

// The snapshot points into its scene: both kept together.
struct Snapshot {
    std::shared_ptr<const scene::Scene> scene;
    TangibleScene tangible;
};

Snapshot snapshot(const std::string& text) {
    auto scene = test::readScene(text);
    TangibleScene tangible = makeTangibleScene(*scene, 0.0);
    return {std::move(scene), std::move(tangible)};
}

struct FixedFriction final : SurfaceMaterial {
    explicit FixedFriction(double mu) : mu(mu) {}
    double frictionAt(const field::Vec3&) override {
        ++asked;
        return mu;
    }
    double mu;
    int asked = 0;
};

} // namespace

TEST(ContactAlgorithm, EachKindOfShapeGetsItsAlgorithm) {
    const Snapshot function = snapshot(test::tangibleScene(kBall, {.friction = "0"}));
    ASSERT_EQ(function.tangible.shapes.size(), 1u);
    field::FieldSampler sampler(*function.tangible.shapes[0].field);
    const auto proxy = surfaceContactFor(function.tangible.shapes[0], &sampler);
    EXPECT_NE(dynamic_cast<ImplicitProxyContact*>(proxy.get()), nullptr);

    const Snapshot polygons = snapshot(R"(#X3D V3.3 utf8
PROFILE Immersive
FShape { geometry FGeometry { definition "1 - x*x - y*y - z*z" resolution 16
  domainMin -1.2 -1.2 -1.2 domainMax 1.2 1.2 1.2 collision "polygonal" }
  physics FPhysics { surface FSurface { friction FFriction { definition "0" } } } }
)");
    ASSERT_EQ(polygons.tangible.shapes.size(), 1u);
    const auto god = surfaceContactFor(polygons.tangible.shapes[0], nullptr);
    EXPECT_NE(dynamic_cast<GodObjectContact*>(god.get()), nullptr);

    // Only an inside (density): no surface to keep a proxy on.
    const Snapshot inside = snapshot(test::tangibleScene(kBall, {.density = "1"}));
    ASSERT_EQ(inside.tangible.shapes.size(), 1u);
    field::FieldSampler insideSampler(*inside.tangible.shapes[0].field);
    EXPECT_EQ(surfaceContactFor(inside.tangible.shapes[0], &insideSampler), nullptr);
}

TEST(ContactAlgorithm, TheProxyMovesOnlyAsFarAsTheMaterialsFrictionLets) {
    const Snapshot ball = snapshot(test::tangibleScene(kBall, {.friction = "0"}));
    field::FieldSampler sampler(*ball.tangible.shapes[0].field);
    auto slideWith = [&](double mu, FixedFriction& material) {
        ImplicitProxyContact contact(sampler, ball.tangible.shapes[0].container.diagonal());
        ContactState s;
        s.lastTool = {0, 0, 1.5};
        s.hasLastTool = true;
        // In through the top, then along the surface, 1 cm under it.
        for (const field::Vec3& tool :
             {field::Vec3{0, 0, 0.99}, field::Vec3{0.05, 0, 0.985}, field::Vec3{0.1, 0, 0.985}}) {
            contact.step(s, tool, solidAt(sampler, tool), material);
            s.lastTool = tool;
        }
        EXPECT_EQ(s.contact, ContactKind::Surface) << mu;
        EXPECT_NEAR(solidAt(sampler, s.proxy).v, 0, 1e-9) << mu; // on f = 0
        return s.proxy;
    };
    FixedFriction slippery(0), sticky(100);
    const field::Vec3 free = slideWith(0, slippery), held = slideWith(100, sticky);
    EXPECT_GT(slippery.asked + sticky.asked, 0); // friction comes from the material
    EXPECT_GT(free[0], 0.09);                    // follows the tool's projection
    EXPECT_LT(held[0], 1e-6);                    // stays where contact began
}
