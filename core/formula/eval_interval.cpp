#include "eval_interval.h"

#include "tape_walk.h"

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

namespace {
struct IntervalDomain {
    using Value = Interval;
    static Interval constant(double v) { return Interval::point(v); }
    static Interval unary(Op op, const Interval& a, double imm0) { return iv::unary(op, a, imm0); }
    static Interval binary(Op op, const Interval& a, const Interval& b, double imm0, double imm1) {
        return iv::binary(op, a, b, imm0, imm1);
    }
    static Interval ternary(Op op, const Interval& a, const Interval& b, const Interval& c) {
        return iv::ternary(op, a, b, c);
    }
};
} // namespace

IntervalEvaluator::IntervalEvaluator(const Tape& tape)
    : tape_(tape), params_(tape_), regs_(static_cast<std::size_t>(tape.registerCount)) {}

void IntervalEvaluator::load(const Box& box) {
    Interval* r = regs_.data();
    for (int i = 0; i < kInputCount; ++i)
        r[i] = box[i];
    const std::vector<double>& pv = params_.values();
    for (std::size_t i = 0; i < pv.size(); ++i)
        r[kInputCount + i] = Interval::point(pv[i]);
}

void IntervalEvaluator::run(const Box& box) {
    load(box);
    walkTape<IntervalDomain>(tape_, regs_.data());
}

Interval IntervalEvaluator::firstOutput() const {
    return tape_.outputs.empty() ? Interval::point(0.0)
                                 : tapeOutput<IntervalDomain>(tape_, regs_.data(), 0);
}

Interval IntervalEvaluator::evaluate(const Box& box) {
    run(box);
    return firstOutput();
}

Interval IntervalEvaluator::evaluate(const Box& box, std::vector<Keep>& keep) {
    load(box);
    keep.assign(tape_.code.size(), Keep::All);
    walkTape<IntervalDomain>(tape_, regs_.data(),
                             [&keep](std::size_t i, const Instruction& ins, const Interval& a,
                                     const Interval& b) { keep[i] = decide(ins.op, a, b); });
    return firstOutput();
}

void IntervalEvaluator::evaluateAll(const Box& box, Interval* outputs) {
    run(box);
    for (std::size_t i = 0; i < tape_.outputs.size(); ++i)
        outputs[i] = tapeOutput<IntervalDomain>(tape_, regs_.data(), i);
}

} // namespace fl::formula
