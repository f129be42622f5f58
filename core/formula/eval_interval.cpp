#include "eval_interval.h"

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

IntervalEvaluator::IntervalEvaluator(const Tape& tape)
    : tape_(tape), params_(tape), regs_(static_cast<std::size_t>(tape.registerCount)) {}

void IntervalEvaluator::run(const Box& box) {
    Interval* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = box[i];
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = Interval::point(pv[i]);
    auto get = [r](const Operand& o) { return o.isConst() ? Interval::point(o.value) : r[o.reg]; };
    for (const Instruction& ins : tape_.code) {
        switch (opArity(ins.op)) {
        case 1:
            r[ins.out] = iv::unary(ins.op, get(ins.a), ins.imm0);
            break;
        case 2:
            r[ins.out] = iv::binary(ins.op, get(ins.a), get(ins.b), ins.imm0, ins.imm1);
            break;
        default:
            r[ins.out] = iv::ternary(ins.op, get(ins.a), get(ins.b), get(ins.c));
            break;
        }
    }
}

Interval IntervalEvaluator::evaluate(const Box& box) {
    run(box);
    if (tape_.outputs.empty()) return Interval::point(0.0);
    const Operand& o = tape_.outputs[0].value;
    return o.isConst() ? Interval::point(o.value) : regs_[o.reg];
}

void IntervalEvaluator::evaluateAll(const Box& box, Interval* outputs) {
    run(box);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i) {
        const Operand& o = tape_.outputs[i].value;
        outputs[i] = o.isConst() ? Interval::point(o.value) : regs_[o.reg];
    }
}

} // namespace fl::formula
