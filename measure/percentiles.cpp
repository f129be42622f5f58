#include "measure/percentiles.h"

#include <algorithm>

namespace fl::measure {
namespace {

double atRank(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0;
    q = std::clamp(q, 0.0, 1.0);
    return sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size() - 1) + 0.5))];
}

} // namespace

double percentile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    return atRank(values, q);
}

Spread spreadOf(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return {atRank(values, 0.5), atRank(values, 0.95), atRank(values, 0.99), atRank(values, 0.999),
            atRank(values, 1)};
}

} // namespace fl::measure
