// Leases, grace after a disconnect, the rate limit and the failed-join
// throttle, all on a ManualClock: no sleeps.
#include "classroom/rate_limit.h"
#include "classroom/scene_lock.h"

#include <gtest/gtest.h>

namespace fl::classroom {
namespace {

TEST(SceneLock, LeaseExpiresWithoutRenewal) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000);
    lock.grant(1, clock.now());
    EXPECT_TRUE(lock.heldByOther(2, clock.now()));
    EXPECT_FALSE(lock.heldByOther(1, clock.now()));
    clock.advance(9'999);
    EXPECT_TRUE(lock.holder(clock.now()).has_value());
    clock.advance(1);
    EXPECT_FALSE(lock.holder(clock.now()).has_value());
}

TEST(SceneLock, AnotherEditRenewsIt) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000);
    lock.grant(1, clock.now());
    clock.advance(8'000);
    lock.grant(1, clock.now()); // the holder's next edit
    clock.advance(8'000);
    EXPECT_EQ(lock.holder(clock.now())->member, 1u);
}

TEST(SceneLock, ReleaseOnlyByTheHolder) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000);
    lock.grant(1, clock.now());
    EXPECT_FALSE(lock.release(2));
    EXPECT_TRUE(lock.release(1));
    EXPECT_FALSE(lock.holder(clock.now()).has_value());
}

TEST(SceneLock, DisconnectedHolderKeepsItForTheGrace) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000);
    lock.grant(1, clock.now());
    clock.advance(5'000);
    lock.disconnected(1, clock.now());
    clock.advance(19'000);
    EXPECT_TRUE(lock.heldByOther(2, clock.now()));
    clock.advance(1'000);
    EXPECT_FALSE(lock.holder(clock.now()).has_value());
}

TEST(SceneLock, ReconnectWithinTheGraceKeepsIt) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000);
    lock.grant(1, clock.now());
    lock.disconnected(1, clock.now());
    clock.advance(15'000);
    lock.reconnected(1, clock.now()); // a fresh lease from now
    clock.advance(9'000);
    EXPECT_EQ(lock.holder(clock.now())->member, 1u);
}

TEST(SceneLock, GrantTakesItFromAnyone) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000);
    lock.grant(1, clock.now());
    lock.grant(9, clock.now());
    EXPECT_EQ(lock.holder(clock.now())->member, 9u);
    lock.breakLock(clock.now(), false);
    EXPECT_FALSE(lock.holder(clock.now()).has_value());
    EXPECT_FALSE(lock.coolingDown(9, clock.now()));
}

TEST(SceneLock, ABrokenHolderWaitsBeforeTakingItAgain) {
    ManualClock clock;
    SceneLock lock(10'000, 20'000, 30'000);
    lock.grant(4, clock.now());
    lock.breakLock(clock.now(), true);
    EXPECT_TRUE(lock.coolingDown(4, clock.now()));
    EXPECT_FALSE(lock.coolingDown(5, clock.now()));
    clock.advance(29'999);
    EXPECT_TRUE(lock.coolingDown(4, clock.now()));
    clock.advance(1);
    EXPECT_FALSE(lock.coolingDown(4, clock.now()));
}

TEST(RateLimit, BucketEmptiesAndRefills) {
    ManualClock clock;
    TokenBucket bucket(3, 2, clock.now());
    EXPECT_TRUE(bucket.take(clock.now()));
    EXPECT_TRUE(bucket.take(clock.now()));
    EXPECT_TRUE(bucket.take(clock.now()));
    EXPECT_FALSE(bucket.take(clock.now()));
    clock.advance(499);
    EXPECT_FALSE(bucket.take(clock.now()));
    clock.advance(1);
    EXPECT_TRUE(bucket.take(clock.now()));
    clock.advance(60'000); // never more than the burst
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(bucket.take(clock.now()));
    EXPECT_FALSE(bucket.take(clock.now()));
}

TEST(RateLimit, FailedJoinsBlockAnAddressForTheWindow) {
    ManualClock clock;
    FailedJoinThrottle throttle(3, 60'000);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(throttle.blocked("10.0.0.1", clock.now()));
        throttle.failed("10.0.0.1", clock.now());
    }
    EXPECT_TRUE(throttle.blocked("10.0.0.1", clock.now()));
    EXPECT_FALSE(throttle.blocked("10.0.0.2", clock.now()));
    clock.advance(60'000);
    EXPECT_FALSE(throttle.blocked("10.0.0.1", clock.now()));
}

} // namespace
} // namespace fl::classroom
