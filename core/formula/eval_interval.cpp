#include "eval_interval.h"

#include "interval_ops.h"

namespace fl::formula {

Box boxXYZ(double x0, double x1, double y0, double y1, double z0, double z1, double t) {
    Box b;
    for (Interval& i : b)
        i = Interval::point(0.0);
    b[0] = Interval::of(x0, x1);
    b[1] = Interval::of(y0, y1);
    b[2] = Interval::of(z0, z1);
    b[3] = Interval::point(t);
    return b;
}

IntervalEvaluator::IntervalEvaluator(const Tape& tape) : tape_(tape), params_(tape_) {
    std::vector<double> constants;
    auto reg = [&](const Operand& o) {
        if (!o.isConst()) return o.reg;
        constants.push_back(o.value);
        return std::int32_t(tape_.registerCount + std::int32_t(constants.size()) - 1);
    };
    steps_.reserve(tape_.code.size());
    for (const Instruction& ins : tape_.code) {
        const int arity = opArity(ins.op);
        Step s{ins.op, ins.out, reg(ins.a), 0, 0, ins.imm0, ins.imm1};
        s.b = arity >= 2 ? reg(ins.b) : s.a;
        s.c = arity >= 3 ? reg(ins.c) : s.a;
        steps_.push_back(s);
    }
    for (const OutputInfo& o : tape_.outputs)
        outputs_.push_back(reg(o.value));
    regs_.resize(std::size_t(tape_.registerCount) + constants.size());
    for (std::size_t i = 0; i < constants.size(); ++i)
        regs_[std::size_t(tape_.registerCount) + i] = Interval::point(constants[i]);
}

void IntervalEvaluator::load(const Box& box) {
    Interval* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = box[std::size_t(i)];
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = Interval::point(pv[i]);
}

// The operations a formula is mostly made of run inline; the rest through
// iv::unary, iv::binary and iv::ternary (the same code: interval_ops.h).
// With kRecord, what the box decides at each min, max and select is
// recorded for simplifyTape.
template <bool kRecord>
void IntervalEvaluator::run(std::vector<Keep>* keep) {
    Interval* r = regs_.data();
    for (std::size_t i = 0; i < steps_.size(); ++i) {
        const Step& s = steps_[i];
        const Interval& a = r[s.a];
        const Interval& b = r[s.b];
        if constexpr (kRecord) // (decide keeps all of every other operation)
            if (s.op == Op::Min || s.op == Op::Max || s.op == Op::Select)
                (*keep)[i] = decide(s.op, a, b);
        Interval v;
        switch (s.op) {
        case Op::Add:
            v = iv::add(a, b);
            break;
        case Op::Sub:
            v = iv::sub(a, b);
            break;
        case Op::Mul:
            v = iv::mul(a, b);
            break;
        case Op::Min:
            v = iv::min(a, b);
            break;
        case Op::Max:
            v = iv::max(a, b);
            break;
        case Op::Neg:
            v = iv::neg(a);
            break;
        case Op::Square:
            v = iv::square(a);
            break;
        default:
            switch (opArity(s.op)) {
            case 1:
                v = iv::unary(s.op, a, s.imm0);
                break;
            case 2:
                v = iv::binary(s.op, a, b, s.imm0, s.imm1);
                break;
            default:
                v = iv::ternary(s.op, a, b, r[s.c]);
                break;
            }
        }
        r[s.out] = v;
    }
}

Interval IntervalEvaluator::evaluate(const Box& box) {
    load(box);
    run<false>(nullptr);
    return firstOutput();
}

Interval IntervalEvaluator::evaluate(const Box& box, std::vector<Keep>& keep) {
    load(box);
    keep.assign(steps_.size(), Keep::All);
    run<true>(&keep);
    return firstOutput();
}

void IntervalEvaluator::evaluateAll(const Box& box, Interval* outputs) {
    load(box);
    run<false>(nullptr);
    for (std::size_t i = 0; i < outputs_.size(); ++i)
        outputs[i] = output(i);
}

} // namespace fl::formula
