#pragma once
// Percentiles by nearest rank, the one way every measurement of the program
// reports a spread (force ticks, loop jitter, grading times, class delivery):
// the value at rank round(q * (n - 1)) of the sorted values.
#include <vector>

namespace fl::measure {

// 0 for no values; q in [0, 1] (1: the largest).
double percentile(std::vector<double> values, double q);

struct Spread {
    double p50 = 0, p95 = 0, p99 = 0, p999 = 0, max = 0;
};
Spread spreadOf(std::vector<double> values); // sorts once

} // namespace fl::measure
