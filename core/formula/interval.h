#pragma once
// Conservative interval arithmetic: every operation returns an interval that
// contains the result for every point of its operand intervals, as computed in
// double precision by the scalar evaluator (endpoints come from the same
// maths routines — SLEEF, <= 1 ulp — and are widened outward by two ulps).
//
// `nan` records that some point of the box may evaluate to NaN (outside a
// function's domain, 0/0, inf - inf). When no point has a numeric value the
// interval is empty (lo > hi) with nan set.
#include "opcodes.h"

#include <cmath>
#include <limits>

namespace fl::formula {

struct Interval {
    double lo = 0.0;
    double hi = 0.0;
    bool nan = false;

    static Interval point(double v) {
        if (std::isnan(v)) return undefined();
        return {v, v, false};
    }
    static Interval of(double lo, double hi, bool nan = false) { return {lo, hi, nan}; }
    static Interval entire(bool nan = true) {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                nan};
    }
    static Interval undefined() {
        return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                true};
    }
    bool empty() const { return lo > hi; }
    bool contains(double v) const {
        if (std::isnan(v)) return nan;
        return lo <= v && v <= hi;
    }
    bool containsZero() const { return lo <= 0.0 && hi >= 0.0; }
    double width() const { return hi - lo; }
};

Interval hull(const Interval& a, const Interval& b);

namespace iv {
Interval unary(Op op, const Interval& a, double imm0);
Interval binary(Op op, const Interval& a, const Interval& b, double imm0, double imm1);
Interval ternary(Op op, const Interval& a, const Interval& b, const Interval& c);
} // namespace iv

} // namespace fl::formula
