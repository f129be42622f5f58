#include "eval_batch.h"

#include "scalar_ops.h"
#include "vector_math.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

namespace fl::formula {

// Hot pairs fused for the batch loops only (one pass over the block instead
// of two or three). Each computes exactly what the unfused steps would.
enum class Fused : std::uint8_t {
    None,
    SquareOfDiff, // out = (a - ca)^2           from  t = a - c; out = t * t
    AddSquare,    // out = A + (b - cb)^2       from  q = square(...); out = A + q
    SubSquare,    // out = A - (b - cb)^2       from  q = square(...); out = A - q
};

struct BatchEvaluator::Step {
    Op op;
    Fused fused;
    bool constA, constB, constC;
    std::int32_t out, a, b, c;
    double ca, cb, cc;
    double imm0, imm1;
};

namespace {

using Step = BatchEvaluator::Step;

template <typename F>
inline void unaryLoop(double* __restrict o, const double* __restrict a, std::size_t n, F f) {
    for (std::size_t i = 0; i < n; ++i)
        o[i] = f(a[i]);
}

template <typename F>
inline void binaryLoop(const Step& s, double* const* base, double* __restrict o, std::size_t n,
                       F f) {
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

// Number of reads of each step's result before its register is written again
// (a final output counts as one more read).
std::vector<int> useCounts(const std::vector<Step>& steps, const Tape& tape) {
    std::vector<int> uses(steps.size(), 0);
    std::vector<int> writer(static_cast<std::size_t>(tape.registerCount), -1);
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Step& s = steps[i];
        const int arity = opArity(s.op);
        auto read = [&](bool isConst, std::int32_t reg) {
            if (!isConst && writer[reg] >= 0) ++uses[writer[reg]];
        };
        read(s.constA, s.a);
        if (arity >= 2) read(s.constB, s.b);
        if (arity >= 3) read(s.constC, s.c);
        writer[s.out] = static_cast<int>(i);
    }
    for (const OutputInfo& o : tape.outputs)
        if (!o.value.isConst() && writer[o.value.reg] >= 0) ++uses[writer[o.value.reg]];
    return uses;
}

// Whether register `reg` is written by any step in (from, to).
bool writtenBetween(const std::vector<Step>& steps, std::size_t from, std::size_t to,
                    std::int32_t reg) {
    for (std::size_t k = from + 1; k < to; ++k)
        if (steps[k].out == reg) return true;
    return false;
}

// Index of the step that last wrote `reg` before step `at`, or -1.
int definingStep(const std::vector<Step>& steps, std::size_t at, std::int32_t reg) {
    for (std::size_t k = at; k-- > 0;)
        if (steps[k].out == reg) return static_cast<int>(k);
    return -1;
}

// Peephole: (a - c)^2 and A +/- (b - c)^2, the bread and butter of FRep
// primitives (sums of squared offsets), become single passes.
void fuseSquares(std::vector<Step>& steps, const Tape& tape) {
    std::vector<int> uses = useCounts(steps, tape);
    std::vector<char> dead(steps.size(), 0);
    for (std::size_t i = 0; i < steps.size(); ++i) {
        Step& s = steps[i];
        if (s.op == Op::Square && s.fused == Fused::None) {
            // square of (reg - const) or (reg + const) whose result feeds only this square
            int d = definingStep(steps, i, s.a);
            if (d < 0 || dead[d] || uses[d] != 1) continue;
            const Step& diff = steps[d];
            bool sub = diff.op == Op::Sub && !diff.constA && diff.constB;
            bool add = diff.op == Op::Add &&
                       ((!diff.constA && diff.constB) || (diff.constA && !diff.constB));
            if ((!sub && !add) || diff.fused != Fused::None) continue;
            std::int32_t reg = diff.constA ? diff.b : diff.a;
            double c = diff.constA ? diff.ca : diff.cb;
            if (add) c = -c; // x + c == x - (-c) exactly (IEEE subtraction adds the negation)
            if (writtenBetween(steps, static_cast<std::size_t>(d), i, reg) || s.out == reg)
                continue;
            s.fused = Fused::SquareOfDiff;
            s.a = reg;
            s.ca = c;
            dead[d] = 1;
        }
    }
    for (std::size_t i = 0; i < steps.size(); ++i) {
        Step& s = steps[i];
        if (dead[i] || s.fused != Fused::None || (s.op != Op::Add && s.op != Op::Sub)) continue;
        // which operand is a square used only here?
        for (int side = 1; side >= 0; --side) {
            if (s.op == Op::Sub && side == 0) break; // A - q only
            bool isConst = side ? s.constB : s.constA;
            std::int32_t reg = side ? s.b : s.a;
            if (isConst) continue;
            int q = definingStep(steps, i, reg);
            if (q < 0 || dead[q] || uses[q] != 1) continue;
            const Step& sq = steps[q];
            bool plain = sq.op == Op::Square && sq.fused == Fused::None;
            bool ofDiff = sq.op == Op::Square && sq.fused == Fused::SquareOfDiff;
            if (!plain && !ofDiff) continue;
            std::int32_t base = sq.a;
            if (writtenBetween(steps, static_cast<std::size_t>(q), i, base) || s.out == base)
                continue;
            // the other operand becomes A
            if (side == 0) {
                s.constA = s.constB;
                s.a = s.b;
                s.ca = s.cb;
            }
            s.fused = s.op == Op::Add ? Fused::AddSquare : Fused::SubSquare;
            s.constB = false;
            s.b = base;
            s.cb = ofDiff ? sq.ca : 0.0;
            dead[q] = 1;
            break;
        }
    }
    std::vector<Step> kept;
    kept.reserve(steps.size());
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (!dead[i]) kept.push_back(steps[i]);
    steps.swap(kept);
}

template <bool Add>
inline void squareTermLoop(const Step& s, double* const* base, double* o, std::size_t n) {
    // o may be b's register only if fuseSquares allowed it (it does not), so
    // these loops may assume no overlap between o and the operands
    const double cb = s.cb;
    const double* __restrict b = base[s.b];
    double* __restrict out = o;
    if (s.constA) {
        const double ca = s.ca;
        for (std::size_t i = 0; i < n; ++i) {
            double d = b[i] - cb;
            out[i] = Add ? ca + d * d : ca - d * d;
        }
    } else {
        const double* __restrict a = base[s.a];
        for (std::size_t i = 0; i < n; ++i) {
            double d = b[i] - cb;
            out[i] = Add ? a[i] + d * d : a[i] - d * d;
        }
    }
}

} // namespace

BatchEvaluator::BatchEvaluator(const Tape& tape) : tape_(tape), params_(tape) {
    const std::size_t regs = static_cast<std::size_t>(tape.registerCount);
    std::size_t bytes = (regs + 3) * kBlock * sizeof(double);
    workspace_ = static_cast<double*>(std::aligned_alloc(64, bytes));
    if (!workspace_) throw std::bad_alloc();
    std::memset(workspace_, 0, bytes);
    for (int k = 0; k < 3; ++k)
        scratch_[k] = workspace_ + (regs + k) * kBlock;
    uniformValue_.assign(regs, 0.0);
    isUniform_.assign(regs, 0);
}

BatchEvaluator::~BatchEvaluator() {
    std::free(workspace_);
}

void BatchEvaluator::specialise(const BatchInputs& in) {
    const std::vector<double>& pv = params_.values();
    bool same = specialised_ && specialisedParams_ == pv;
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
            double v = arity == 1   ? ops::unary(ins.op, s.ca, ins.imm0)
                       : arity == 2 ? ops::binary(ins.op, s.ca, s.cb, ins.imm0, ins.imm1)
                                    : ops::ternary(ins.op, s.ca, s.cb, s.cc);
            isUniform_[ins.out] = 1;
            uniformValue_[ins.out] = v;
            continue;
        }
        isUniform_[ins.out] = 0;
        steps_.push_back(s);
    }
    fuseSquares(steps_, tape_);
    specialised_ = true;
}

