// The accuracy sweep's summary (measure/accuracy_sweep.h): each method's time
// at the finest error both reach is read off its own log-log line, whichever
// method sets that error.
#include "measure/accuracy_sweep.h"

#include <gtest/gtest.h>

#include <cmath>

using fl::measure::AccuracyRow;
using fl::measure::Method;

namespace {

AccuracyRow row(Method method, double resolution, double ms, double error) {
    AccuracyRow r;
    r.method = method;
    r.resolution = resolution;
    r.milliseconds = ms;
    r.maxError = error;
    r.evaluations = 1;
    return r;
}

} // namespace

TEST(AccuracySummary, TheLimitedMethodKeepsItsRowTheOtherIsInterpolated) {
    // The adaptive mesher stops at 2.5e-6 (its budget); dense goes finer.
    const std::vector<AccuracyRow> rows = {
        row(Method::Adaptive, 100, 10, 1e-5), row(Method::Dense, 100, 100, 4e-6),
        row(Method::Adaptive, 200, 40, 2.5e-6), row(Method::Dense, 200, 800, 1e-6)};
    EXPECT_DOUBLE_EQ(*fl::measure::timeAtError(rows, Method::Adaptive, 2.5e-6), 40);
    const double dense = *fl::measure::timeAtError(rows, Method::Dense, 2.5e-6);
    // log-log between (4e-6, 100 ms) and (1e-6, 800 ms) at 2.5e-6.
    const double s = std::log(4e-6 / 2.5e-6) / std::log(4.0);
    EXPECT_NEAR(dense, 100 * std::pow(8.0, s), 1e-9);
    const std::string summary = fl::measure::accuracySummary(rows);
    EXPECT_NE(summary.find("interpolated at that error: adaptive 40.0 ms"), std::string::npos)
        << summary;
    EXPECT_FALSE(fl::measure::timeAtError(rows, Method::Dense, 1e-7)); // never reached
}

TEST(AccuracySummary, EvaluationsAtDense256sErrorAreReadOffTheAdaptiveLine) {
    std::vector<AccuracyRow> rows = {row(Method::Adaptive, 128, 10, 4e-6),
                                     row(Method::Adaptive, 256, 40, 1e-6),
                                     row(Method::Dense, 256, 50, 2e-6)};
    rows[0].evaluations = 1000;
    rows[1].evaluations = 4000;
    rows[2].evaluations = 17000;
    // Halfway (in log error) from 4e-6 to 1e-6: halfway from 1000 to 4000 in log.
    EXPECT_NEAR(*fl::measure::evaluationsAtError(rows, Method::Adaptive, 2e-6), 2000, 1e-9);
    const std::string summary = fl::measure::accuracySummary(rows);
    EXPECT_NE(
        summary.find("at dense 256's error (2.00e-06): adaptive 2000 evaluations, dense 17000 "
                     "(8.5x fewer)"),
        std::string::npos)
        << summary;
}
