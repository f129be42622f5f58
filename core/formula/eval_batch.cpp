#include "eval_batch.h"

#include "scalar_ops.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

namespace fl::formula {

struct BatchEvaluator::Step {
    Op op;
    bool constA, constB, constC;
    std::int32_t out, a, b, c;
    double ca, cb, cc;
    double imm0, imm1;
};

namespace {

using Step = BatchEvaluator::Step;

template <typename F>
inline void unaryLoop(double* __restrict o, const double* __restrict a, std::size_t n, F f) {
    for (std::size_t i = 0; i < n; ++i) o[i] = f(a[i]);
}

template <typename F>
inline void binaryLoop(const Step& s, double* const* base, double* __restrict o, std::size_t n, F f) {
    if (s.constA) {
        const double ca = s.ca;
        const double* __restrict b = base[s.b];
        for (std::size_t i = 0; i < n; ++i) o[i] = f(ca, b[i]);
    } else if (s.constB) {
        const double cb = s.cb;
        const double* __restrict a = base[s.a];
        for (std::size_t i = 0; i < n; ++i) o[i] = f(a[i], cb);
    } else {
        const double* __restrict a = base[s.a];
        const double* __restrict b = base[s.b];
        for (std::size_t i = 0; i < n; ++i) o[i] = f(a[i], b[i]);
    }
}

inline double cmpResult(bool v) { return v ? 1.0 : 0.0; }

} // namespace

BatchEvaluator::BatchEvaluator(const Tape& tape) : tape_(tape), params_(tape) {
    const std::size_t regs = static_cast<std::size_t>(tape.registerCount);
    std::size_t bytes = (regs + 3) * kBlock * sizeof(double);
    workspace_ = static_cast<double*>(std::aligned_alloc(64, bytes));
    if (!workspace_) throw std::bad_alloc();
    std::memset(workspace_, 0, bytes);
    for (int k = 0; k < 3; ++k) scratch_[k] = workspace_ + (regs + k) * kBlock;
    uniformValue_.assign(regs, 0.0);
    isUniform_.assign(regs, 0);
}

BatchEvaluator::~BatchEvaluator() { std::free(workspace_); }

void BatchEvaluator::specialise(const BatchInputs& in) {
    const std::vector<double>& pv = params_.values();
    bool same = specialised_ && specialisedParams_ == pv;
    for (int i = 0; same && i < kInputCount; ++i) {
        bool varying = in.arrays[i] != nullptr;
        same = specialisedVarying_[i] == varying &&
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
    specialised_ = true;
}

void BatchEvaluator::runBlock(double* const* base, std::size_t n) {
    for (const Step& s : steps_) {
        double* __restrict o = base[s.out];
        switch (s.op) {
        // ---- unary (the operand always varies: uniform ones were folded)
        case Op::Neg: unaryLoop(o, base[s.a], n, [](double a) { return -a; }); break;
        case Op::Abs: unaryLoop(o, base[s.a], n, [](double a) { return std::fabs(a); }); break;
        case Op::Square: unaryLoop(o, base[s.a], n, [](double a) { return a * a; }); break;
        case Op::Sqrt: unaryLoop(o, base[s.a], n, [](double a) { return std::sqrt(a); }); break;
        case Op::Cbrt: unaryLoop(o, base[s.a], n, [](double a) { return std::cbrt(a); }); break;
        case Op::Exp: unaryLoop(o, base[s.a], n, [](double a) { return std::exp(a); }); break;
        case Op::Log: unaryLoop(o, base[s.a], n, [](double a) { return std::log(a); }); break;
        case Op::Log2: unaryLoop(o, base[s.a], n, [](double a) { return std::log2(a); }); break;
        case Op::Log10: unaryLoop(o, base[s.a], n, [](double a) { return std::log10(a); }); break;
        case Op::Sin: unaryLoop(o, base[s.a], n, [](double a) { return std::sin(a); }); break;
        case Op::Cos: unaryLoop(o, base[s.a], n, [](double a) { return std::cos(a); }); break;
        case Op::Tan: unaryLoop(o, base[s.a], n, [](double a) { return std::tan(a); }); break;
        case Op::Asin: unaryLoop(o, base[s.a], n, [](double a) { return std::asin(a); }); break;
        case Op::Acos: unaryLoop(o, base[s.a], n, [](double a) { return std::acos(a); }); break;
        case Op::Atan: unaryLoop(o, base[s.a], n, [](double a) { return std::atan(a); }); break;
        case Op::Sinh: unaryLoop(o, base[s.a], n, [](double a) { return std::sinh(a); }); break;
        case Op::Cosh: unaryLoop(o, base[s.a], n, [](double a) { return std::cosh(a); }); break;
        case Op::Tanh: unaryLoop(o, base[s.a], n, [](double a) { return std::tanh(a); }); break;
        case Op::Floor: unaryLoop(o, base[s.a], n, [](double a) { return std::floor(a); }); break;
        case Op::Ceil: unaryLoop(o, base[s.a], n, [](double a) { return std::ceil(a); }); break;
        case Op::Round: unaryLoop(o, base[s.a], n, [](double a) { return std::round(a); }); break;
        case Op::Sign: unaryLoop(o, base[s.a], n, [](double a) { return ops::sign(a); }); break;
        case Op::Not: unaryLoop(o, base[s.a], n, [](double a) { return ops::truth(a) ? 0.0 : 1.0; }); break;
        case Op::PowI: {
            const int k = static_cast<int>(s.imm0);
            if (k == 3) unaryLoop(o, base[s.a], n, [](double a) { return a * a * a; });
            else if (k == 4) unaryLoop(o, base[s.a], n, [](double a) { double q = a * a; return q * q; });
            else if (k == -1) unaryLoop(o, base[s.a], n, [](double a) { return 1.0 / a; });
            else if (k == -2) unaryLoop(o, base[s.a], n, [](double a) { return 1.0 / (a * a); });
            else unaryLoop(o, base[s.a], n, [k](double a) { return ops::powi(a, k); });
            break;
        }
        // ---- binary
        case Op::Add: binaryLoop(s, base, o, n, [](double a, double b) { return a + b; }); break;
        case Op::Sub: binaryLoop(s, base, o, n, [](double a, double b) { return a - b; }); break;
        case Op::Mul: binaryLoop(s, base, o, n, [](double a, double b) { return a * b; }); break;
        case Op::Div: binaryLoop(s, base, o, n, [](double a, double b) { return a / b; }); break;
        case Op::Pow: binaryLoop(s, base, o, n, [](double a, double b) { return std::pow(a, b); }); break;
        case Op::Min: binaryLoop(s, base, o, n, [](double a, double b) { return ops::min(a, b); }); break;
        case Op::Max: binaryLoop(s, base, o, n, [](double a, double b) { return ops::max(a, b); }); break;
        case Op::Atan2: binaryLoop(s, base, o, n, [](double a, double b) { return std::atan2(a, b); }); break;
        case Op::Hypot: binaryLoop(s, base, o, n, [](double a, double b) { return std::hypot(a, b); }); break;
        case Op::Mod: binaryLoop(s, base, o, n, [](double a, double b) { return ops::mod(a, b); }); break;
        case Op::Less: binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a < b); }); break;
        case Op::LessEq: binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a <= b); }); break;
        case Op::Greater: binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a > b); }); break;
        case Op::GreaterEq: binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a >= b); }); break;
        case Op::Equal: binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a == b); }); break;
        case Op::NotEqual: binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(a != b); }); break;
        case Op::And:
            binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(ops::truth(a) && ops::truth(b)); });
            break;
        case Op::Or:
            binaryLoop(s, base, o, n, [](double a, double b) { return cmpResult(ops::truth(a) || ops::truth(b)); });
            break;
        case Op::RIntersect: {
            const double m = s.imm0, alpha = s.imm1;
            if (m == 0.0 && alpha == 0.0)
                binaryLoop(s, base, o, n, [](double a, double b) { return rIntersect0(a, b); });
            else
                binaryLoop(s, base, o, n, [m, alpha](double a, double b) { return rIntersect(a, b, m, alpha); });
            break;
        }
        case Op::RUnion: {
            const double m = s.imm0, alpha = s.imm1;
            if (m == 0.0 && alpha == 0.0)
                binaryLoop(s, base, o, n, [](double a, double b) { return rUnion0(a, b); });
            else
                binaryLoop(s, base, o, n, [m, alpha](double a, double b) { return rUnion(a, b, m, alpha); });
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
                for (std::size_t i = 0; i < n; ++i) o[i] = ops::truth(p[0][i]) ? p[1][i] : p[2][i];
            } else {
                for (std::size_t i = 0; i < n; ++i) o[i] = noise3(p[0][i], p[1][i], p[2][i]);
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
    for (std::size_t r = 0; r < regs; ++r) base[r] = workspace_ + r * kBlock;
    for (std::size_t start = 0; start < n; start += kBlock) {
        const std::size_t count = std::min(kBlock, n - start);
        for (int i = 0; i < kInputCount; ++i)
            if (in.arrays[i]) base[i] = const_cast<double*>(in.arrays[i] + start); // read only
        runBlock(base.data(), count);
        for (std::size_t k = 0; k < tape_.outputs.size(); ++k) {
            const Operand& o = tape_.outputs[k].value;
            double* dst = outputs[k] + start;
            if (o.isConst()) std::fill(dst, dst + count, o.value);
            else if (isUniform_[o.reg]) std::fill(dst, dst + count, uniformValue_[o.reg]);
            else std::memcpy(dst, base[o.reg], count * sizeof(double));
        }
    }
}

} // namespace fl::formula
