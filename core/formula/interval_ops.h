#pragma once
// The interval operations every formula is made of (add, sub, mul, square,
// neg, min, max) and the outward rounding they share, inline: the interval
// evaluator runs them in its loop without a call (an octree asks millions of
// intervals of formulas of a dozen steps, and the call, the dispatch and the
// copies cost more than the arithmetic), and iv::binary / iv::unary run the
// same code for everyone else (interval.cpp) — one definition of each.
#include "interval.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fl::formula::iv {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// `ulps` steps of std::nextafter towards +inf (dir 1) or -inf (dir -1): the
// rare cases (zero, subnormals, infinities), out of line.
double stepByNextafter(double x, int ulps, int dir);

// The same, bit for bit: for finite numbers away from zero a step is one unit
// of the bit pattern (libm's nextafter is a slow call).
[[gnu::always_inline]] inline double step(double x, int ulps, int dir) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const std::uint64_t magnitude = bits & 0x7FFF'FFFF'FFFF'FFFFull;
    if (std::isfinite(x) && magnitude > std::uint64_t(ulps)) {
        const bool away = (x > 0) == (dir > 0); // moving away from zero grows the magnitude
        const double r =
            std::bit_cast<double>(away ? bits + std::uint64_t(ulps) : bits - std::uint64_t(ulps));
        return std::isnan(r) ? (x > 0 ? kInf : -kInf) : r; // past the largest double: infinity
    }
    return stepByNextafter(x, ulps, dir);
}
[[gnu::always_inline]] inline double down(double x, int ulps = 2) {
    return step(x, ulps, -1);
}
[[gnu::always_inline]] inline double up(double x, int ulps = 2) {
    return step(x, ulps, 1);
}

// A result from computed endpoints: widened outward, and everything if an
// endpoint came out NaN (inf - inf, 0 * inf …).
[[gnu::always_inline]] inline Interval make(double lo, double hi, bool nan, int ulps = 2) {
    if (std::isnan(lo) || std::isnan(hi)) return Interval::entire(true);
    return {down(lo, ulps), up(hi, ulps), nan};
}
// Endpoints that are exact (min, max, floor, negation): no widening.
inline Interval exact(double lo, double hi, bool nan) {
    if (std::isnan(lo) || std::isnan(hi)) return Interval::entire(true);
    return {lo, hi, nan};
}

// For results that are never negative (squares, even powers, norms) the
// outward widening must not push the lower end below 0.
inline Interval nonNegative(Interval r) {
    if (!r.empty()) r.lo = std::max(r.lo, 0.0);
    return r;
}

// A sum or difference that rounds to exactly 0 was exact (results below the
// smallest subnormal cannot round to 0), so a 0 endpoint needs no widening.
[[gnu::always_inline]] inline Interval makeSum(double lo, double hi, bool nan) {
    Interval r = make(lo, hi, nan);
    if (lo == 0.0) r.lo = 0.0;
    if (hi == 0.0) r.hi = 0.0;
    return r;
}

inline bool hasInf(const Interval& a) {
    return std::isinf(a.lo) || std::isinf(a.hi);
}

// The operations, with what an operand without values (only NaN) gives.

// inf - inf inside the boxes is NaN even when the endpoint sums are not.
[[gnu::always_inline]] inline Interval add(const Interval& a, const Interval& b) {
    if (a.empty() || b.empty()) return Interval::undefined();
    return makeSum(a.lo + b.lo, a.hi + b.hi,
                   a.nan || b.nan || (a.hi == kInf && b.lo == -kInf) ||
                       (a.lo == -kInf && b.hi == kInf));
}
[[gnu::always_inline]] inline Interval sub(const Interval& a, const Interval& b) {
    if (a.empty() || b.empty()) return Interval::undefined();
    return makeSum(a.lo - b.hi, a.hi - b.lo,
                   a.nan || b.nan || (a.hi == kInf && b.hi == kInf) ||
                       (a.lo == -kInf && b.lo == -kInf));
}
// The product of two intervals with values.
[[gnu::always_inline]] inline Interval mulValues(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    for (double v : p)
        if (std::isnan(v)) return Interval::entire(true);
    // 0 * inf inside the boxes is NaN even when no corner product is
    const bool zeroTimesInf = (a.containsZero() && hasInf(b)) || (b.containsZero() && hasInf(a));
    return make(std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]}),
                a.nan || b.nan || zeroTimesInf);
}
[[gnu::always_inline]] inline Interval mul(const Interval& a, const Interval& b) {
    if (a.empty() || b.empty()) return Interval::undefined();
    return mulValues(a, b);
}
[[gnu::always_inline]] inline Interval min(const Interval& a, const Interval& b) {
    if (a.empty() || b.empty()) return Interval::undefined();
    return exact(std::min(a.lo, b.lo), std::min(a.hi, b.hi), a.nan || b.nan);
}
[[gnu::always_inline]] inline Interval max(const Interval& a, const Interval& b) {
    if (a.empty() || b.empty()) return Interval::undefined();
    return exact(std::max(a.lo, b.lo), std::max(a.hi, b.hi), a.nan || b.nan);
}
[[gnu::always_inline]] inline Interval neg(const Interval& a) {
    if (a.empty()) return Interval::undefined();
    return exact(-a.hi, -a.lo, a.nan);
}
[[gnu::always_inline]] inline Interval square(const Interval& a) {
    if (a.empty()) return Interval::undefined();
    const double l2 = a.lo * a.lo, h2 = a.hi * a.hi;
    if (a.containsZero()) return nonNegative(make(0.0, std::max(l2, h2), a.nan));
    return nonNegative(make(std::min(l2, h2), std::max(l2, h2), a.nan));
}

} // namespace fl::formula::iv
