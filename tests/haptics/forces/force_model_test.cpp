// The force model on the simulated device (haptics/force_model.h): contact by
// sign change and a proxy kept on f = 0, friction, tension, density, force
// fields, and the named hard cases of docs/haptics.md.
#include "force_test_scenes.h"

#include "haptics/probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace fl;
using namespace fl::haptics;
using fl::haptics::test::Physics;

namespace {

constexpr const char* kBall = "1 - x*x - y*y - z*z";
constexpr double kStiffness = 10000; // half the simulated device's

ProbeRun probe(const std::string& text, std::vector<field::Vec3> path, double duration = 1,
               double start = 0) {
    const auto scene = test::readScene(text);
    ProbeOptions o;
    o.path = std::move(path);
    o.duration = duration;
    o.startTime = start;
    std::string error;
    auto run = runProbe(*scene, o, &error);
    EXPECT_TRUE(run) << error;
    return run ? *run : ProbeRun{};
}

const ProbeTick& last(const ProbeRun& r) {
    return r.ticks.back();
}

} // namespace

TEST(ForceModel, PressingOnABallHoldsTheProxyOnItsSurface) {
    // Down the z axis from 1.5 to 0.999: 1 mm under the surface at the end.
    const auto r =
        probe(test::tangibleScene(kBall, {.friction = "0"}), {{0, 0, 1.5}, {0, 0, 0.999}});
    ASSERT_EQ(r.ticks.size(), 1001u);
    EXPECT_EQ(r.ticks.front().contact, ContactKind::None);
    EXPECT_EQ(last(r).contact, ContactKind::Surface);
    EXPECT_NEAR(last(r).proxy[2], 1.0, 1e-9);
    EXPECT_NEAR(last(r).force[2], kStiffness * 0.001, 1e-3); // 10 N outwards
    EXPECT_NEAR(last(r).force[0], 0, 1e-9);
    // No force before the surface is reached.
    for (const ProbeTick& t : r.ticks) {
        if (t.device[2] > 1) {
            EXPECT_EQ(field::length(t.force), 0) << t.ms;
        }
    }
}

TEST(ForceModel, TheDevicesMaximumForceIsNeverExceeded) {
    const auto r = probe(test::tangibleScene(kBall, {.friction = "0"}), {{0, 0, 1.5}, {0, 0, 0.5}});
    for (const ProbeTick& t : r.ticks)
        EXPECT_LE(field::length(t.force), r.maxForce + 1e-9);
    EXPECT_NEAR(field::length(last(r).force), r.maxForce, 1e-9);
    EXPECT_EQ(last(r).contact, ContactKind::Surface); // no tension: it holds
}

TEST(ForceModel, FrictionHoldsTheProxyBackWhileSliding) {
    // 1 mm deep, then sideways: without friction the proxy follows the tool;
    // with friction 0.5 it lags and the force has a part against the motion.
    auto run = [](const char* mu) {
        return probe(test::tangibleScene("1 - z", {.friction = mu}),
                     {{0, 0, 1.2}, {0, 0, 0.999}, {0.2, 0, 0.999}});
    };
    const auto free = run("0"), rough = run("0.5");
    EXPECT_EQ(last(free).contact, ContactKind::Surface);
    EXPECT_NEAR(last(free).force[0], 0, 1e-6);
    EXPECT_NEAR(last(free).proxy[0], last(free).device[0], 1e-9);
    // The friction cone: radius 0.5 * depth 0.001 behind the tool.
    EXPECT_NEAR(last(rough).proxy[0], last(rough).device[0] - 0.0005, 1e-7);
    EXPECT_NEAR(last(rough).force[0], -kStiffness * 0.0005, 1e-3);
    EXPECT_NEAR(last(rough).force[2], kStiffness * 0.001, 1e-3);
}