// Compiled twice — baseline and AVX2 — and picked at load time by the CPU, so
// the arithmetic loops run 4 lanes wide where they can. Without FMA contraction
// (-ffp-contract=off) both clones round exactly like the scalar evaluator.
__attribute__((target_clones("avx2", "default"))) void BatchEvaluator::runBlock(double* const* base,
                                                                                std::size_t n) {
    const vmath::Implementation& vm = vmath::implementation();
    for (const Step& s : steps_) {
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
            continue;
        }
        case Fused::AddSquare:
            squareTermLoop<true>(s, base, o, n);
            continue;
        case Fused::SubSquare:
            squareTermLoop<false>(s, base, o, n);
            continue;
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
            binaryLoop(s, base, o, n, [](double a, double b) {
                return cmpResult(ops::truth(a) && ops::truth(b));
            });
            break;
        case Op::Or:
            binaryLoop(s, base, o, n, [](double a, double b) {
                return cmpResult(ops::truth(a) || ops::truth(b));
            });
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
                    std::fill(scratch_[k], scratch_[k] + n, cval[k]);
                    p[k] = scratch_[k];
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
}

void BatchEvaluator::evaluate(const BatchInputs& in, std::size_t n, double* const* outputs) {
    specialise(in);
    const std::size_t regs = static_cast<std::size_t>(tape_.registerCount);
    std::vector<double*> base(regs);
    for (std::size_t r = 0; r < regs; ++r)
        base[r] = workspace_ + r * kBlock;
    for (std::size_t start = 0; start < n; start += kBlock) {
        const std::size_t count = std::min(kBlock, n - start);
        for (int i = 0; i < kInputCount; ++i)
            if (in.arrays[i]) base[i] = const_cast<double*>(in.arrays[i] + start); // read only
        runBlock(base.data(), count);
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
