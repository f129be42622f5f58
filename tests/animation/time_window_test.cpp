// X3D time-dependent node rules (ISO/IEC 19775-1 §8.2.4) and the function
// nodes' t: start, stop, loop, cycle ends reading 1, and exact fractions
// however long a scene runs.
#include "animation/clock.h"
#include "animation/time_window.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fl::animation;

namespace {
constexpr std::int64_t kSecond = kNanosecondsPerSecond;
constexpr std::int64_t kDay = 86'400 * kSecond;
} // namespace

TEST(CycleFraction, WholeNanosecondCyclesAreExact) {
    std::int64_t cycles = 0;
    EXPECT_EQ(cycleFraction(0, 60, &cycles), 0);
    EXPECT_EQ(cycles, 0);
    EXPECT_DOUBLE_EQ(cycleFraction(15 * kSecond, 60, &cycles), 0.25);
    // The end of a cycle reads 1 (X3D), not 0 of the next.
    EXPECT_EQ(cycleFraction(60 * kSecond, 60, &cycles), 1.0);
    EXPECT_EQ(cycles, 0);
    EXPECT_DOUBLE_EQ(cycleFraction(61 * kSecond, 60, &cycles), 1.0 / 60);
    EXPECT_EQ(cycles, 1);
}

TEST(CycleFraction, ThreeWeeksOnTheWallClockLoseNothing) {
    // UTC now is ~1.76e18 ns: a double of seconds would resolve 0.2 us; the
    // fraction of a 60 s cycle must still see a single nanosecond.
    const std::int64_t midnight = 20'410 * kDay; // 2025-11-18 00:00 UTC
    const std::int64_t a = midnight + 21 * kDay + 15 * kSecond;
    EXPECT_DOUBLE_EQ(cycleFraction(a, 60), 0.25);
    EXPECT_NEAR(cycleFraction(a + 1, 60) - 0.25, 1.0 / 60e9, 1e-16); // one ulp of 0.25 is 5.6e-17
}

TEST(CycleFraction, CyclesThatAreNotWholeNanosecondsStayAccurate) {
    const double cycle = 0.1 + 1e-12; // not a whole number of nanoseconds
    const std::int64_t elapsed = 21 * kDay + 50'000'000;
    std::int64_t cycles = 0;
    const double f = cycleFraction(elapsed, cycle, &cycles);
    const long double exact =
        static_cast<long double>(elapsed) / (static_cast<long double>(cycle) * 1e9L);
    EXPECT_EQ(cycles, static_cast<std::int64_t>(std::floor(exact)));
    EXPECT_NEAR(f, double(exact - std::floor(exact)), 1e-9);
}

TEST(CycleFraction, PropertyFractionAndCyclesRebuildTheElapsedTime) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<std::int64_t> elapsedDist(1, 400 * kDay);
    std::uniform_real_distribution<double> cycleDist(1e-3, 1e5);
    for (int i = 0; i < 2000; ++i) {
        const std::int64_t elapsed = elapsedDist(rng);
        const double cycle = i % 2 ? cycleDist(rng) : std::round(cycleDist(rng));
        std::int64_t cycles = 0;
        const double f = cycleFraction(elapsed, cycle, &cycles);
        ASSERT_GE(f, 0.0);
        ASSERT_LE(f, 1.0);
        ASSERT_GT(f, 0.0); // elapsed > 0: zero becomes one
        const long double rebuilt = (static_cast<long double>(cycles) + f) * cycle * 1e9L;
        ASSERT_NEAR(double(rebuilt - elapsed), 0.0, 1e-6 * cycle * 1e9 + 2)
            << elapsed << " " << cycle;
    }
}

TEST(TimeWindow, BeforeActiveAfterWithoutLoop) {
    const TimeWindow w{10 * kSecond, 0, 4, false};
    EXPECT_EQ(evaluateWindow(w, 9 * kSecond).phase, Phase::Before);
    WindowState s = evaluateWindow(w, 11 * kSecond);
    EXPECT_EQ(s.phase, Phase::Active);
    EXPECT_DOUBLE_EQ(s.fraction, 0.25);
    s = evaluateWindow(w, 14 * kSecond); // one cycle done: inactive, fraction 1
    EXPECT_EQ(s.phase, Phase::After);
    EXPECT_EQ(s.fraction, 1.0);
    EXPECT_EQ(s.endNs, 14 * kSecond);
    s = evaluateWindow(w, 100 * kSecond);
    EXPECT_EQ(s.phase, Phase::After);
    EXPECT_EQ(s.fraction, 1.0);
}

TEST(TimeWindow, StopTimeEndsItAndIsIgnoredWhenNotAfterStart) {
    TimeWindow w{0, 5 * kSecond, 2, true};
    WindowState s = evaluateWindow(w, 7 * kSecond);
    EXPECT_EQ(s.phase, Phase::After);
    EXPECT_DOUBLE_EQ(s.fraction, 0.5); // the fraction at stopTime: 5 s of 2 s cycles
    w.stopNs = 0;                      // stopTime <= startTime: ignored, loops forever
    s = evaluateWindow(w, 7 * kSecond);
    EXPECT_EQ(s.phase, Phase::Active);
    EXPECT_FALSE(s.bounded);
    EXPECT_DOUBLE_EQ(s.fraction, 0.5);
    EXPECT_EQ(s.cycle, 3);
}

TEST(TimeWindow, StopTimeBeforeTheEndOfASingleCycle) {
    const TimeWindow w{0, 1 * kSecond, 4, false};
    const WindowState s = evaluateWindow(w, 3 * kSecond);
    EXPECT_EQ(s.phase, Phase::After);
    EXPECT_DOUBLE_EQ(s.fraction, 0.25);
}

TEST(FunctionTime, MapsCyclesOntoTimeSpanAndFreezesAtTheEnd) {
    const TimeWindow w{2 * kSecond, 0, 4, false};
    EXPECT_EQ(functionTime(w, 1, 3, 0), 1);                    // before: timeSpan[0]
    EXPECT_DOUBLE_EQ(functionTime(w, 1, 3, 3 * kSecond), 1.5); // a quarter
    EXPECT_EQ(functionTime(w, 1, 3, 6 * kSecond), 3);          // end of the one cycle
    EXPECT_EQ(functionTime(w, 1, 3, 60 * kSecond), 3);         // frozen after it
    EXPECT_DOUBLE_EQ(functionTime(w, 3, 1, 3 * kSecond), 2.5); // timeSpan may run backwards
}

TEST(FunctionTime, ClockHandsOnLocalTime) {
    // 12:00:15 local time: the second hand is a quarter round, the minute
    // hand 15 s into its hour, the hour hand at 12 (0 of its 12-hour cycle).
    const std::int64_t noonLocal = 20'410 * kDay + 12 * 3600 * kSecond;
    const Instant now{0, noonLocal + 15 * kSecond - 3600 * kSecond, 3600}; // UTC+1
    const std::int64_t local = now.nanosecondsOn(TimeBase::Local);
    EXPECT_DOUBLE_EQ(functionTime({0, 0, 60, true}, 0, 1, local), 0.25);
    EXPECT_DOUBLE_EQ(functionTime({0, 0, 3600, true}, 0, 1, local), 15.0 / 3600);
    EXPECT_DOUBLE_EQ(functionTime({0, 0, 43200, true}, 0, 1, local), 15.0 / 43200);
}
