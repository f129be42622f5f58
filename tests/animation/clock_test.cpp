// The clocks: an injectable wall clock, the scene timeline (play, pause,
// seek, speed, resync) and the instant every clock reads from.
#include "animation/clock.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fl::animation;

namespace {
constexpr std::int64_t kSecond = kNanosecondsPerSecond;
constexpr std::int64_t kDay = 86'400 * kSecond;
} // namespace

TEST(Clock, InstantReadsEachTimeBase) {
    const Instant i{5 * kSecond, 1'700'000'000 * kSecond, 3600};
    EXPECT_EQ(i.nanosecondsOn(TimeBase::Scene), 5 * kSecond);
    EXPECT_EQ(i.nanosecondsOn(TimeBase::Utc), 1'700'000'000 * kSecond);
    EXPECT_EQ(i.nanosecondsOn(TimeBase::Local), 1'700'003'600 * kSecond);
    EXPECT_DOUBLE_EQ(i.x3dSeconds(), 1.7e9);
}

TEST(Clock, ParseTimeBase) {
    EXPECT_EQ(parseTimeBase("scene"), TimeBase::Scene);
    EXPECT_EQ(parseTimeBase("local"), TimeBase::Local);
    EXPECT_EQ(parseTimeBase("utc"), TimeBase::Utc);
    EXPECT_FALSE(parseTimeBase("UTC").has_value());
}

TEST(Clock, SystemClockIsNearNowAndHasASaneOffset) {
    const WallTime t = SystemWallClock().now();
    EXPECT_GT(t.utcNs, 1'700'000'000 * kSecond); // after November 2023
    EXPECT_LE(std::abs(t.localOffsetSeconds), 14 * 3600);
}

TEST(Timeline, FollowsTheWallClockWhilePlaying) {
    ManualWallClock wall({1'000 * kSecond, -7200});
    SceneTimeline timeline(wall);
    EXPECT_EQ(timeline.now().sceneNs, 0);
    wall.advance(2 * kSecond + 1);
    const Instant i = timeline.now();
    EXPECT_EQ(i.sceneNs, 2 * kSecond + 1);
    EXPECT_EQ(i.utcNs, 1'002 * kSecond + 1);
    EXPECT_EQ(i.localOffsetSeconds, -7200);
}

TEST(Timeline, PauseFreezesEveryClockAndPlayGoesOn) {
    ManualWallClock wall({1'000 * kSecond, 0});
    SceneTimeline timeline(wall);
    wall.advance(3 * kSecond);
    timeline.pause();
    wall.advance(10 * kSecond);
    EXPECT_EQ(timeline.now().sceneNs, 3 * kSecond);
    EXPECT_EQ(timeline.now().utcNs, 1'003 * kSecond); // the wall clock of the scene froze too
    timeline.play();
    wall.advance(kSecond);
    EXPECT_EQ(timeline.now().sceneNs, 4 * kSecond);
    EXPECT_EQ(timeline.now().utcNs, 1'004 * kSecond); // ten seconds behind the real clock now
    timeline.resync();
    EXPECT_EQ(timeline.now().sceneNs, 4 * kSecond);
    EXPECT_EQ(timeline.now().utcNs, 1'014 * kSecond); // back on real time
}

TEST(Timeline, SeekAndSpeed) {
    ManualWallClock wall({0, 0});
    SceneTimeline timeline(wall);
    timeline.seek(10 * kSecond);
    EXPECT_EQ(timeline.now().sceneNs, 10 * kSecond);
    timeline.setSpeed(0.5);
    wall.advance(4 * kSecond);
    EXPECT_EQ(timeline.now().sceneNs, 12 * kSecond);
    timeline.setSpeed(0);  // refused: stays at 0.5
    timeline.setSpeed(-1); // refused
    EXPECT_EQ(timeline.speed(), 0.5);
    timeline.pause();
    timeline.seek(1 * kSecond); // scrubbing while paused
    wall.advance(kSecond);
    EXPECT_EQ(timeline.now().sceneNs, 1 * kSecond);
}

TEST(Timeline, KeepsNanosecondsAfterWeeksOfRunning) {
    ManualWallClock wall({1'763'800'000 * kSecond, 0});
    SceneTimeline timeline(wall);
    wall.advance(21 * kDay + 1); // three weeks and one nanosecond
    EXPECT_EQ(timeline.now().sceneNs, 21 * kDay + 1);
    EXPECT_EQ(timeline.now().utcNs, 1'763'800'000 * kSecond + 21 * kDay + 1);
}

TEST(Clock, SaturatingConversions) {
    EXPECT_EQ(secondsToNanoseconds(1.5), 1'500'000'000);
    EXPECT_EQ(secondsToNanoseconds(-2), -2 * kSecond);
    EXPECT_EQ(secondsToNanoseconds(-0.5), -kSecond / 2);
    // Today's X3D times (seconds since 1970 in a double) convert without the
    // 256 ns rounding a single multiplication would give.
    EXPECT_EQ(secondsToNanoseconds(1'795'000'001.0), 1'795'000'001 * kSecond);
    EXPECT_EQ(secondsToNanoseconds(1'795'000'001.25), 1'795'000'001 * kSecond + kSecond / 4);
    EXPECT_EQ(secondsToNanoseconds(1e300), std::int64_t(9.2e18));
    EXPECT_EQ(secondsToNanoseconds(-1e300), -std::int64_t(9.2e18));
    EXPECT_EQ(secondsToNanoseconds(std::nan("")), 0);
    EXPECT_EQ(saturatingSubtract(INT64_MIN, 1), INT64_MIN);
    EXPECT_EQ(saturatingSubtract(INT64_MAX, -1), INT64_MAX);
}
