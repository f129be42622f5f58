// The real-time servo loop (haptics/servo_loop.h) with the mouse's device:
// it takes snapshots from another thread, ramps in, renders the surface,
// publishes its status, and lets go when stopped or when the device falls
// silent. Nothing here is timed: waits are bounded, figures are not asserted.
#include "force_test_scenes.h"

#include "haptics/device/device_limits.h"
#include "haptics/pointer_device.h"
#include "haptics/servo_loop.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

using namespace fl;
using namespace fl::haptics;

namespace {

// Waits (at most 20 s) until `done` says so.
template <class F>
bool waitFor(F done) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < until) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

// A device that answers until told to fall silent.
class FallsSilent : public PointerDevice {
  public:
    using PointerDevice::PointerDevice;
    std::atomic<bool> silent{false};
    std::optional<DeviceState> read() override {
        if (silent) return std::nullopt;
        return PointerDevice::read();
    }
};

std::shared_ptr<const TangibleScene> ball() {
    const auto scene =
        test::readScene(test::tangibleScene("1 - x*x - y*y - z*z", {.friction = "0"}));
    return std::make_shared<const TangibleScene>(makeTangibleScene(*scene, 0));
}

} // namespace

TEST(ServoLoop, RendersTheSurfaceItWasHandedAndLetsGoWhenStopped) {
    PointerDevice device(limitsOf(DeviceModel::Simulated));
    ServoOptions o;
    o.rampSeconds = 0.05;
    ServoLoop loop(device, o);
    device.moveTo({0, 0, 1.2}); // outside
    loop.start();
    loop.setScene(ball());
    ASSERT_TRUE(waitFor([&] { return loop.status().ticks > 20; }));
    EXPECT_EQ(loop.status().contact, ContactKind::None);
    device.moveTo({0, 0, 0.999}); // 1 mm into the ball, from above
    ASSERT_TRUE(waitFor([&] {
        const ServoStatus s = loop.status();
        return s.contact == ContactKind::Surface && s.force[2] > 5;
    }));
    const ServoStatus s = loop.status();
    EXPECT_NEAR(s.proxy[2], 1.0, 1e-9);
    EXPECT_LE(field::length(s.force), device.limits().maxForce);
    EXPECT_FALSE(loop.recentForces().empty());
    loop.stop();
    EXPECT_FALSE(loop.running());
    EXPECT_EQ(field::length(device.lastForce()), 0); // it let go
    const JitterFigures j = loop.jitter();
    EXPECT_GT(j.samples, 0u);
    EXPECT_LE(j.p50, j.p99);
    EXPECT_LE(j.p99, j.max);
}

TEST(ServoLoop, ASilentDeviceGetsNoForce) {
    FallsSilent device(limitsOf(DeviceModel::Simulated));
    ServoOptions o;
    o.rampSeconds = 0;
    ServoLoop loop(device, o);
    device.moveTo({0, 0, 1.2});
    loop.setScene(ball());
    loop.start();
    ASSERT_TRUE(waitFor([&] { return loop.status().ticks > 5; }));
    device.moveTo({0, 0, 0.999});
    ASSERT_TRUE(waitFor([&] { return loop.status().force[2] > 5; }));
    device.silent = true;
    ASSERT_TRUE(waitFor([&] { return loop.status().cut == ForceLimiter::Cut::Stale; }));
    EXPECT_EQ(field::length(loop.status().force), 0);
    EXPECT_GT(loop.status().staleReads, 0u);
}

TEST(ServoLoop, JitterPercentilesAreOrderStatistics) {
    std::vector<double> e;
    for (int i = 1; i <= 1000; ++i)
        e.push_back(i);
    const JitterFigures j = jitterOf(e);
    EXPECT_EQ(j.samples, 1000u);
    EXPECT_EQ(j.p50, 501);
    EXPECT_EQ(j.p99, 990);
    EXPECT_EQ(j.p999, 999);
    EXPECT_EQ(j.max, 1000);
    EXPECT_EQ(jitterOf({}).samples, 0u);
}
