#include "eval_gradient.h"

#include "noise.h"
#include "scalar_ops.h"
#include "tape_walk.h"
#include "vector_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::formula {

namespace ad {
namespace {

// f'(a) * da, with 0 * anything = 0 so that a constant operand of a function
// with an infinite derivative (sqrt at 0) keeps a zero gradient.
Dual chain(double value, double fprime, const Dual& a) {
    Dual r;
    r.v = value;
    for (int i = 0; i < 3; ++i)
        r.d[i] = (a.d[i] == 0.0 || fprime == 0.0) ? 0.0 : fprime * a.d[i];
    return r;
}
Dual chain2(double value, double fa, const Dual& a, double fb, const Dual& b) {
    Dual r;
    r.v = value;
    for (int i = 0; i < 3; ++i) {
        double ta = (a.d[i] == 0.0 || fa == 0.0) ? 0.0 : fa * a.d[i];
        double tb = (b.d[i] == 0.0 || fb == 0.0) ? 0.0 : fb * b.d[i];
        r.d[i] = ta + tb;
    }
    return r;
}
Dual constant(double v) {
    Dual r;
    r.v = v;
    return r;
}

// Partial derivatives of the R_alpha intersection (m = 0) at (a, b).
void rIntersectPartials(double a, double b, double alpha, double& da, double& db) {
    if (alpha >= 1.0) { // min: the smaller one's slope, the average at a tie
        da = a < b ? 1.0 : (a == b ? 0.5 : 0.0);
        db = 1.0 - da;
        return;
    }
    double s = std::max(std::abs(a), std::abs(b));
    if (s == 0.0 || !std::isfinite(s)) {
        // not differentiable at the origin: the average of the one-sided slopes
        da = db = 0.5;
        return;
    }
    double as = a / s, bs = b / s;
    double hs = std::sqrt(std::max(0.0, as * as + bs * bs - 2.0 * alpha * as * bs));
    da = (1.0 - (as - alpha * bs) / hs) / (1.0 + alpha);
    db = (1.0 - (bs - alpha * as) / hs) / (1.0 + alpha);
}

Dual rfunction(Op op, const Dual& a, const Dual& b, double m, double alpha) {
    bool uni = op == Op::RUnion;
    double value = uni ? rUnion(a.v, b.v, m, alpha) : rIntersect(a.v, b.v, m, alpha);
    double da, db;
    // union(a, b) = -intersect(-a, -b): same partials, taken at (-a, -b)
    rIntersectPartials(uni ? -a.v : a.v, uni ? -b.v : b.v, alpha, da, db);
    if (m != 0.0) {
        double h = std::hypot(a.v, b.v);
        if (h == 0.0 || !std::isfinite(h)) {
            da = db = 0.0; // the factor h^m flattens the origin (m > 0)
        } else {
            double r0 = uni ? rUnionAlpha(a.v, b.v, alpha) : rIntersectAlpha(a.v, b.v, alpha);
            double hm = std::pow(h, m);
            // d/da [r0 h^m] = r0' h^m + r0 m h^m (a / h^2), arranged to avoid overflow
            double common = m * hm * (r0 / h);
            da = da * hm + common * (a.v / h);
            db = db * hm + common * (b.v / h);
        }
    }
    return chain2(value, da, a, db, b);
}

} // namespace

Dual unary(Op op, const Dual& a, double imm0) {
    const double x = a.v;
    const double v = ops::unary(op, x, imm0);
    switch (op) {
    case Op::Neg:
        return chain(v, -1.0, a);
    case Op::Abs:
        return chain(v, x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0), a);
    case Op::Square:
        return chain(v, 2.0 * x, a);
    case Op::Sqrt:
        return chain(v, 0.5 / v, a);
    case Op::Cbrt:
        return chain(v, 1.0 / (3.0 * v * v), a);
    case Op::Exp:
        return chain(v, v, a);
    case Op::Log:
        return chain(v, 1.0 / x, a);
    case Op::Log2:
        return chain(v, 1.0 / (x * std::numbers::ln2), a);
    case Op::Log10:
        return chain(v, 1.0 / (x * std::numbers::ln10), a);
    // The derivatives through the same SLEEF functions as the values, so
    // evaluateMany's array calls give these bits exactly.
    case Op::Sin:
        return chain(v, vmath::eval(vmath::Unary::Cos, x), a);
    case Op::Cos:
        return chain(v, -vmath::eval(vmath::Unary::Sin, x), a);
    case Op::Tan:
        return chain(v, 1.0 + v * v, a);
    case Op::Asin:
        return chain(v, 1.0 / std::sqrt(1.0 - x * x), a);
    case Op::Acos:
        return chain(v, -1.0 / std::sqrt(1.0 - x * x), a);
    case Op::Atan:
        return chain(v, 1.0 / (1.0 + x * x), a);
    case Op::Sinh:
        return chain(v, std::cosh(x), a);
    case Op::Cosh:
        return chain(v, std::sinh(x), a);
    case Op::Tanh:
        return chain(v, 1.0 - v * v, a);
    case Op::Floor:
    case Op::Ceil:
    case Op::Round:
    case Op::Sign:
    case Op::Not:
        return constant(v);
    case Op::PowI: {
        int n = static_cast<int>(imm0);
        return chain(v, n == 0 ? 0.0 : n * ops::powi(x, n - 1), a);
    }
    default:
        break;
    }
    return constant(v);
}

