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

// Beyond this magnitude p + h could overflow: R-functions are positively
// homogeneous, so the arguments are scaled by an exact power of two and the
// result scaled back (overflowing only when the true value does).
constexpr double kRScaleAbove = 0x1p1000;

inline double rIntersect0(double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return a + b;
    if ((std::abs(a) > kRScaleAbove || std::abs(b) > kRScaleAbove) && std::isfinite(a) &&
        std::isfinite(b))
        return 0x1p32 * rIntersect0(a * 0x1p-32, b * 0x1p-32);
    double p = std::max(a, b), q = std::min(a, b);
    double h = std::hypot(a, b);
    if (std::isinf(h)) {
        // at least one infinity: the R-function tends to min(a, b) or its sign
        if (std::isinf(p) && p > 0) return q; // +inf with q: inside-ness decided by q
        return -INFINITY;                     // -inf present: outside
    }
    if (p > 0) return q * (1.0 - q / (p + h));
    return a + b - h; // all terms <= 0: no cancellation
}

inline double rUnion0(double a, double b) {
    return -rIntersect0(-a, -b);
}

// The R_alpha family: alpha in (-1, 1]; alpha = 0 is R0, alpha = 1 is min/max.
inline double rIntersectAlpha(double a, double b, double alpha) {
    if (alpha == 0.0) return rIntersect0(a, b);
    if (alpha >= 1.0) return minPropagating(a, b);
    if (std::isnan(a) || std::isnan(b)) return a + b;
    if ((std::abs(a) > kRScaleAbove || std::abs(b) > kRScaleAbove) && std::isfinite(a) &&
        std::isfinite(b))
        return 0x1p32 * rIntersectAlpha(a * 0x1p-32, b * 0x1p-32, alpha);
    double p = std::max(a, b), q = std::min(a, b);
    // a^2 + b^2 - 2 alpha a b, scaled to avoid overflow
    double s = std::max(std::abs(a), std::abs(b));
    if (s == 0.0) return 0.0;
    if (std::isinf(s)) return rIntersect0(a, b);
    double as = a / s, bs = b / s;
    double h = s * std::sqrt(std::max(0.0, as * as + bs * bs - 2.0 * alpha * as * bs));
    double r;
    if (p > 0) {
        // p - h = (p^2 - h^2) / (p + h) = (2 alpha p q - q^2) / (p + h)
        r = q + (q / (p + h)) * (2.0 * alpha * p - q);
    } else {
        r = a + b - h;
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