TEST(ForceModel, PastItsTensionTheToolPopsThroughAndTheInsideActs) {
    // Tension 0.4 of the simulated device's 50 N, 20 N: about 1 mm of
    // spring at 10000 N/m and the contact damping at 1 m/s; then density
    // drag inside.
    const auto r =
        probe(test::tangibleScene(kBall, {.friction = "0", .tension = "0.4", .density = "0.2"}),
              {{0, 0, 1.5}, {0, 0, 0.5}});
    bool surface = false, inside = false;
    double peak = 0;
    for (const ProbeTick& t : r.ticks) {
        surface = surface || t.contact == ContactKind::Surface;
        if (t.contact == ContactKind::Surface) peak = std::max(peak, field::length(t.force));
        if (t.contact == ContactKind::Inside && t.ms < 1000) { // at rest at the end
            inside = true;
            // Drag: 0.2 * 200 N·s/m * 1 m/s against the motion (down -z).
            EXPECT_NEAR(t.force[2], 0.2 * 200 * 1.0, 1e-6) << t.ms;
        }
    }
    EXPECT_TRUE(surface);
    EXPECT_TRUE(inside);
    // The spring gives way at 20 N; the contact damping (K·T = 10 N·s/m at
    // 1 m/s) adds to what is felt, not to what pops it.
    EXPECT_LE(peak, 20.0 + 10.0 + 1e-9);
    EXPECT_GT(peak, 5.0); // it was felt before it gave way
}

TEST(ForceModel, AForceFieldActsOnlyInsideItsContainer) {
    // An invisible ball blowing along +x with 3 N, nothing outside.
    const auto r = probe(test::tangibleScene(kBall, {.force = "fx = 3; fy = 0; fz = 0;"}),
                         {{-1.5, 0, 0}, {1.5, 0, 0}});
    for (const ProbeTick& t : r.ticks) {
        const bool in = std::abs(t.device[0]) < 1 - 1e-9;
        const bool out = std::abs(t.device[0]) > 1 + 1e-9;
        if (in) {
            EXPECT_EQ(t.contact, ContactKind::Inside) << t.ms;
            EXPECT_NEAR(t.force[0], 3, 1e-12) << t.ms;
        }
        if (out) {
            EXPECT_EQ(field::length(t.force), 0) << t.ms;
        }
    }
}

TEST(ForceModel, EffectsAreReadThroughTheirOwnDomainBoxes) {
    // Friction defined over the unit box [0,1]^3 mapped onto the geometry's
    // [-2,2]^3: x' = 0.5 at the scene's x = 0.
    const auto scene = test::readScene(
        "#X3D V3.3 utf8\nPROFILE Immersive\nFShape { geometry FGeometry { definition \"1 - z\" "
        "domainMin -2 -2 -2 domainMax 2 2 2 } physics FPhysics { surface FSurface { friction "
        "FFriction { definition \"x\" domainMin 0 0 0 domainMax 1 1 1 } } } }\n");
    ProbeOptions o;
    o.path = {{0, 0, 1.2}, {0, 0, 0.999}, {0.1, 0, 0.999}};
    const auto r = runProbe(*scene, o);
    ASSERT_TRUE(r);
    // mu at the proxy: x' = (x + 2) / 4 ≈ 0.525; lag = mu * depth.
    const double lag = r->ticks.back().device[0] - r->ticks.back().proxy[0];
    EXPECT_NEAR(lag, 0.525 * 0.001, 2e-5);
}

TEST(ForceModel, ForcesThatVaryWithTimeFollowTheOneClock) {
    // fx = t: cycleInterval 1 over timeSpan 0..1, looping; started at scene time 0.25.
    const auto scene = test::readScene(
        "#X3D V3.3 utf8\nPROFILE Immersive\nFShape { geometry FGeometry { definition \"1 - "
        "x*x - y*y - z*z\" } physics FPhysics { force FForce { definition \"fx = t; fy = 0; fz = "
        "0;\" loop TRUE } } }\n");
    ProbeOptions o;
    o.path = {{0, 0, 0}};
    o.duration = 0.5;
    o.startTime = 0.25;
    const auto r = runProbe(*scene, o);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->ticks.front().force[0], 0.25, 1e-9);
    EXPECT_NEAR(r->ticks[250].force[0], 0.5, 1e-9);
    EXPECT_NEAR(r->ticks.back().force[0], 0.75, 1e-9);
}

// ---- hard cases (docs/haptics.md, "Hard cases") ------------------------------

TEST(ForceModelHardCases, AShellThinnerThanOneTicksMotionIsNotTunnelledThrough) {
    // A shell 1e-4 thick at radius 1; the tool crosses it in one 5 cm step.
    const auto r =
        probe(test::tangibleScene("1e-4 - abs(sqrt(x*x + y*y + z*z) - 1)", {.friction = "0"}),
              {{0, 0, 1.5}, {0, 0, 0.5}}, 0.02);
    ASSERT_EQ(r.ticks.size(), 21u);
    EXPECT_EQ(last(r).contact, ContactKind::Surface);
    EXPECT_NEAR(last(r).proxy[2], 1.0001, 1e-6);
    EXPECT_GT(last(r).force[2], 0);
}