Dual binary(Op op, const Dual& a, const Dual& b, double imm0, double imm1) {
    const double x = a.v, y = b.v;
    const double v = ops::binary(op, x, y, imm0, imm1); // the scalar evaluator's value, bit for bit
    switch (op) {
    case Op::Add:
        return chain2(x + y, 1.0, a, 1.0, b);
    case Op::Sub:
        return chain2(x - y, 1.0, a, -1.0, b);
    case Op::Mul:
        return chain2(x * y, y, a, x, b);
    case Op::Div:
        return chain2(x / y, 1.0 / y, a, -x / (y * y), b);
    case Op::Pow: {
        double dx = y == 0.0 ? 0.0 : y * std::pow(x, y - 1.0);
        double dy = x > 0.0 ? v * std::log(x) : 0.0; // d/dy undefined for x <= 0
        return chain2(v, dx, a, dy, b);
    }
    case Op::Min:
    case Op::Max: {
        // the chosen operand's gradient; at a tie (a kink) the average of both
        const bool tie = x == y;
        const bool first = op == Op::Min ? (x < y || x != x) : (x > y || x != x);
        if (!tie) return first ? Dual{v, a.d} : Dual{v, b.d};
        return chain2(v, 0.5, a, 0.5, b);
    }
    case Op::Atan2: {
        double r2 = x * x + y * y;
        if (r2 == 0.0) return constant(v);
        return chain2(v, y / r2, a, -x / r2, b);
    }
    case Op::Hypot: {
        double h = std::hypot(x, y);
        if (h == 0.0) return constant(h);
        return chain2(h, x / h, a, y / h, b);
    }
    case Op::Mod:
        return chain2(ops::mod(x, y), 1.0, a, -std::floor(x / y), b);
    case Op::RIntersect:
    case Op::RUnion:
        return rfunction(op, a, b, imm0, imm1);
    default:
        break;
    }
    // comparisons and logic: piecewise constant
    return constant(v);
}

Dual ternary(Op op, const Dual& a, const Dual& b, const Dual& c) {
    switch (op) {
    case Op::Select:
        return ops::truth(a.v) ? b : c;
    case Op::Noise: {
        double g[3];
        double v = noise3Gradient(a.v, b.v, c.v, g);
        Dual r = chain2(v, g[0], a, g[1], b);
        Dual t = chain(0.0, g[2], c);
        for (int i = 0; i < 3; ++i)
            r.d[i] += t.d[i];
        return r;
    }
    default:
        break;
    }
    return constant(NAN);
}

} // namespace ad

