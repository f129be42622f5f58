#include "eval_batch.h"

#include "batch_hoist.h"

#include "batch_step_run.h"

#include "batch_fusion.h"
#include "scalar_ops.h"
#include "vector_math.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <new>

namespace fl::formula {

namespace {

using Step = BatchStep;

// Every loop helper is forced inline: runBlock is compiled twice (baseline and
// AVX2, see below), and a helper left out of line would be compiled once, for
// the baseline, and run 2 lanes wide even on an AVX2 machine.
#define FL_BATCH_LOOP [[gnu::always_inline]] inline

template <typename F>
FL_BATCH_LOOP void unaryLoop(double* __restrict o, const double* __restrict a, std::size_t n, F f) {
    for (std::size_t i = 0; i < n; ++i)
        o[i] = f(a[i]);
}

template <typename F>
FL_BATCH_LOOP void binaryLoop(const Step& s, double* const* base, double* __restrict o,
                              std::size_t n, F f) {
    if (s.constA) {
        const double ca = s.ca;
        const double* __restrict b = base[s.b];
        for (std::size_t i = 0; i < n; ++i)
            o[i] = f(ca, b[i]);
    } else if (s.constB) {
        const double cb = s.cb;
        const double* __restrict a = base[s.a];
        for (std::size_t i = 0; i < n; ++i)
            o[i] = f(a[i], cb);
    } else {
        const double* __restrict a = base[s.a];
        const double* __restrict b = base[s.b];
        for (std::size_t i = 0; i < n; ++i)
            o[i] = f(a[i], b[i]);
    }
}

inline double cmpResult(bool v) {
    return v ? 1.0 : 0.0;
}

// out = A + sign0*(r0 - c0)^2 [+ sign1*(r1 - c1)^2 [+ sign2*(r2 - c2)^2]]: the
// same operations in the same order as the steps it replaces (multiplying by
// -1 and adding is exactly subtracting).
template <int Terms, bool ConstA>
FL_BATCH_LOOP void squareTermsLoop(const Step& s, double* const* base, double* __restrict o,
                                   std::size_t n) {
    const double* __restrict r0 = base[s.termReg[0]];
    const double* __restrict r1 = base[s.termReg[Terms > 1 ? 1 : 0]];
    const double* __restrict r2 = base[s.termReg[Terms > 2 ? 2 : 0]];
    const double* __restrict a = ConstA ? nullptr : base[s.a];
    const double c0 = s.termOffset[0], c1 = s.termOffset[1], c2 = s.termOffset[2];
    const double s0 = s.termSign[0], s1 = s.termSign[1], s2 = s.termSign[2];
    const double ca = s.ca;
    for (std::size_t i = 0; i < n; ++i) {
        double acc = ConstA ? ca : a[i];
        double d = r0[i] - c0;
        acc = acc + s0 * (d * d);
        if constexpr (Terms > 1) {
            d = r1[i] - c1;
            acc = acc + s1 * (d * d);
        }
        if constexpr (Terms > 2) {
            d = r2[i] - c2;
            acc = acc + s2 * (d * d);
        }
        o[i] = acc;
    }
}

template <bool ConstA>
FL_BATCH_LOOP void squareTermsDispatch(const Step& s, double* const* base, double* o,
                                       std::size_t n) {
    switch (s.terms) {
    case 1:
        squareTermsLoop<1, ConstA>(s, base, o, n);
        break;
    case 2:
        squareTermsLoop<2, ConstA>(s, base, o, n);
        break;
    default:
        squareTermsLoop<3, ConstA>(s, base, o, n);
        break;
    }
}

// min/max with one operand negated on the fly (a \\ b is min(a, -b)). The
// output may be the negated operand's own register (fusion allows it here),
// so that case reads the operand through the output pointer: one pointer,
// read then written at the same index, which vectorises without alias checks.
template <bool NegA, typename F>
FL_BATCH_LOOP void negatedLoop(const Step& s, double* const* base, double* o, std::size_t n, F f) {
    auto apply = [f](double a, double b) { return NegA ? f(-a, b) : f(a, -b); };
    const std::int32_t negReg = NegA ? s.a : s.b;
    const bool otherConst = NegA ? s.constB : s.constA;
    const double k = NegA ? s.cb : s.ca;
    const double* __restrict other = otherConst ? nullptr : base[NegA ? s.b : s.a];
    if (base[negReg] == o) {
        if (otherConst) {
            for (std::size_t i = 0; i < n; ++i)
                o[i] = NegA ? apply(o[i], k) : apply(k, o[i]);
        } else {
            for (std::size_t i = 0; i < n; ++i)
                o[i] = NegA ? apply(o[i], other[i]) : apply(other[i], o[i]);
        }
        return;
    }
    double* __restrict out = o;
    const double* __restrict v = base[negReg];
    if (otherConst) {
        for (std::size_t i = 0; i < n; ++i)
            out[i] = NegA ? apply(v[i], k) : apply(k, v[i]);
    } else {
        for (std::size_t i = 0; i < n; ++i)
            out[i] = NegA ? apply(v[i], other[i]) : apply(other[i], v[i]);
    }
}

// op(op(op(r0, r1), r2), r3) with each operand times its sign (+1 or -1).
// When the output is r0's own register, r0 is read through the output
// pointer: one pointer read and written at the same index still vectorises.
template <int Count, bool IsMin, bool InPlace>
FL_BATCH_LOOP void chainLoop(const Step& s, double* const* base, double* o, std::size_t n) {
    const double* __restrict r1 = base[s.chainReg[1]];
    const double* __restrict r2 = base[s.chainReg[2]];
    const double* __restrict r3 = base[s.chainReg[Count > 3 ? 3 : 2]];
    const double s0 = s.chainSign[0], s1 = s.chainSign[1], s2 = s.chainSign[2], s3 = s.chainSign[3];
    auto op = [](double a, double b) { return IsMin ? ops::min(a, b) : ops::max(a, b); };
    if constexpr (InPlace) {
        for (std::size_t i = 0; i < n; ++i) { // o[i] is r0[i]: read, then written
            double acc = op(s0 * o[i], s1 * r1[i]);
            acc = op(acc, s2 * r2[i]);
            if constexpr (Count > 3) acc = op(acc, s3 * r3[i]);
            o[i] = acc;
        }
    } else {
        double* __restrict out = o;
        const double* __restrict r0 = base[s.chainReg[0]];
        for (std::size_t i = 0; i < n; ++i) {
            double acc = op(s0 * r0[i], s1 * r1[i]);
            acc = op(acc, s2 * r2[i]);
            if constexpr (Count > 3) acc = op(acc, s3 * r3[i]);
            out[i] = acc;
        }
    }
}

template <bool IsMin>
FL_BATCH_LOOP void chainDispatch(const Step& s, double* const* base, double* o, std::size_t n) {
    const bool inPlace = base[s.chainReg[0]] == o;
    if (s.chainCount == 3)
        inPlace ? chainLoop<3, IsMin, true>(s, base, o, n)
                : chainLoop<3, IsMin, false>(s, base, o, n);
    else
        inPlace ? chainLoop<4, IsMin, true>(s, base, o, n)
                : chainLoop<4, IsMin, false>(s, base, o, n);
}

} // namespace

BatchEvaluator::BatchEvaluator(const Tape& tape, bool compile)
    : tape_(tape), params_(tape_), compile_(compile) {
    const std::size_t regs = static_cast<std::size_t>(tape.registerCount);
    uniformValue_.assign(regs, 0.0);
    isUniform_.assign(regs, 0);
}

// The blocks' rows, made at the first evaluate(): an evaluator used one
// point at a time (ScalarEvaluator's) needs one double a register, not 2 KiB.
void BatchEvaluator::makeWorkspace() {
    const std::size_t regs = static_cast<std::size_t>(tape_.registerCount);
    std::size_t bytes = (regs + 3) * kStride * sizeof(double);
    workspace_ = static_cast<double*>(std::aligned_alloc(64, bytes));
    if (!workspace_) throw std::bad_alloc();
    std::memset(workspace_, 0, bytes);
    for (int k = 0; k < 3; ++k)
        scratch_[k] = workspace_ + (regs + k) * kStride;
}

BatchEvaluator::~BatchEvaluator() {
    std::free(workspace_);
}

void BatchEvaluator::specialise(const BatchInputs& in) {
    const std::vector<double>& pv = params_.values();
    // (by their bits: with ==, k * x kept +0's sign after k became -0)
    bool same = specialised_ && params_.sameBitsAs(specialisedParams_);
    for (int i = 0; same && i < kInputCount; ++i) {
        bool varying = in.arrays[i] != nullptr;
        same =
            specialisedVarying_[i] == varying &&
            (varying || std::memcmp(&specialisedUniform_[i], &in.uniform[i], sizeof(double)) == 0);
    }
    if (same) return;

    std::fill(isUniform_.begin(), isUniform_.end(), 0);
    for (int i = 0; i < kInputCount; ++i) {
        specialisedVarying_[i] = in.arrays[i] != nullptr;
        specialisedUniform_[i] = in.uniform[i];
        isUniform_[i] = in.arrays[i] == nullptr;
        uniformValue_[i] = in.uniform[i];
    }
    for (std::size_t i = 0; i < pv.size(); ++i) {
        isUniform_[kInputCount + i] = 1;
        uniformValue_[kInputCount + i] = pv[i];
    }
    specialisedParams_ = pv;

    steps_.clear();
    for (const Instruction& ins : tape_.code) {
        Step s{};
        s.op = ins.op;
        s.out = ins.out;
        s.imm0 = ins.imm0;
        s.imm1 = ins.imm1;
        auto resolve = [&](const Operand& o, bool& isConst, std::int32_t& reg, double& value) {
            if (o.isConst()) {
                isConst = true;
                value = o.value;
            } else if (isUniform_[o.reg]) {
                isConst = true;
                value = uniformValue_[o.reg];
            } else {
                isConst = false;
                reg = o.reg;
            }
        };
        const int arity = opArity(ins.op);
        s.constB = s.constC = true;
        resolve(ins.a, s.constA, s.a, s.ca);
        if (arity >= 2) resolve(ins.b, s.constB, s.b, s.cb);
        if (arity >= 3) resolve(ins.c, s.constC, s.c, s.cc);
        if (s.constA && s.constB && s.constC) {
            double v = ops::apply(ins.op, s.ca, s.cb, s.cc, ins.imm0, ins.imm1);
            isUniform_[ins.out] = 1;
            uniformValue_[ins.out] = v;
            continue;
        }
        isUniform_[ins.out] = 0;
        steps_.push_back(s);
    }
    fuseBatchSteps(steps_, tape_);
    // Compiled when every step can be: outputs are what evaluate() reads back.
    liveOut_.assign(std::size_t(tape_.registerCount), 0);
    for (const OutputInfo& o : tape_.outputs)
        if (!o.value.isConst() && !isUniform_[std::size_t(o.value.reg)])
            liveOut_[std::size_t(o.value.reg)] = 1;
    const auto started = std::chrono::steady_clock::now();
    jit_ = compile_ ? BatchJit::compile(steps_, liveOut_, tape_.registerCount) : nullptr;
    jitCompileUs_ =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started)
            .count();
    specialised_ = true;
}