TEST(ForceModelHardCases, AConesApexWhereTheGradientVanishesGivesAFiniteForce) {
    // The apex of the cone sqrt(x² + y²) <= -z ... pointing up at the origin.
    const auto r = probe(test::tangibleScene("-z - sqrt(x*x + y*y)", {.friction = "0"}),
                         {{0, 0, 0.5}, {0, 0, -0.01}});
    for (const ProbeTick& t : r.ticks) {
        EXPECT_TRUE(field::isFinite(t.force)) << t.ms;
        EXPECT_TRUE(field::isFinite(t.proxy)) << t.ms;
    }
    EXPECT_EQ(last(r).contact, ContactKind::Surface);
    EXPECT_GE(last(r).proxy[2], -1e-6); // the proxy did not sink with the tool
    EXPECT_GT(last(r).force[2], 0);
}

TEST(ForceModelHardCases, ASharpCsgEdgeDoesNotLetTheProxyLeakThrough) {
    // The quarter space x <= 0, y <= 0 (min of two half-spaces): pressed
    // diagonally into its edge, the proxy stays on the solid's boundary.
    const auto r = probe(test::tangibleScene("min(-x, -y)", {.friction = "0"}),
                         {{0.3, 0.3, 0}, {-0.05, -0.05, 0}});
    EXPECT_EQ(last(r).contact, ContactKind::Surface);
    const auto& p = last(r).proxy;
    EXPECT_GE(std::max(p[0], p[1]), -1e-9) << p[0] << " " << p[1];
    EXPECT_GT(last(r).force[0] + last(r).force[1], 0); // pushed back out
}

TEST(ForceModelHardCases, VeryFastMotionStillFindsTheSurface) {
    // 100 m/s: 10 cm a tick, straight through a ball of radius 0.3.
    const auto r = probe(test::tangibleScene("0.09 - x*x - y*y - z*z", {.friction = "0"}),
                         {{0, 0, 10}, {0, 0, 0}}, 0.1);
    EXPECT_EQ(last(r).contact, ContactKind::Surface);
    EXPECT_NEAR(last(r).proxy[2], 0.3, 1e-9);
}

TEST(ForceModelHardCases, ANaNRegionContributesNothingAndIsReportedOnce) {
    // Density sqrt(x): not a number where x < 0.
    const auto r =
        probe(test::tangibleScene(kBall, {.density = "sqrt(x)"}), {{-0.5, 0, 0}, {0.5, 0, 0}});
    ASSERT_EQ(r.reports.size(), 1u);
    EXPECT_NE(r.reports[0].find("FDensity"), std::string::npos) << r.reports[0];
    EXPECT_NE(r.reports[0].find("test.x3dv:"), std::string::npos) << r.reports[0];
    for (const ProbeTick& t : r.ticks) {
        EXPECT_TRUE(field::isFinite(t.force));
        if (t.device[0] < 0) {
            EXPECT_EQ(field::length(t.force), 0) << t.ms;
        }
        if (t.device[0] > 0.01 && t.ms < 1000) { // moving: at the end it rests
            EXPECT_LT(t.force[0], 0) << t.ms;    // drag against +x
        }
    }
}

TEST(ForceModelHardCases, VeryLargeAndVerySmallScalesBehaveAlike) {
    for (double scale : {1e-4, 1e4}) {
        SCOPED_TRACE(scale);
        char r2[32];
        std::snprintf(r2, sizeof r2, "%.17g", scale * scale);
        const auto r = probe(test::tangibleScene(std::string(r2) + " - x*x - y*y - z*z",
                                                 {.friction = "0"}, 2 * scale),
                             {{0, 0, 1.5 * scale}, {0, 0, 0.999 * scale}});
        EXPECT_EQ(last(r).contact, ContactKind::Surface);
        EXPECT_NEAR(last(r).proxy[2] / scale, 1.0, 1e-9);
    }
}

TEST(ForceModel, AScenesWithNothingTangibleHasAnEmptySnapshot) {
    const auto scene = test::readScene(
        "#X3D V3.3 utf8\nPROFILE Immersive\nFShape { geometry FGeometry { definition \"1 - "
        "x*x - y*y - z*z\" } }\n");
    EXPECT_TRUE(makeTangibleScene(*scene, 0).empty());
}
