#pragma once
// Rvachev functions (R-functions) in forms that stay accurate for any input.
//
//   R0 intersection  a + b - sqrt(a^2 + b^2)          runion: a + b + sqrt(a^2 + b^2)
//   C^m variants     R0 * (a^2 + b^2)^(m/2)
//   R_alpha          (a + b -/+ sqrt(a^2 + b^2 - 2 alpha a b)) / (1 + alpha)
//
// The textbook form loses everything when one argument dwarfs the other
// (1e8 and 1e-8 gives 0 or even the wrong sign) and overflows when a^2 does
// (1e200). With p = max(a, b), q = min(a, b), h = hypot(a, b) and p > 0,
// p - h = -q^2 / (p + h), so a + b - h = q * (1 - q / (p + h)): a sum of two
// terms of one sign and a ratio bounded by 1, hence no cancellation, no overflow.
#include "minmax.h"

#include <algorithm>
#include <cmath>

namespace fl::formula {

inline double rIntersect0(double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return a + b;
    double p = std::max(a, b), q = std::min(a, b);
    if (std::isinf(a) || std::isinf(b)) {
        // the R-function tends to min(a, b) or its sign
        if (std::isinf(p) && p > 0) return q; // +inf with q: inside-ness decided by q
        return -INFINITY;                     // -inf present: outside
    }
    if (p > 0) {
        // in halves, so that p + h cannot overflow near the largest double;
        // halving is exact, and only the negligible q/2 of a subnormal q rounds
        double halfH = std::hypot(0.5 * a, 0.5 * b);
        return q * (1.0 - (0.5 * q) / (0.5 * p + halfH));
    }
    return a + b - std::hypot(a, b); // all terms <= 0: no cancellation
}

inline double rUnion0(double a, double b) {
    return -rIntersect0(-a, -b);
}

// The R_alpha family: alpha in (-1, 1]; alpha = 0 is R0, alpha = 1 is min/max.
inline double rIntersectAlpha(double a, double b, double alpha) {
    if (alpha == 0.0) return rIntersect0(a, b);
    if (alpha >= 1.0) return minPropagating(a, b);
    if (std::isnan(a) || std::isnan(b)) return a + b;
    if (std::isinf(a) || std::isinf(b)) return rIntersect0(a, b);
    double p = std::max(a, b), q = std::min(a, b);
    // a^2 + b^2 - 2 alpha a b, scaled to avoid overflow; h/2 as in rIntersect0
    double s = std::max(std::abs(a), std::abs(b));
    if (s == 0.0) return 0.0;
    double as = a / s, bs = b / s;
    double halfH = (0.5 * s) * std::sqrt(std::max(0.0, as * as + bs * bs - 2.0 * alpha * as * bs));
    double r;
    if (p > 0) {
        // p - h = (p^2 - h^2) / (p + h) = q (2 alpha p - q) / (p + h)
        r = q + (q / (0.5 * p + halfH)) * (alpha * p - 0.5 * q);
    } else {
        r = a + b - 2.0 * halfH;
    }
    return r / (1.0 + alpha);
}

inline double rUnionAlpha(double a, double b, double alpha) {
    return -rIntersectAlpha(-a, -b, alpha);
}

// C^m smoothing factor (a^2 + b^2)^(m/2), computed as hypot^m.
inline double rFactor(double a, double b, double m) {
    if (m == 0.0) return 1.0;
    return std::pow(std::hypot(a, b), m);
}

inline double rIntersect(double a, double b, double m, double alpha) {
    double r = rIntersectAlpha(a, b, alpha);
    if (m == 0.0 || r == 0.0 || std::isnan(r)) return r;
    return r * rFactor(a, b, m);
}

inline double rUnion(double a, double b, double m, double alpha) {
    double r = rUnionAlpha(a, b, alpha);
    if (m == 0.0 || r == 0.0 || std::isnan(r)) return r;
    return r * rFactor(a, b, m);
}

} // namespace fl::formula