namespace {
struct DualDomain {
    using Value = Dual;
    static Dual constant(double v) { return Dual{v, {0.0, 0.0, 0.0}}; }
    static Dual unary(Op op, const Dual& a, double imm0) { return ad::unary(op, a, imm0); }
    static Dual binary(Op op, const Dual& a, const Dual& b, double imm0, double imm1) {
        return ad::binary(op, a, b, imm0, imm1);
    }
    static Dual ternary(Op op, const Dual& a, const Dual& b, const Dual& c) {
        return ad::ternary(op, a, b, c);
    }
};
} // namespace

GradientEvaluator::GradientEvaluator(const Tape& tape, std::array<Input, 3> wrt)
    : tape_(tape), wrt_(wrt), params_(tape_), regs_(static_cast<std::size_t>(tape.registerCount)) {}

void GradientEvaluator::run(const Point& p) {
    Dual* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = DualDomain::constant(p[i]);
    for (int k = 0; k < 3; ++k)
        r[static_cast<int>(wrt_[k])].d[k] = 1.0;
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = DualDomain::constant(pv[i]);
    walkTape<DualDomain>(tape_, r);
}

Dual GradientEvaluator::evaluate(const Point& p) {
    run(p);
    return tape_.outputs.empty() ? Dual{} : tapeOutput<DualDomain>(tape_, regs_.data(), 0);
}

void GradientEvaluator::evaluateAll(const Point& p, Dual* outputs) {
    run(p);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i)
        outputs[i] = tapeOutput<DualDomain>(tape_, regs_.data(), i);
}

} // namespace fl::formula

