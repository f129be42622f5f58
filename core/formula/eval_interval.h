#pragma once
// Evaluates a tape over a box: the result contains every point value the
// scalar evaluator can produce inside it (the mesher's license to skip space).
#include "eval_scalar.h"
#include "interval.h"
#include "tape_simplify.h"

#include <array>
#include <vector>

namespace fl::formula {

using Box = std::array<Interval, kInputCount>;

// A box over x, y, z with t fixed (the mesher's usual question).
Box boxXYZ(double x0, double x1, double y0, double y1, double z0, double z1, double t = 0.0);

class IntervalEvaluator {
  public:
    explicit IntervalEvaluator(const Tape& tape);

    ParameterValues& parameters() { return params_; }

    Interval evaluate(const Box& box);
    // The same, and what the box decides at each instruction (one entry per
    // instruction: which operand a min, max or select keeps everywhere in
    // the box), for simplifyTape.
    Interval evaluate(const Box& box, std::vector<Keep>& keep);
    void evaluateAll(const Box& box, Interval* outputs);

  private:
    // An instruction with its operands as registers: constants are loaded
    // once, into registers past the tape's own, so the loop never builds
    // an interval from a number (the tape's instructions, one for one).
    struct Step {
        Op op;
        std::int32_t out, a, b, c;
        double imm0, imm1;
    };

    const Tape tape_; // a copy: evaluators never dangle when a CompileResult goes away
    ParameterValues params_;
    std::vector<Step> steps_;
    std::vector<std::int32_t> outputs_; // the register each output is in
    std::vector<Interval> regs_;
    void load(const Box& box);
    template <bool kRecord>
    void run(std::vector<Keep>* keep);
    Interval output(std::size_t i) const { return regs_[std::size_t(outputs_[i])]; }
    Interval firstOutput() const { return outputs_.empty() ? Interval::point(0.0) : output(0); }
};

} // namespace fl::formula
