#include "interval.h"

#include "interval_ops.h"

#include "noise.h"
#include "rfunctions.h"
#include "scalar_ops.h"
#include "vector_math.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numbers>

namespace fl::formula {

namespace {

using iv::down;
using iv::exact;
using iv::hasInf;
using iv::kInf;
using iv::make;
using iv::nonNegative;
using iv::up;
constexpr double kPi = std::numbers::pi;

// Endpoints come from the same maths routines the point evaluators use.
double V(vmath::Unary f, double x) {
    return vmath::eval(f, x);
}

Interval monotoneUp(vmath::Unary f, const Interval& a, int ulps = 2) {
    return make(V(f, a.lo), V(f, a.hi), a.nan, ulps);
}

// Truth of an interval: 1 = surely true, 0 = surely false, -1 = unknown.
int truthOf(const Interval& a) {
    if (a.empty()) return 0; // only NaN: NaN is false
    if (!a.nan && (a.lo > 0.0 || a.hi < 0.0)) return 1;
    if (a.lo == 0.0 && a.hi == 0.0) return 0;
    return -1;
}
Interval fromTruth(int t) {
    if (t == 1) return {1.0, 1.0, false};
    if (t == 0) return {0.0, 0.0, false};
    return {0.0, 1.0, false};
}

Interval div(const Interval& a, const Interval& b) {
    if (b.containsZero()) return Interval::entire(true);
    double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    for (double v : p)
        if (std::isnan(v)) return Interval::entire(true);
    bool infOverInf = hasInf(a) && hasInf(b);
    return make(*std::min_element(p, p + 4), *std::max_element(p, p + 4),
                a.nan || b.nan || infOverInf);
}

Interval powi(const Interval& a, int n) {
    if (n == 0) return {1.0, 1.0, false}; // pow(x, 0) = 1, even for NaN
    if (n < 0) return div({1.0, 1.0, false}, powi(a, -n));
    double l = ops::powi(a.lo, n), h = ops::powi(a.hi, n);
    // repeated squaring rounds at most log2(n) + popcount(n) times
    int ulps = 2 + 2 * static_cast<int>(std::log2(static_cast<double>(n)) + 1);
    if (n % 2 == 1) return make(l, h, a.nan, ulps);
    if (a.containsZero()) return nonNegative(make(0.0, std::max(l, h), a.nan, ulps));
    return nonNegative(make(std::min(l, h), std::max(l, h), a.nan, ulps));
}

// Range of sin over [lo, hi]: endpoints plus any interior extremum. A
// paired opcode's endpoints come from sincos, as its point values do.
Interval sinRange(const Interval& a, bool cosine, bool paired = false) {
    if (!std::isfinite(a.lo) || !std::isfinite(a.hi) || a.hi - a.lo >= 2.0 * kPi ||
        std::abs(a.lo) > 1e15 || std::abs(a.hi) > 1e15)
        return {-1.0, 1.0, a.nan || std::isinf(a.lo) || std::isinf(a.hi)};
    double fl, fh;
    if (paired) {
        // A pair's two halves come one after the other on the same interval:
        // the second takes the first's endpoints (compared by their bits:
        // sin(-0) is -0).
        thread_local struct {
            std::uint64_t lo = 0, hi = 0;
            bool valid = false;
            vmath::SinCos atLo{}, atHi{};
        } ends;
        const std::uint64_t lo = std::bit_cast<std::uint64_t>(a.lo),
                            hi = std::bit_cast<std::uint64_t>(a.hi);
        if (!ends.valid || ends.lo != lo || ends.hi != hi) {
            ends.lo = lo, ends.hi = hi, ends.valid = true;
            ends.atLo = vmath::sinCos(a.lo);
            ends.atHi = vmath::sinCos(a.hi);
        }
        fl = cosine ? ends.atLo.cos : ends.atLo.sin;
        fh = cosine ? ends.atHi.cos : ends.atHi.sin;
    } else {
        fl = V(cosine ? vmath::Unary::Cos : vmath::Unary::Sin, a.lo);
        fh = V(cosine ? vmath::Unary::Cos : vmath::Unary::Sin, a.hi);
    }
    double lo = std::min(fl, fh), hi = std::max(fl, fh);
    // maxima at phase 0 (cos) / pi/2 (sin), minima half a turn later; a small
    // slack admits an extremum that rounding might place just outside.
    double phaseMax = cosine ? 0.0 : kPi / 2.0;
    double slack = 1e-9 * (1.0 + std::max(std::abs(a.lo), std::abs(a.hi)));
    auto hits = [&](double phase) {
        double k = std::ceil((a.lo - slack - phase) / (2.0 * kPi));
        return phase + 2.0 * kPi * k <= a.hi + slack;
    };
    if (hits(phaseMax)) hi = 1.0;
    if (hits(phaseMax + kPi)) lo = -1.0;
    Interval r = make(lo, hi, a.nan);
    r.lo = std::max(r.lo, -1.0);
    r.hi = std::min(r.hi, 1.0);
    return r;
}

Interval tanRange(const Interval& a) {
    if (!std::isfinite(a.lo) || !std::isfinite(a.hi) || a.hi - a.lo >= kPi)
        return Interval::entire(a.nan || std::isinf(a.lo) || std::isinf(a.hi));
    double slack = 1e-9 * (1.0 + std::max(std::abs(a.lo), std::abs(a.hi)));
    double k = std::ceil((a.lo - slack - kPi / 2.0) / kPi);
    if (kPi / 2.0 + kPi * k <= a.hi + slack) return Interval::entire(a.nan);
    return make(V(vmath::Unary::Tan, a.lo), V(vmath::Unary::Tan, a.hi), a.nan);
}

// Clip to a function's domain [dlo, dhi]: points outside are NaN.
bool clipDomain(Interval& a, double dlo, double dhi) {
    if (a.hi < dlo || a.lo > dhi) return false;
    if (a.lo < dlo) {
        a.lo = dlo;
        a.nan = true;
    }
    if (a.hi > dhi) {
        a.hi = dhi;
        a.nan = true;
    }
    return true;
}

Interval absRange(const Interval& a) {
    if (a.lo >= 0.0) return exact(a.lo, a.hi, a.nan);
    if (a.hi <= 0.0) return exact(-a.hi, -a.lo, a.nan);
    return exact(0.0, std::max(-a.lo, a.hi), a.nan);
}

Interval powGeneral(const Interval& a, const Interval& b) {
    // the compiler turns x^n into PowI only for |n| <= 64; beyond that the
    // point evaluators use pow, and so must its interval
    if (b.lo == b.hi && b.lo == std::trunc(b.lo) && std::abs(b.lo) <= 64.0 && !b.nan)
        return powi(a, static_cast<int>(b.lo));
    Interval m = absRange(a);
    auto P = [](double x, double y) { return vmath::eval(vmath::Binary::Pow, x, y); };
    double c[4] = {P(m.lo, b.lo), P(m.lo, b.hi), P(m.hi, b.lo), P(m.hi, b.hi)};
    bool nan = a.nan || b.nan;
    for (double v : c)
        if (std::isnan(v)) return Interval::entire(true);
    double lo = *std::min_element(c, c + 4), hi = *std::max_element(c, c + 4);
    if (b.containsZero()) {
        lo = std::min(lo, 1.0);
        hi = std::max(hi, 1.0);
    }
    // a base that may be -0 only matters for negative exponents
    // (pow(-0, -1) = -inf); for positive ones it gives 0 like +0
    if (a.lo > 0.0 || (a.lo == 0.0 && b.lo > 0.0)) return make(std::max(lo, 0.0), hi, nan);
    // zero or negative bases: NaN for non-integer exponents, ±|a|^b for
    // integer ones (intervals do not track the sign of 0)
    return make(-hi, hi, true);
}

Interval atan2Range(const Interval& y, const Interval& x) {
    bool nan = y.nan || x.nan;
    // the box touches the origin or crosses the branch cut on the negative x axis
    if ((x.containsZero() && y.containsZero()) || (x.lo < 0.0 && y.containsZero()))
        return make(-kPi, kPi, nan);
    auto A = [](double v, double u) { return vmath::eval(vmath::Binary::Atan2, v, u); };
    double c[4] = {A(y.lo, x.lo), A(y.lo, x.hi), A(y.hi, x.lo), A(y.hi, x.hi)};
    return make(*std::min_element(c, c + 4), *std::max_element(c, c + 4), nan);
}

Interval modRange(const Interval& a, const Interval& b) {
    bool nan = a.nan || b.nan;
    if (!std::isfinite(a.lo) || !std::isfinite(a.hi)) return Interval::entire(true);
    if (b.lo == b.hi && b.lo != 0.0 && std::isfinite(b.lo)) {
        double c = b.lo;
        double kl = std::floor(a.lo / c), kh = std::floor(a.hi / c);
        if (kl == kh && std::abs(kl) < 1e15) {
            double l = ops::mod(a.lo, c), h = ops::mod(a.hi, c);
            if (c > 0 && l <= h) return make(l, h, nan, 4);
            if (c < 0 && h <= l) return make(h, l, nan, 4);
        }
        return c > 0 ? exact(0.0, c, nan) : exact(c, 0.0, nan);
    }
    if (b.lo > 0.0) return exact(0.0, b.hi, nan);
    if (b.hi < 0.0) return exact(b.lo, 0.0, nan);
    return Interval::entire(true);
}

Interval compare(Op op, const Interval& a, const Interval& b) {
    if (a.empty() || b.empty()) return fromTruth(op == Op::NotEqual ? 1 : 0);
    int t = -1;
    switch (op) {
    case Op::Less:
        t = a.hi < b.lo ? 1 : (a.lo >= b.hi ? 0 : -1);
        break;
    case Op::LessEq:
        t = a.hi <= b.lo ? 1 : (a.lo > b.hi ? 0 : -1);
        break;
    case Op::Greater:
        t = a.lo > b.hi ? 1 : (a.hi <= b.lo ? 0 : -1);
        break;
    case Op::GreaterEq:
        t = a.lo >= b.hi ? 1 : (a.hi < b.lo ? 0 : -1);
        break;
    case Op::Equal:
        t = (a.lo == a.hi && b.lo == b.hi && a.lo == b.lo) ? 1
                                                           : (a.hi < b.lo || b.hi < a.lo ? 0 : -1);
        break;
    case Op::NotEqual:
        t = (a.lo == a.hi && b.lo == b.hi && a.lo == b.lo) ? 0
                                                           : (a.hi < b.lo || b.hi < a.lo ? 1 : -1);
        break;
    default:
        break;
    }
    // a NaN point compares false (and NotEqual true)
    if ((a.nan || b.nan) && t != -1) {
        int nanResult = op == Op::NotEqual ? 1 : 0;
        if (t != nanResult) t = -1;
    }
    return fromTruth(t);
}

// R-functions with m = 0 are non-decreasing in both arguments (for alpha in
// (-1, 1]), so the corners give the range; their point values are accurate to
// a few ulps, covered by the wider rounding margin.
Interval rfunction(Op op, const Interval& a, const Interval& b, double m, double alpha) {
    if (a.empty() || b.empty()) return Interval::undefined();
    bool nan = a.nan || b.nan;
    auto r0 = [&](double x, double y) {
        return op == Op::RIntersect ? rIntersectAlpha(x, y, alpha) : rUnionAlpha(x, y, alpha);
    };
    Interval base = make(r0(a.lo, b.lo), r0(a.hi, b.hi), nan, 8);
    if (m == 0.0) return base;
    Interval ha = absRange(a), hb = absRange(b);
    Interval h = make(std::hypot(ha.lo, hb.lo), std::hypot(ha.hi, hb.hi), false);
    h.lo = std::max(h.lo, 0.0);
    Interval factor = make(std::pow(h.lo, m), std::pow(h.hi, m), false, 4);
    factor.lo = std::max(factor.lo, 0.0);
    Interval r = iv::mulValues(base, factor);
    // the scalar form returns exactly 0 whenever the R0 part is 0
    if (base.containsZero()) {
        r.lo = std::min(r.lo, 0.0);
        r.hi = std::max(r.hi, 0.0);
    }
    r.nan = r.nan || nan;
    return r;
}

Interval noiseRange(const Interval& x, const Interval& y, const Interval& z) {
    bool nan = x.nan || y.nan || z.nan;
    if (x.empty() || y.empty() || z.empty()) return Interval::undefined();
    Interval global = {-kNoiseBound, kNoiseBound, nan};
    const Interval* c[3] = {&x, &y, &z};
    double spread = 0.0;
    double centre[3];
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(c[i]->lo) || !std::isfinite(c[i]->hi)) return global;
        centre[i] = 0.5 * c[i]->lo + 0.5 * c[i]->hi;
        spread += 0.5 * (c[i]->hi - c[i]->lo);
    }
    double v = noise3(centre[0], centre[1], centre[2]);
    double r = kNoiseLipschitz * spread * (1.0 + 1e-12) + 1e-12;
    return {std::max(-kNoiseBound, v - r), std::min(kNoiseBound, v + r), nan};
}

} // namespace