namespace fl::formula {

namespace {
// One instruction over a block, the operation fixed at compile time for the
// commonest ones: with `flatten` the compiler inlines ad::binary/unary and
// folds their switch away, leaving a plain loop (same arithmetic, same bits).
template <Op kOp>
[[gnu::flatten]] void binaryLoop(Dual* dst, const Dual* a, const Dual* b, std::size_t m) {
    for (std::size_t j = 0; j < m; ++j)
        dst[j] = ad::binary(kOp, a[j], b[j], 0.0, 0.0);
}
template <Op kOp>
[[gnu::flatten]] void unaryLoop(Dual* dst, const Dual* a, std::size_t m) {
    for (std::size_t j = 0; j < m; ++j)
        dst[j] = ad::unary(kOp, a[j], 0.0);
}

// sin and cos of a row at once, each through SLEEF's array form (4 lanes
// with AVX2): a dual number needs both, and the gyroid-like formulas that
// use them spend most of a gradient there. The arrays give the scalar bits
// (vector_math_variant.inc), so this matches ad::unary exactly.
void trigLoop(bool sine, Dual* dst, const Dual* a, std::size_t m) {
    constexpr std::size_t kMax = 64;
    double x[kMax], s[kMax], c[kMax];
    const auto& vm = vmath::implementation();
    for (std::size_t start = 0; start < m; start += kMax) {
        const std::size_t n = std::min(kMax, m - start);
        for (std::size_t j = 0; j < n; ++j)
            x[j] = a[start + j].v;
        vm.unaryArray[int(vmath::Unary::Sin)](x, s, n);
        vm.unaryArray[int(vmath::Unary::Cos)](x, c, n);
        for (std::size_t j = 0; j < n; ++j) {
            const Dual& in = a[start + j];
            Dual& out = dst[start + j];
            const double slope = sine ? c[j] : -s[j];
            out.v = sine ? s[j] : c[j];
            for (int i = 0; i < 3; ++i)
                out.d[i] = (in.d[i] == 0.0 || slope == 0.0) ? 0.0 : slope * in.d[i];
        }
    }
}
} // namespace

void GradientEvaluator::evaluateMany(const Point* points, std::size_t n, Dual* out) {
    constexpr std::size_t kManyBlock = 64;
    if (tape_.outputs.empty()) {
        for (std::size_t i = 0; i < n; ++i)
            out[i] = Dual{};
        return;
    }
    const std::size_t regCount = std::size_t(tape_.registerCount);
    blockRegs_.resize(regCount * kManyBlock);
    Dual* r = blockRegs_.data();
    const std::vector<double>& pv = params_.values();
    for (std::size_t start = 0; start < n; start += kManyBlock) {
        const std::size_t m = std::min(kManyBlock, n - start);
        for (std::size_t j = 0; j < m; ++j) {
            const Point& p = points[start + j];
            for (int i = 0; i < kInputCount; ++i)
                r[std::size_t(i) * kManyBlock + j] = DualDomain::constant(p[std::size_t(i)]);
            for (int k = 0; k < 3; ++k)
                r[std::size_t(wrt_[std::size_t(k)]) * kManyBlock + j].d[std::size_t(k)] = 1.0;
            for (std::size_t i = 0; i < pv.size(); ++i)
                r[(kInputCount + i) * kManyBlock + j] = DualDomain::constant(pv[i]);
        }
        auto operand = [&](const Operand& o, std::size_t j) {
            return o.isConst() ? DualDomain::constant(o.value)
                               : r[std::size_t(o.reg) * kManyBlock + j];
        };
        // Operands as rows (a constant is spread over a scratch row).
        auto row = [&](const Operand& o, Dual* scratch) -> const Dual* {
            if (!o.isConst()) return r + std::size_t(o.reg) * kManyBlock;
            for (std::size_t j = 0; j < m; ++j)
                scratch[j] = DualDomain::constant(o.value);
            return scratch;
        };
        Dual sa[kManyBlock], sb[kManyBlock];
        for (const Instruction& ins : tape_.code) {
            Dual* dst = r + std::size_t(ins.out) * kManyBlock;
            bool done = true;
            switch (ins.op) {
            case Op::Add:
                binaryLoop<Op::Add>(dst, row(ins.a, sa), row(ins.b, sb), m);
                break;
            case Op::Sub:
                binaryLoop<Op::Sub>(dst, row(ins.a, sa), row(ins.b, sb), m);
                break;
            case Op::Mul:
                binaryLoop<Op::Mul>(dst, row(ins.a, sa), row(ins.b, sb), m);
                break;
            case Op::Min:
                binaryLoop<Op::Min>(dst, row(ins.a, sa), row(ins.b, sb), m);
                break;
            case Op::Max:
                binaryLoop<Op::Max>(dst, row(ins.a, sa), row(ins.b, sb), m);
                break;
            case Op::Neg:
                unaryLoop<Op::Neg>(dst, row(ins.a, sa), m);
                break;
            case Op::Square:
                unaryLoop<Op::Square>(dst, row(ins.a, sa), m);
                break;
            case Op::Sin:
                trigLoop(true, dst, row(ins.a, sa), m);
                break;
            case Op::Cos:
                trigLoop(false, dst, row(ins.a, sa), m);
                break;
            case Op::Sqrt:
                unaryLoop<Op::Sqrt>(dst, row(ins.a, sa), m);
                break;
            default:
                done = false;
            }
            if (done) continue;
            switch (opArity(ins.op)) {
            case 1:
                for (std::size_t j = 0; j < m; ++j)
                    dst[j] = ad::unary(ins.op, operand(ins.a, j), ins.imm0);
                break;
            case 2:
                for (std::size_t j = 0; j < m; ++j)
                    dst[j] = ad::binary(ins.op, operand(ins.a, j), operand(ins.b, j), ins.imm0,
                                        ins.imm1);
                break;
            default:
                for (std::size_t j = 0; j < m; ++j)
                    dst[j] = ad::ternary(ins.op, operand(ins.a, j), operand(ins.b, j),
                                         operand(ins.c, j));
                break;
            }
        }
        const Operand& o = tape_.outputs[0].value;
        for (std::size_t j = 0; j < m; ++j)
            out[start + j] = operand(o, j);
    }
}

} // namespace fl::formula
