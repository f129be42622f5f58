#include "operation_liveness.h"

#include "formula/opcodes.h"

#include <vector>

namespace fl::grading {
namespace {

using formula::Op;

field::ImplicitField withTape(const field::ImplicitField& f, formula::Tape tape) {
    field::ImplicitField out = f;
    out.tape = std::move(tape);
    return out;
}

bool readsRegister(const formula::Instruction& in, const std::vector<bool>& marked) {
    const formula::Operand* operands[3] = {&in.a, &in.b, &in.c};
    for (int k = 0; k < formula::opArity(in.op); ++k)
        if (!operands[k]->isConst() && marked[std::size_t(operands[k]->reg)]) return true;
    return false;
}

// Whether the sign of the field (inside or not) is decided by the sign of
// the value instruction `index` writes, wherever the other operands are:
// every use on the way to the output is a set operation (min, max, the
// R-functions: R∩ > 0 exactly where both are, R∪ where either is), a
// negation, adding 0 or scaling by a positive constant.
bool signCarriesThrough(const formula::Tape& tape, std::size_t index) {
    std::vector<bool> carries(std::size_t(tape.registerCount), false);
    carries[std::size_t(tape.code[index].out)] = true;
    for (std::size_t i = index + 1; i < tape.code.size(); ++i) {
        const formula::Instruction& in = tape.code[i];
        if (!readsRegister(in, carries)) continue;
        const auto constantOther = [&](double& value) {
            const bool aMarked = !in.a.isConst() && carries[std::size_t(in.a.reg)];
            const formula::Operand& other = aMarked ? in.b : in.a;
            value = other.value;
            return other.isConst();
        };
        double c = 0;
        switch (in.op) {
        case Op::Min:
        case Op::Max:
        case Op::RIntersect:
        case Op::RUnion:
        case Op::Neg:
            break;
        case Op::Add:
            if (!constantOther(c) || c != 0) return false;
            break;
        case Op::Mul:
            if (!constantOther(c) || !(c > 0)) return false;
            break;
        default:
            return false;
        }
        carries[std::size_t(in.out)] = true;
    }
    return true;
}

// A tape whose value is > 0 only where the field's sign may change when the
// set operation at `index` is replaced by its operand `kept`: cells where it
// stays <= 0 are the same solid without looking further.
// - Where the sign carries through (see above), the signs decide: an
//   intersection (min, R∩) differs from its kept operand a only where a is
//   inside and the other outside, min(a, -b); a union (max, R∪) only where
//   a is outside and the other inside, min(-a, b).
// - Else, for min and max, where the values differ: min(a, b) is a where
//   a <= b (activity a - b); max(a, b) where a >= b (activity b - a).
// - Else (an R-function feeding arithmetic): none.
std::optional<formula::Tape> activityOf(const formula::Tape& tape, std::size_t index, int kept) {
    const Op op = tape.code[index].op;
    const bool intersection = op == Op::Min || op == Op::RIntersect;
    const bool setOperation = intersection || op == Op::Max || op == Op::RUnion;
    if (setOperation && signCarriesThrough(tape, index)) {
        formula::Tape t = tape;
        const formula::Instruction at = tape.code[index];
        t.code.resize(index);
        const formula::Operand keptOperand = kept == 0 ? at.a : at.b;
        const formula::Operand other = kept == 0 ? at.b : at.a;
        auto emit = [&](Op o, formula::Operand a, formula::Operand b = {}) {
            formula::Instruction in;
            in.op = o;
            in.out = t.registerCount++;
            in.a = a;
            in.b = b;
            in.origin = at.origin;
            t.code.push_back(in);
            return formula::Operand::ofReg(in.out);
        };
        const formula::Operand result = intersection
                                            ? emit(Op::Min, keptOperand, emit(Op::Neg, other))
                                            : emit(Op::Min, emit(Op::Neg, keptOperand), other);
        t.outputs = {{"value", result}};
        return t;
    }
    // min(a, b) differs from a where b < a: activity a - b; from b where a < b.
    if (op == Op::Min) return operandGap(tape, index, kept);
    // max(a, b) differs from a where b > a: activity b - a.
    if (op == Op::Max) return operandGap(tape, index, 1 - kept);
    return std::nullopt;
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