Interval hull(const Interval& a, const Interval& b) {
    if (a.empty()) return {b.lo, b.hi, b.nan || a.nan};
    if (b.empty()) return {a.lo, a.hi, a.nan || b.nan};
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi), a.nan || b.nan};
}

namespace iv {

[[gnu::noinline]] double stepByNextafter(double x, int ulps, int dir) {
    for (int i = 0; i < ulps; ++i)
        x = std::nextafter(x, dir > 0 ? kInf : -kInf);
    return x;
}

Interval unary(Op op, const Interval& in, double imm0) {
    if (in.empty()) {
        if (op == Op::Not) return {1.0, 1.0, false};                 // NaN is false, so !NaN is 1
        if (op == Op::PowI && imm0 == 0.0) return {1.0, 1.0, false}; // NaN^0 = 1
        return Interval::undefined();
    }
    Interval a = in;
    switch (op) {
    case Op::Neg:
        return neg(a);
    case Op::Abs:
        return absRange(a);
    case Op::Square:
        return iv::square(a);
    case Op::Sqrt:
        if (!clipDomain(a, 0.0, kInf)) return Interval::undefined();
        {
            Interval r = make(std::sqrt(a.lo), std::sqrt(a.hi), a.nan);
            r.lo = std::max(r.lo, 0.0);
            return r;
        }
    case Op::Cbrt:
        return monotoneUp(vmath::Unary::Cbrt, a);
    case Op::Exp: {
        Interval r = monotoneUp(vmath::Unary::Exp, a);
        r.lo = std::max(r.lo, 0.0);
        return r;
    }
    case Op::Log:
    case Op::Log2:
    case Op::Log10: {
        if (!clipDomain(a, 0.0, kInf)) return Interval::undefined();
        vmath::Unary f = op == Op::Log    ? vmath::Unary::Log
                         : op == Op::Log2 ? vmath::Unary::Log2
                                          : vmath::Unary::Log10;
        return monotoneUp(f, a);
    }
    case Op::Sin:
        return sinRange(a, false);
    case Op::Cos:
        return sinRange(a, true);
    case Op::SinOfPair:
        return sinRange(a, false, true);
    case Op::CosOfPair:
        return sinRange(a, true, true);
    case Op::Tan:
        return tanRange(a);
    case Op::Asin:
        if (!clipDomain(a, -1.0, 1.0)) return Interval::undefined();
        return monotoneUp(vmath::Unary::Asin, a);
    case Op::Acos: {
        if (!clipDomain(a, -1.0, 1.0)) return Interval::undefined();
        return make(V(vmath::Unary::Acos, a.hi), V(vmath::Unary::Acos, a.lo), a.nan);
    }
    case Op::Atan:
        return monotoneUp(vmath::Unary::Atan, a);
    case Op::Sinh:
        return monotoneUp(vmath::Unary::Sinh, a);
    case Op::Cosh: {
        double l = V(vmath::Unary::Cosh, a.lo), h = V(vmath::Unary::Cosh, a.hi);
        if (a.containsZero()) return make(1.0, std::max(l, h), a.nan);
        return make(std::min(l, h), std::max(l, h), a.nan);
    }
    case Op::Tanh: {
        Interval r = monotoneUp(vmath::Unary::Tanh, a);
        r.lo = std::max(r.lo, -1.0);
        r.hi = std::min(r.hi, 1.0);
        return r;
    }
    case Op::Floor:
        return exact(std::floor(a.lo), std::floor(a.hi), a.nan);
    case Op::Ceil:
        return exact(std::ceil(a.lo), std::ceil(a.hi), a.nan);
    case Op::Round:
        return exact(std::round(a.lo), std::round(a.hi), a.nan);
    case Op::Sign:
        return exact(ops::sign(a.lo), ops::sign(a.hi), a.nan);
    case Op::Not: {
        int t = truthOf(a);
        return fromTruth(t == -1 ? -1 : 1 - t);
    }
    case Op::PowI:
        return powi(a, static_cast<int>(imm0));
    default:
        break;
    }
    return Interval::entire(true);
}

Interval binary(Op op, const Interval& a, const Interval& b, double imm0, double imm1) {
    switch (op) {
    case Op::Less:
    case Op::LessEq:
    case Op::Greater:
    case Op::GreaterEq:
    case Op::Equal:
    case Op::NotEqual:
        return compare(op, a, b);
    case Op::And:
    case Op::Or: {
        int ta = truthOf(a), tb = truthOf(b);
        if (op == Op::And) {
            if (ta == 0 || tb == 0) return fromTruth(0);
            if (ta == 1 && tb == 1) return fromTruth(1);
        } else {
            if (ta == 1 || tb == 1) return fromTruth(1);
            if (ta == 0 && tb == 0) return fromTruth(0);
        }
        return fromTruth(-1);
    }
    case Op::Pow:
        // IEEE: pow(1, y) = 1 and pow(x, 0) = 1 even when the other is NaN
        if (a.empty() || b.empty()) {
            bool one = (!a.empty() && a.contains(1.0)) || (!b.empty() && b.contains(0.0));
            return one ? Interval{1.0, 1.0, true} : Interval::undefined();
        }
        break;
    case Op::Hypot:
        // IEEE: hypot(±inf, NaN) = +inf
        if (a.empty() || b.empty()) {
            const Interval& other = a.empty() ? b : a;
            bool inf = !other.empty() && (std::isinf(other.lo) || std::isinf(other.hi));
            return inf ? Interval{kInf, kInf, true} : Interval::undefined();
        }
        break;
    default:
        break;
    }
    if (a.empty() || b.empty()) return Interval::undefined();
    bool nan = a.nan || b.nan;
    switch (op) {
    // inf - inf inside the boxes is NaN even when the endpoint sums are not
    case Op::Add:
        return add(a, b);
    case Op::Sub:
        return sub(a, b);
    case Op::Mul:
        return mulValues(a, b);
    case Op::Div:
        return div(a, b);
    case Op::Pow:
        return powGeneral(a, b);
    case Op::Min:
        return iv::min(a, b);
    case Op::Max:
        return iv::max(a, b);
    case Op::Atan2:
        return atan2Range(a, b);
    case Op::Hypot: {
        Interval x = absRange(a), y = absRange(b);
        return nonNegative(make(std::hypot(x.lo, y.lo), std::hypot(x.hi, y.hi), nan));
    }
    case Op::Mod:
        return modRange(a, b);
    case Op::RIntersect:
    case Op::RUnion:
        return rfunction(op, a, b, imm0, imm1);
    default:
        break;
    }
    return Interval::entire(true);
}

Interval ternary(Op op, const Interval& a, const Interval& b, const Interval& c) {
    switch (op) {
    case Op::Select: {
        int t = truthOf(a);
        if (t == 1) return b;
        if (t == 0) return c;
        return hull(b, c);
    }
    case Op::Noise:
        return noiseRange(a, b, c);
    default:
        break;
    }
    return Interval::entire(true);
}

} // namespace iv
} // namespace fl::formula
