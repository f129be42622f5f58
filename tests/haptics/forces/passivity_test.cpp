// A closed haptic path gains no energy (passivity): a hand drives the
// simulated tool round closed paths into and out of tangible shapes; the
// work the rendered forces do on the tool over each loop is at most what the
// sampling costs (a hair above zero), whatever the friction, tension and
// density.
#include "force_test_scenes.h"

#include "haptics/device/simulated_device.h"
#include "haptics/force_limiter.h"
#include "haptics/force_model.h"

#include <gtest/gtest.h>

#include <random>

using namespace fl;
using namespace fl::haptics;
using fl::haptics::test::Physics;

namespace {

// Runs the servo loop at 1 kHz with a hand holding the tool along `points`
// (closed: back to the first) for `seconds`; returns the work done on the tool.
double workOverLoop(const scene::Scene& scene, std::vector<field::Vec3> points, double seconds) {
    points.push_back(points.front());
    SimulatedDevice device;
    auto path = PolylinePath::make(points, seconds);
    EXPECT_TRUE(path);
    device.holdWithHand(*path);
    ForceModel model(settingsFor(device.limits(), 1000));
    model.setScene(std::make_shared<const TangibleScene>(makeTangibleScene(scene, 0)));
    LimiterSettings ls;
    ls.maxForce = device.limits().maxForce;
    ls.rampSeconds = 0;
    ForceLimiter limiter(ls);
    const int ticks = int(seconds * 1000) + 200; // and a rest at the end
    for (int k = 0; k <= ticks; ++k) {
        const double t = k / 1000.0;
        device.setTime(t);
        const auto s = device.read();
        if (!s) continue;
        const ForceSample f = model.tick({s->position, s->velocity, {}});
        device.command(limiter.limit(f.force, t), {});
    }
    return device.forceWork();
}

} // namespace

TEST(Passivity, AClosedPathIntoAFrictionlessBallGainsNoEnergy) {
    const auto scene =
        test::readScene(test::tangibleScene("1 - x*x - y*y - z*z", {.friction = "0"}));
    const double w = workOverLoop(*scene, {{0, 0, 1.3}, {0, 0, 0.95}, {0.2, 0, 0.95}}, 1);
    EXPECT_LE(w, 1e-4) << w; // joules
}

TEST(Passivity, RandomClosedPathsThroughEveryEffectGainNoEnergy) {
    // Friction, a tension the hand can beat, density and a swirling force
    // field (not conservative, but held inside its container: the hand does
    // the work of crossing it) — 20 random loops.
    const auto rough = test::readScene(test::tangibleScene(
        "1 - x*x - y*y - z*z",
        {.friction = "0.3 + 0.2*sin(5*x)", .tension = "0.12", .density = "0.5 + 0.5*cos(3*y)"}));
    std::mt19937 random(19);
    std::uniform_real_distribution<double> u(-1.4, 1.4);
    for (int loop = 0; loop < 20; ++loop) {
        std::vector<field::Vec3> points;
        for (int k = 0; k < 4; ++k)
            points.push_back({u(random), u(random), u(random)});
        const double w = workOverLoop(*rough, points, 2);
        EXPECT_LE(w, 1e-3) << "loop " << loop << ": " << w << " J gained";
    }
}