// Compiled twice — baseline and AVX2 — and picked at load time by the CPU, so
// the arithmetic loops run 4 lanes wide where they can. Without FMA contraction
// (-ffp-contract=off) both clones round exactly like the scalar evaluator.
__attribute__((target_clones("avx2", "default"))) void
runBatchStep(const BatchStep& s, double* const* base, std::size_t n,
             double* const* scratch) noexcept {
    const vmath::Implementation& vm = vmath::implementation();
    double* __restrict o = base[s.out];
    switch (s.fused) {
    case Fused::None:
        break;
    case Fused::SquareOfDiff: {
        const double c = s.ca;
        unaryLoop(o, base[s.a], n, [c](double a) {
            double d = a - c;
            return d * d;
        });
        return;
    }
    case Fused::SquareTerms:
        if (s.constA)
            squareTermsDispatch<true>(s, base, o, n);
        else
            squareTermsDispatch<false>(s, base, o, n);
        return;
    case Fused::MinMaxChain:
        if (s.op == Op::Min)
            chainDispatch<true>(s, base, o, n);
        else
            chainDispatch<false>(s, base, o, n);
        return;
    case Fused::SinCos:
        vm.sinCosArray(base[s.a], o, base[s.out2], n);
        return;
    case Fused::NegatedOperand: {
        auto mn = [](double a, double b) { return ops::min(a, b); };
        auto mx = [](double a, double b) { return ops::max(a, b); };
        if (s.op == Op::Min)
            s.negA ? negatedLoop<true>(s, base, o, n, mn) : negatedLoop<false>(s, base, o, n, mn);
        else
            s.negA ? negatedLoop<true>(s, base, o, n, mx) : negatedLoop<false>(s, base, o, n, mx);
        return;
    }
    }
    switch (s.op) {
    // ---- unary (the operand always varies: uniform ones were folded)
    case Op::Neg:
        unaryLoop(o, base[s.a], n, [](double a) { return -a; });
        break;
    case Op::Abs:
        unaryLoop(o, base[s.a], n, [](double a) { return std::fabs(a); });
        break;
    case Op::Square:
        unaryLoop(o, base[s.a], n, [](double a) { return a * a; });
        break;
    case Op::Sqrt:
        unaryLoop(o, base[s.a], n, [](double a) { return std::sqrt(a); });
        break;
    case Op::Cbrt:
        vm.unaryArray[int(vmath::Unary::Cbrt)](base[s.a], o, n);
        break;
    case Op::Exp:
        vm.unaryArray[int(vmath::Unary::Exp)](base[s.a], o, n);
        break;
    case Op::Log:
        vm.unaryArray[int(vmath::Unary::Log)](base[s.a], o, n);
        break;
    case Op::Log2:
        vm.unaryArray[int(vmath::Unary::Log2)](base[s.a], o, n);
        break;
    case Op::Log10:
        vm.unaryArray[int(vmath::Unary::Log10)](base[s.a], o, n);
        break;
    case Op::Sin:
        vm.unaryArray[int(vmath::Unary::Sin)](base[s.a], o, n);
        break;
    case Op::Cos:
        vm.unaryArray[int(vmath::Unary::Cos)](base[s.a], o, n);
        break;
    case Op::SinOfPair: { // alone (its partner simplified away or uniform): half a sincos
        double* unused = scratch[0];
        vm.sinCosArray(base[s.a], o, unused, n);
        break;
    }
    case Op::CosOfPair: {
        double* unused = scratch[0];
        vm.sinCosArray(base[s.a], unused, o, n);
        break;
    }
    case Op::Tan:
        vm.unaryArray[int(vmath::Unary::Tan)](base[s.a], o, n);
        break;
    case Op::Asin:
        vm.unaryArray[int(vmath::Unary::Asin)](base[s.a], o, n);
        break;
    case Op::Acos:
        vm.unaryArray[int(vmath::Unary::Acos)](base[s.a], o, n);
        break;
    case Op::Atan:
        vm.unaryArray[int(vmath::Unary::Atan)](base[s.a], o, n);
        break;
    case Op::Sinh:
        vm.unaryArray[int(vmath::Unary::Sinh)](base[s.a], o, n);
        break;
    case Op::Cosh:
        vm.unaryArray[int(vmath::Unary::Cosh)](base[s.a], o, n);
        break;
    case Op::Tanh:
        vm.unaryArray[int(vmath::Unary::Tanh)](base[s.a], o, n);
        break;
    case Op::Floor:
        unaryLoop(o, base[s.a], n, [](double a) { return std::floor(a); });
        break;
    case Op::Ceil:
        unaryLoop(o, base[s.a], n, [](double a) { return std::ceil(a); });
        break;
    case Op::Round:
        unaryLoop(o, base[s.a], n, [](double a) { return std::round(a); });
        break;
    case Op::Sign:
        unaryLoop(o, base[s.a], n, [](double a) { return ops::sign(a); });
        break;
    case Op::Not:
        unaryLoop(o, base[s.a], n, [](double a) { return ops::truth(a) ? 0.0 : 1.0; });
        break;
    case Op::PowI: {
        const int k = static_cast<int>(s.imm0);
        if (k == 3)
            unaryLoop(o, base[s.a], n, [](double a) { return a * a * a; });
        else if (k == 4)
            unaryLoop(o, base[s.a], n, [](double a) {
                double q = a * a;
                return q * q;
            });
        else if (k == -1)
            unaryLoop(o, base[s.a], n, [](double a) { return 1.0 / a; });
        else if (k == -2)
            unaryLoop(o, base[s.a], n, [](double a) { return 1.0 / (a * a); });
        else
            unaryLoop(o, base[s.a], n, [k](double a) { return ops::powi(a, k); });
        break;
    }
    // ---- binary
    case Op::Add:
        binaryLoop(s, base, o, n, [](double a, double b) { return a + b; });
        break;
    case Op::Sub:
        binaryLoop(s, base, o, n, [](double a, double b) { return a - b; });
        break;
    case Op::Mul:
        binaryLoop(s, base, o, n, [](double a, double b) { return a * b; });
        break;
    case Op::Div:
        binaryLoop(s, base, o, n, [](double a, double b) { return a / b; });
        break;
    case Op::Pow:
        vm.binaryArray[int(vmath::Binary::Pow)](s.constA ? nullptr : base[s.a], s.ca,
                                                s.constB ? nullptr : base[s.b], s.cb, o, n);
        break;
    case Op::Min:
        binaryLoop(s, base, o, n, [](double a, double b) { return ops::min(a, b); });
        break;
    case Op::Max:
        binaryLoop(s, base, o, n, [](double a, double b) { return ops::max(a, b); });
        break;
    case Op::Atan2:
        vm.binaryArray[int(vmath::Binary::Atan2)](s.constA ? nullptr : base[s.a], s.ca,
                                                  s.constB ? nullptr : base[s.b], s.cb, o, n);
        break;
    case Op::Hypot:
        binaryLoop(s, base, o, n, [](double a, double b) { return std::hypot(a, b); });
        break;
    case Op::Mod:
        binaryLoop(s, base, o, n, [](double a, double b) { return ops::mod(a, b); });
        break;
    case Op::Less:
        binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a < b); });
        break;
    case Op::LessEq:
        binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a <= b); });
        break;
    case Op::Greater:
        binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a > b); });
        break;
    case Op::GreaterEq:
        binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a >= b); });
        break;
    case Op::Equal:
        binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a == b); });
        break;
    case Op::NotEqual:
        binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a != b); });
        break;
    case Op::And:
        binaryLoop(s, base, o, n,
                   [](double a, double b) { return cmpResult(ops::truth(a) && ops::truth(b)); });
        break;
    case Op::Or:
        binaryLoop(s, base, o, n,
                   [](double a, double b) { return cmpResult(ops::truth(a) || ops::truth(b)); });
        break;
    case Op::RIntersect: {
        const double m = s.imm0, alpha = s.imm1;
        if (m == 0.0 && alpha == 0.0)
            binaryLoop(s, base, o, n, [](double a, double b) { return rIntersect0(a, b); });
        else
            binaryLoop(s, base, o, n,
                       [m, alpha](double a, double b) { return rIntersect(a, b, m, alpha); });
        break;
    }
    case Op::RUnion: {
        const double m = s.imm0, alpha = s.imm1;
        if (m == 0.0 && alpha == 0.0)
            binaryLoop(s, base, o, n, [](double a, double b) { return rUnion0(a, b); });
        else
            binaryLoop(s, base, o, n,
                       [m, alpha](double a, double b) { return rUnion(a, b, m, alpha); });
        break;
    }
    // ---- ternary: uniform operands are broadcast into scratch buffers
    case Op::Select:
    case Op::Noise: {
        const double* p[3];
        const bool isConst[3] = {s.constA, s.constB, s.constC};
        const double cval[3] = {s.ca, s.cb, s.cc};
        const std::int32_t reg[3] = {s.a, s.b, s.c};
        for (int k = 0; k < 3; ++k) {
            if (isConst[k]) {
                std::fill(scratch[k], scratch[k] + n, cval[k]);
                p[k] = scratch[k];
            } else {
                p[k] = base[reg[k]];
            }
        }
        if (s.op == Op::Select) {
            for (std::size_t i = 0; i < n; ++i)
                o[i] = ops::truth(p[0][i]) ? p[1][i] : p[2][i];
        } else {
            for (std::size_t i = 0; i < n; ++i)
                o[i] = noise3(p[0][i], p[1][i], p[2][i]);
        }
        break;
    }
    }
}

