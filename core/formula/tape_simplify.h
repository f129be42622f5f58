#pragma once
// Tape simplification over a region (issue 31 §1, as libfive and Fidget do
// it): where an interval evaluation over a box shows that a min or max
// always takes the same operand, or a select always the same branch, the
// operation is the identity of that operand everywhere in the box, and the
// other operand's whole subtree is dead there. The simplified tape computes
// the same bits as the full one at every point of the box — values,
// gradients and intervals of sub-boxes alike — with fewer instructions.
//
// The decision is exact, not approximate: min(a, b) keeps a only where
// a.hi < b.lo (strictly, so no tie's signed zero is at stake) and b can
// never be NaN (min propagates a NaN from either side: dropping a NaN
// operand would change the result). A caller must evaluate the simplified
// tape only inside the box the choices were made for.
#include "interval.h"
#include "tape.h"

#include <cstdint>
#include <vector>

namespace fl::formula {

// Which operands of an instruction the region needs.
enum class Keep : std::uint8_t {
    All, // undecided (and every instruction that is not a choice)
    A,   // min/max: the first operand
    B,   // min/max: the second; select: the value if true
    C,   // select: the value if false
};

// Whether the tape has an instruction an interval may decide (min, max,
// select): otherwise there is nothing to simplify.
bool hasChoices(const Tape& tape);

// What the intervals of an instruction's first two operands over a region
// decide (a select's condition is its first).
Keep decide(Op op, const Interval& a, const Interval& b);

// The tape with every decided instruction replaced by the operand it keeps,
// then dead code dropped and registers assigned again. An operation whose
// operands all became constants stays an operation (not folded): the
// interval evaluator widens its result by two ulps as it does on the full
// tape, so the simplified tape's intervals are the full tape's and the
// mesher prunes the same blocks (its warnings depend on which).
// `keep` has one entry per instruction of tape.code. Inputs, parameters and
// outputs keep their registers' meaning (the evaluators' parameter names
// still apply); origins are kept, so diagnostics still point at the source.
// `source`, when given, receives for each instruction of the result the
// index of the instruction of `tape` it is (to carry later decisions back).
Tape simplifyTape(const Tape& tape, const std::vector<Keep>& keep,
                  std::vector<std::int32_t>* source = nullptr);

} // namespace fl::formula
