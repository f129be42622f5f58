#include "eval_gradient.h"

#include "gradient_jit.h"
#include "noise.h"
#include "scalar_ops.h"
#include "tape_walk.h"
#include "vector_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::formula {

namespace ad {

// f'(a) * da, with 0 * anything = 0 so that a constant operand of a function
// with an infinite derivative (sqrt at 0) keeps a zero gradient.
Dual chain(double value, double fprime, const Dual& a) {
    Dual r;
    r.v = value;
    for (int i = 0; i < 3; ++i)
        r.d[i] = (a.d[i] == 0.0 || fprime == 0.0) ? 0.0 : fprime * a.d[i];
    return r;
}

namespace {
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
    // +inf and a finite other: the R-function is that other (rIntersect0),
    // so its slope is the other's
    if (std::isinf(a) && a > 0 && std::isfinite(b)) {
        da = 0.0, db = 1.0;
        return;
    }
    if (std::isinf(b) && b > 0 && std::isfinite(a)) {
        da = 1.0, db = 0.0;
        return;
    }
    double s = std::max(std::abs(a), std::abs(b));
    if (s == 0.0 || !std::isfinite(s)) {
        // not differentiable at the origin: the average of the one-sided
        // slopes (and the value is infinite or NaN beyond it)
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
    if (op == Op::SinOfPair || op == Op::CosOfPair) { // value and slope from one sincos
        const vmath::SinCos sc = vmath::sinCos(x);
        return op == Op::SinOfPair ? chain(sc.sin, sc.cos, a) : chain(sc.cos, -sc.sin, a);
    }
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

namespace {

// Whether evaluateMany runs the machine code point by point rather than its
// row loops, from an estimate of each way's cost a point (ns, measured on
// the Zen 4 VM of docs/performance.md, eleventh part): a row loop about 1
// an instruction, 4 a sine or cosine (SLEEF's arrays), 10 an operation
// without one (ad:: point by point); the code about 5 a call, 1.5 an
// instruction it writes, 12 one it calls out for (a sine or cosine of its
// own twice that: ad:: takes both). Row loops win on sums of squares, CSG
// and trig; the code on abs, powers and divisions (a box's distance: 35 ns
// a point in rows, 10 as code). (A sin/cos pair is priced as two trig
// steps both ways, and work on t alone as if it ran at every point.)
bool manyByCode(const Tape& tape) {
    double rows = 0.0, code = 5.0;
    for (const Instruction& ins : tape.code) {
        switch (ins.op) {
        case Op::Add:
        case Op::Sub:
        case Op::Mul:
        case Op::Min:
        case Op::Max:
        case Op::Neg:
        case Op::Square:
        case Op::Sqrt: // evaluateMany's row loops
            rows += 1.0, code += 1.5;
            break;
        case Op::Sin:
        case Op::Cos:
            rows += 4.0, code += 24.0;
            break;
        case Op::SinOfPair:
        case Op::CosOfPair:
            rows += 4.0, code += 12.0;
            break;
        default:
            rows += 10.0, code += GradientJit::writesInline(ins) ? 1.5 : 12.0;
            break;
        }
    }
    return code <= rows;
}

} // namespace

GradientEvaluator::GradientEvaluator(const Tape& tape, std::array<Input, 3> wrt, ScalarCode code)
    : tape_(tape), wrt_(wrt), params_(tape_), regs_(static_cast<std::size_t>(tape.registerCount)),
      code_(code), manyByCode_(manyByCode(tape_)) {}

GradientEvaluator::~GradientEvaluator() = default;
// (The parameters name their tape: the copy's. The code is shared.)
GradientEvaluator::GradientEvaluator(const GradientEvaluator& other)
    : tape_(other.tape_), wrt_(other.wrt_), params_(other.params_), regs_(other.regs_),
      code_(other.code_), manyByCode_(other.manyByCode_), calls_(other.calls_),
      tried_(other.tried_), jit_(other.jit_) {
    params_.rebind(tape_);
}

// Machine code where it can be: after kScalarWarmUp points (an evaluator
// asked for a few never pays for compiling).
bool GradientEvaluator::haveCode(std::size_t asked, double t) {
    if (jit_) return true;
    if (tried_ || code_ == ScalarCode::Interpreted) return false;
    if (code_ == ScalarCode::AfterWarmUp && calls_ < kScalarWarmUp) {
        calls_ += unsigned(std::min<std::size_t>(asked, kScalarWarmUp));
        return false;
    }
    tried_ = true;
    jit_ = GradientJit::compile(tape_, wrt_);
    if (!jit_) return false;
    regs_.resize(std::max(regs_.size(), jit_->duals()));
    jit_->forgetMoment(regs_.data(), t);
    return true;
}

// The code reads the parameters' duals from regs_, written again when their
// values change.
void GradientEvaluator::runCode(const Point& p) {
    if (!paramsWrittenOnce_ || paramsWritten_ != params_.version()) {
        const std::vector<double>& pv = params_.values();
        for (std::size_t i = 0; i < pv.size(); ++i)
            regs_[kInputCount + i] = DualDomain::constant(pv[i]);
        paramsWritten_ = params_.version();
        paramsWrittenOnce_ = true;
    }
    jit_->code()(p.data(), regs_.data());
}

bool GradientEvaluator::runCompiled(const Point& p) {
    if (!haveCode(1, p[std::size_t(Input::T)])) return false;
    runCode(p);
    return true;
}

void GradientEvaluator::run(const Point& p) {
    compiledLast_ = runCompiled(p);
    if (compiledLast_) return;
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
    if (tape_.outputs.empty()) {
        compiledLast_ = false;
        return Dual{};
    }
    run(p);
    return tapeOutput<DualDomain>(tape_, regs_.data(), 0);
}

void GradientEvaluator::evaluateAll(const Point& p, Dual* outputs) {
    run(p);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i)
        outputs[i] = tapeOutput<DualDomain>(tape_, regs_.data(), i);
}

} // namespace fl::formula

namespace fl::formula {

namespace {

// evaluateMany keeps each register of a block of points as four rows — the
// values and the three derivatives, kManyBlock doubles each — so that the
// commonest operations run as plain loops over rows, which the compiler
// vectorises (an AVX2 clone where the CPU has it). Each loop is ad::unary's
// or ad::binary's arithmetic written for rows: the same operations in the
// same order, the same zero rule (0 times anything is 0), so the bits are
// evaluate()'s exactly (GradientMany.* tests).
constexpr std::size_t kManyBlock = 64;
constexpr std::size_t kRow = kManyBlock;
constexpr std::size_t kRegisterStride = 4 * kRow; // v, d0, d1, d2

// The row loops are built twice by GCC, baseline and AVX2, and picked at
// load time by the CPU; clang (the fuzzing build) cannot clone templates.
#if defined(__clang__)
#define FL_ROW_LOOP
#else
#define FL_ROW_LOOP __attribute__((target_clones("avx2", "default")))
#endif

// f' * da under the zero rule: the product always taken, then chosen (no
// branch, so the loops vectorise to a compare and a blend).
inline double term(double da, double fprime) {
    const double product = fprime * da;
    return ((da == 0.0) | (fprime == 0.0)) ? 0.0 : product;
}

template <Op kOp>
FL_ROW_LOOP void binaryRows(double* __restrict dst, const double* __restrict a,
                            const double* __restrict b, std::size_t m) {
    for (std::size_t k = 1; k <= 3; ++k) {
        const double* ad = a + k * kRow;
        const double* bd = b + k * kRow;
        double* od = dst + k * kRow;
        for (std::size_t j = 0; j < m; ++j) {
            const double x = a[j], y = b[j];
            if constexpr (kOp == Op::Add) {
                od[j] = term(ad[j], 1.0) + term(bd[j], 1.0);
            } else if constexpr (kOp == Op::Sub) {
                od[j] = term(ad[j], 1.0) + term(bd[j], -1.0);
            } else if constexpr (kOp == Op::Mul) {
                od[j] = term(ad[j], y) + term(bd[j], x);
            } else { // Min, Max: the chosen operand's slope; at a tie the mean
                const bool first = kOp == Op::Min ? ((x < y) | (x != x)) : ((x > y) | (x != x));
                const double tie = term(ad[j], 0.5) + term(bd[j], 0.5);
                od[j] = x == y ? tie : first ? ad[j] : bd[j];
            }
        }
    }
    for (std::size_t j = 0; j < m; ++j) {
        const double x = a[j], y = b[j];
        if constexpr (kOp == Op::Add)
            dst[j] = x + y;
        else if constexpr (kOp == Op::Sub)
            dst[j] = x - y;
        else if constexpr (kOp == Op::Mul)
            dst[j] = x * y;
        else if constexpr (kOp == Op::Min)
            dst[j] = minPropagating(x, y);
        else
            dst[j] = maxPropagating(x, y);
    }
}

template <Op kOp>
FL_ROW_LOOP void unaryRows(double* __restrict dst, const double* __restrict a, std::size_t m) {
    for (std::size_t j = 0; j < m; ++j) {
        const double x = a[j];
        if constexpr (kOp == Op::Neg)
            dst[j] = -x;
        else if constexpr (kOp == Op::Square)
            dst[j] = x * x;
        else
            dst[j] = std::sqrt(x);
    }
    for (std::size_t k = 1; k <= 3; ++k) {
        const double* ad = a + k * kRow;
        double* od = dst + k * kRow;
        for (std::size_t j = 0; j < m; ++j) {
            double fprime;
            if constexpr (kOp == Op::Neg)
                fprime = -1.0;
            else if constexpr (kOp == Op::Square)
                fprime = 2.0 * a[j];
            else
                fprime = 0.5 / dst[j];
            od[j] = term(ad[j], fprime);
        }
    }
}

// A function's rows from its values and slopes f' (negated with kNegate):
// dst's values, and its derivatives each a's times f' under the zero rule —
// loops of their own over restrict pointers, which vectorise (one loop
// writing either of two optional outputs had a branch and a setnp per
// element: a third of a gradient on the gyroid at 64).
template <bool kNegate>
FL_ROW_LOOP void chainRows(double* __restrict dst, const double* __restrict a,
                           const double* __restrict value, const double* __restrict slope,
                           std::size_t m) {
    for (std::size_t k = 1; k <= 3; ++k) {
        const double* ad = a + k * kRow;
        double* od = dst + k * kRow;
        for (std::size_t j = 0; j < m; ++j)
            od[j] = term(ad[j], kNegate ? -slope[j] : slope[j]);
    }
    for (std::size_t j = 0; j < m; ++j)
        dst[j] = value[j];
}

// sin and cos of a row at once, each through SLEEF's array form (4 lanes
// with AVX2): a dual number needs both, and the gyroid-like formulas that
// use them spend most of a gradient there. The arrays give the scalar bits
// (vector_math_variant.inc), so this matches ad::unary exactly.
// A paired opcode's value and derivative come from one sincos, and a pair
// side by side (as the tape builder puts them) fills both halves' rows from
// it: `sinDst` and `cosDst` (either may be nullptr; neither is a's rows).
void trigRows(bool paired, double* sinDst, double* cosDst, const double* a, std::size_t m) {
    double s[kRow], c[kRow];
    const auto& vm = vmath::implementation();
    if (paired) {
        vm.sinCosArray(a, s, c, m);
    } else {
        vm.unaryArray[int(vmath::Unary::Sin)](a, s, m);
        vm.unaryArray[int(vmath::Unary::Cos)](a, c, m);
    }
    if (sinDst) chainRows<false>(sinDst, a, s, c, m);
    if (cosDst) chainRows<true>(cosDst, a, c, s, m);
}

Dual dualAt(const double* rows, std::size_t j) {
    return Dual{rows[j], {rows[kRow + j], rows[2 * kRow + j], rows[3 * kRow + j]}};
}
void setDual(double* rows, std::size_t j, const Dual& d) {
    rows[j] = d.v;
    for (std::size_t k = 0; k < 3; ++k)
        rows[(k + 1) * kRow + j] = d.d[k];
}

} // namespace

void GradientEvaluator::evaluateMany(const Point* points, std::size_t n, Dual* out) {
    if (tape_.outputs.empty()) {
        for (std::size_t i = 0; i < n; ++i)
            out[i] = Dual{};
        compiledLast_ = false;
        return;
    }
    compiledLast_ = n > 0 && manyByCode_ && haveCode(n, points[0][std::size_t(Input::T)]);
    if (compiledLast_) {
        for (std::size_t i = 0; i < n; ++i) {
            runCode(points[i]);
            out[i] = tapeOutput<DualDomain>(tape_, regs_.data(), 0);
        }
        return;
    }
    const std::size_t regCount = std::size_t(tape_.registerCount);
    blockRegs_.resize(regCount * kRegisterStride);
    double* r = blockRegs_.data();
    auto rows = [r](std::int32_t reg) { return r + std::size_t(reg) * kRegisterStride; };
    const std::vector<double>& pv = params_.values();
    // Constant operands as rows (the value, zero slopes), made once a call.
    const std::size_t first = std::min(n, kManyBlock);
    auto spread = [first](double* dst, double v) {
        std::fill(dst, dst + first, v);
        for (std::size_t k = 1; k <= 3; ++k)
            std::fill(dst + k * kRow, dst + k * kRow + first, 0.0);
    };
    constSlot_.assign(tape_.code.size() * 3, -1);
    std::size_t constants = 0;
    for (std::size_t i = 0; i < tape_.code.size(); ++i) {
        const Instruction& ins = tape_.code[i];
        const Operand* ops[3] = {&ins.a, &ins.b, &ins.c};
        for (std::size_t k = 0; k < std::size_t(opArity(ins.op)); ++k)
            if (ops[k]->isConst()) constSlot_[3 * i + k] = std::int32_t(constants++);
    }
    constRows_.resize(constants * kRegisterStride);
    for (std::size_t i = 0; i < tape_.code.size(); ++i) {
        const Instruction& ins = tape_.code[i];
        const Operand* ops[3] = {&ins.a, &ins.b, &ins.c};
        for (std::size_t k = 0; k < 3; ++k)
            if (constSlot_[3 * i + k] >= 0)
                spread(constRows_.data() + std::size_t(constSlot_[3 * i + k]) * kRegisterStride,
                       ops[k]->value);
    }
    auto operandRows = [&](std::size_t i, std::size_t k, const Operand& o) -> const double* {
        return o.isConst()
                   ? constRows_.data() + std::size_t(constSlot_[3 * i + k]) * kRegisterStride
                   : rows(o.reg);
    };
    // Inputs and parameters are never written by the tape: their slopes
    // (1 along the input they are, else 0) and the parameters' rows are
    // set once a call, the inputs' values per block.
    for (int i = 0; i < kInputCount; ++i)
        std::fill(rows(i) + kRow, rows(i) + kRegisterStride, 0.0);
    for (std::size_t k = 0; k < 3; ++k)
        std::fill_n(rows(std::int32_t(wrt_[k])) + (k + 1) * kRow, first, 1.0);
    for (std::size_t i = 0; i < pv.size(); ++i)
        spread(rows(std::int32_t(kInputCount + i)), pv[i]);
    for (std::size_t start = 0; start < n; start += kManyBlock) {
        const std::size_t m = std::min(kManyBlock, n - start);
        for (int i = 0; i < kInputCount; ++i) {
            if (!tape_.usesInput[std::size_t(i)]) continue;
            double* in = rows(i);
            for (std::size_t j = 0; j < m; ++j)
                in[j] = points[start + j][std::size_t(i)];
        }
        for (std::size_t i = 0; i < tape_.code.size(); ++i) {
            const Instruction& ins = tape_.code[i];
            double* dst = rows(ins.out);
            const double* a = operandRows(i, 0, ins.a);
            switch (ins.op) {
            case Op::Add:
                binaryRows<Op::Add>(dst, a, operandRows(i, 1, ins.b), m);
                continue;
            case Op::Sub:
                binaryRows<Op::Sub>(dst, a, operandRows(i, 1, ins.b), m);
                continue;
            case Op::Mul:
                binaryRows<Op::Mul>(dst, a, operandRows(i, 1, ins.b), m);
                continue;
            case Op::Min:
                binaryRows<Op::Min>(dst, a, operandRows(i, 1, ins.b), m);
                continue;
            case Op::Max:
                binaryRows<Op::Max>(dst, a, operandRows(i, 1, ins.b), m);
                continue;
            case Op::Neg:
                unaryRows<Op::Neg>(dst, a, m);
                continue;
            case Op::Square:
                unaryRows<Op::Square>(dst, a, m);
                continue;
            case Op::Sqrt:
                unaryRows<Op::Sqrt>(dst, a, m);
                continue;
            case Op::Sin:
                trigRows(false, dst, nullptr, a, m);
                continue;
            case Op::Cos:
                trigRows(false, nullptr, dst, a, m);
                continue;
            case Op::SinOfPair:
            case Op::CosOfPair: {
                const bool sine = ins.op == Op::SinOfPair;
                double* other = nullptr;
                if (i + 1 < tape_.code.size()) {
                    const Instruction& next = tape_.code[i + 1];
                    if (next.op == (sine ? Op::CosOfPair : Op::SinOfPair) && !ins.a.isConst() &&
                        !next.a.isConst() && next.a.reg == ins.a.reg && ins.out != ins.a.reg &&
                        next.out != ins.a.reg && next.out != ins.out) {
                        other = rows(next.out);
                        ++i; // done here
                    }
                }
                trigRows(true, sine ? dst : other, sine ? other : dst, a, m);
                continue;
            }
            default:
                break;
            }
            // The rest point by point through ad::*.
            const int arity = opArity(ins.op);
            const double* b = arity >= 2 ? operandRows(i, 1, ins.b) : nullptr;
            const double* c = arity >= 3 ? operandRows(i, 2, ins.c) : nullptr;
            for (std::size_t j = 0; j < m; ++j) {
                const Dual x = dualAt(a, j);
                setDual(dst, j,
                        arity == 1   ? ad::unary(ins.op, x, ins.imm0)
                        : arity == 2 ? ad::binary(ins.op, x, dualAt(b, j), ins.imm0, ins.imm1)
                                     : ad::ternary(ins.op, x, dualAt(b, j), dualAt(c, j)));
            }
        }
        const Operand& o = tape_.outputs[0].value;
        for (std::size_t j = 0; j < m; ++j)
            out[start + j] = o.isConst() ? DualDomain::constant(o.value) : dualAt(rows(o.reg), j);
    }
}

} // namespace fl::formula