void BatchEvaluator::runBlock(double* const* base, std::size_t n) {
    for (const Step& s : steps_)
        runBatchStep(s, base, n, scratch_.data());
}

bool BatchEvaluator::prepareOne() {
    // Every input an array (varying): the point is not known here.
    static const Point anyPoint{};
    BatchInputs in;
    for (int i = 0; i < kInputCount; ++i)
        in.arrays[std::size_t(i)] = &anyPoint[std::size_t(i)];
    specialise(in);
    // What depends on t alone runs once per t (batch_hoist.h).
    const HoistedSteps h = hoistTimeOnly(steps_, liveOut_, tape_.registerCount);
    oneReturns_ = firstOutputComputed();
    oneHoisted_ = h.hoisted;
    onePoint_ =
        BatchJit::compileOnePoint(h.steps, h.liveOut, h.registerCount, oneReturns_, h.hoisted);
    oneRows_.assign(std::size_t(h.registerCount) + 1, 0.0);
    if (onePoint_ && h.hoisted > 0) {
        // The rows made consistent: t's kept bits (1.0's) differ from the
        // call's (0.0's), so it runs the hoisted steps and keeps 0.0.
        oneRows_.back() = 1.0;
        onePoint_->onePoint()(0, 0, 0, 0, 0, 0, 0, oneRows_.data());
    }
    return onePoint_ != nullptr;
}

