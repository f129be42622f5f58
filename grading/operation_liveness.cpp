#include "operation_liveness.h"

namespace fl::grading {
namespace {

using formula::Op;

field::ImplicitField withTape(const field::ImplicitField& f, formula::Tape tape) {
    field::ImplicitField out = f;
    out.tape = std::move(tape);
    return out;
}

// Min and Max equal operand `kept` wherever the gap (other - kept for min,
// kept - other for max) ... is such that the kept one wins: the activity is
// > 0 only where the result and the kept operand may differ.
std::optional<formula::Tape> activityOf(const formula::Tape& tape, std::size_t index, int kept) {
    const Op op = tape.code[index].op;
    // min(a, b) differs from a where b < a: activity a - b; from b where a < b.
    if (op == Op::Min) return operandGap(tape, index, kept);
    // max(a, b) differs from a where b > a: activity b - a.
    if (op == Op::Max) return operandGap(tape, index, 1 - kept);
    return std::nullopt; // R-functions differ from both operands almost everywhere
}

OperandSign signOver(const field::ImplicitField& f, const formula::Tape& tape, std::size_t index,
                     int which, Budget& budget) {
    if (!budget.spend(4 * cost(f))) return OperandSign::Mixed;
    // The operand's value: the gap tape's prefix with the operand as output.
    formula::Tape prefix = tape;
    const formula::Instruction op = tape.code[index];
    prefix.code.resize(index);
    prefix.outputs = {{"value", which == 0 ? op.a : op.b}};
    field::ImplicitField g = withTape(f, std::move(prefix));
    g.displacement.reset();
    g.boundary = field::BoxBoundary::Open;
    field::FieldSampler s(g);
    const formula::Interval r = s.interval(g.box.lo, g.box.hi);
    if (r.empty() || r.nan) return OperandSign::Mixed;
    if (r.lo > 0) return OperandSign::Positive;
    if (r.hi <= 0) return OperandSign::Negative;
    return OperandSign::Mixed;
}

} // namespace

std::optional<std::size_t> operandWriter(const formula::Tape& tape, std::size_t index, int which) {
    const formula::Operand& o = which == 0 ? tape.code[index].a : tape.code[index].b;
    if (o.isConst()) return std::nullopt;
    for (std::size_t i = index; i-- > 0;)
        if (tape.code[i].out == o.reg) return i;
    return std::nullopt;
}

OperationVerdict judgeOperation(const field::ImplicitField& field,
                                const TapeSetOperation& operation, Budget& budget,
                                const CompareOptions& options) {
    OperationVerdict v;
    v.operation = operation;
    for (int kept = 0; kept < 2; ++kept) {
        const field::ImplicitField without =
            withTape(field, withOperationReplaced(field.tape, operation.instruction, kept));
        const std::optional<formula::Tape> gap =
            activityOf(field.tape, operation.instruction, kept);
        std::optional<field::ImplicitField> activity;
        if (gap) {
            activity = withTape(field, *gap);
            activity->displacement.reset();
        }
        const SolidComparison c =
            compareSolids(field, without, activity ? &*activity : nullptr, budget, options);
        v.unresolvedCells += c.unresolvedCells;
        if (c.result == Sameness::Unknown) {
            v.undecided = true;
            return v;
        }
        if (c.result == Sameness::Same) {
            // Keeping operand `kept` alone shows the same solid: the other is idle.
            v.idleOperand = 1 - kept;
            v.idleSign = signOver(field, field.tape, operation.instruction, v.idleOperand, budget);
            return v;
        }
        if (kept == 0) v.witness = c.witness;
    }
    v.counts = true;
    return v;
}

} // namespace fl::grading