// The first output's register where the steps compute it (not a constant,
// not an input: the code returns only what it computes).
std::int32_t BatchEvaluator::firstOutputComputed() const {
    if (tape_.outputs.empty()) return -1;
    const Operand& o = tape_.outputs[0].value;
    return o.isConst() || o.reg < kInputCount || isUniform_[std::size_t(o.reg)] ? -1 : o.reg;
}

void BatchEvaluator::evaluateOne(const Point& p, double* outputs, std::size_t count) {
    const double first =
        onePoint_->onePoint()(p[0], p[1], p[2], p[3], p[4], p[5], p[6], oneRows_.data());
    for (std::size_t k = 0; k < count && k < tape_.outputs.size(); ++k) {
        const Operand& o = tape_.outputs[k].value;
        outputs[k] = o.isConst()            ? o.value
                     : o.reg == oneReturns_ ? first
                     : isUniform_[o.reg]    ? uniformValue_[o.reg]
                     : o.reg < kInputCount  ? p[std::size_t(o.reg)]
                                            : oneRows_[std::size_t(o.reg)];
    }
}

void BatchEvaluator::evaluate(const BatchInputs& in, std::size_t n, double* const* outputs) {
    if (!workspace_) makeWorkspace();
    specialise(in);
    const std::size_t regs = static_cast<std::size_t>(tape_.registerCount);
    // The registers' rows, then the three scratch rows (the JIT passes them on
    // to runBatchStep).
    std::vector<double*> base(regs + scratch_.size());
    for (std::size_t r = 0; r < regs; ++r)
        base[r] = workspace_ + r * kStride;
    std::copy(scratch_.begin(), scratch_.end(), base.begin() + std::ptrdiff_t(regs));
    // A single output computed in a register of its own is written straight
    // into the caller's array: no copy afterwards.
    const bool direct = tape_.outputs.size() == 1 && !tape_.outputs[0].value.isConst() &&
                        tape_.outputs[0].value.reg >= kInputCount &&
                        !isUniform_[std::size_t(tape_.outputs[0].value.reg)];
    const std::size_t outReg = direct ? std::size_t(tape_.outputs[0].value.reg) : 0;
    for (std::size_t start = 0, count = 0; start < n; start += count) {
        for (int i = 0; i < kInputCount; ++i)
            if (in.arrays[i]) base[i] = const_cast<double*>(in.arrays[i] + start); // read only
        if (direct) base[outReg] = outputs[0] + start;
        // The JIT does whole groups of 8 points (`base` with the scratch rows
        // after the registers': it hands them to runBatchStep), the
        // interpreter the rest. With its one output in the caller's array,
        // code that keeps every value in registers runs over all the points
        // left in one call (BatchJit::run: a block at most otherwise).
        const std::size_t left = n - start;
        const std::size_t done =
            jit_ && left >= 8 ? jit_->run(base.data(), direct ? left : std::min(kBlock, left)) : 0;
        count = done >= kBlock ? done : std::min(kBlock, left);
        if (done == 0) {
            runBlock(base.data(), count);
        } else if (done < count) {
            tailBase_.resize(regs);
            for (std::size_t r = 0; r < regs; ++r)
                tailBase_[r] = base[r] + done;
            runBlock(tailBase_.data(), count - done);
        }
        if (direct) {
            base[outReg] = workspace_ + outReg * kStride;
            continue;
        }
        for (std::size_t k = 0; k < tape_.outputs.size(); ++k) {
            const Operand& o = tape_.outputs[k].value;
            double* dst = outputs[k] + start;
            if (o.isConst())
                std::fill(dst, dst + count, o.value);
            else if (isUniform_[o.reg])
                std::fill(dst, dst + count, uniformValue_[o.reg]);
            else
                std::memcpy(dst, base[o.reg], count * sizeof(double));
        }
    }
}

} // namespace fl::formula
