#include "set_operations.h"

namespace fl::grading {

std::string_view setOperationKindName(SetOperationKind kind) {
    switch (kind) {
    case SetOperationKind::Intersection:
        return "intersection";
    case SetOperationKind::Union:
        return "union";
    case SetOperationKind::Difference:
        return "difference";
    }
    return "?";
}

std::vector<TapeSetOperation> setOperationsIn(const formula::Tape& tape) {
    using formula::Op;
    // Which instruction last wrote each register (registers are reused).
    std::vector<std::ptrdiff_t> writer(std::size_t(tape.registerCount), -1);
    auto negated = [&](const formula::Operand& o) {
        if (o.isConst() || o.reg < 0 || std::size_t(o.reg) >= writer.size()) return false;
        const std::ptrdiff_t w = writer[std::size_t(o.reg)];
        return w >= 0 && tape.code[std::size_t(w)].op == Op::Neg;
    };
    std::vector<TapeSetOperation> out;
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
        const formula::Instruction& in = tape.code[i];
        const bool meet = in.op == Op::Min || in.op == Op::RIntersect;
        const bool join = in.op == Op::Max || in.op == Op::RUnion;
        // An operation with a constant operand cuts by a level, not by a solid.
        if ((meet || join) && !in.a.isConst() && !in.b.isConst()) {
            SetOperationKind kind = meet ? SetOperationKind::Intersection : SetOperationKind::Union;
            if (meet && negated(in.b)) kind = SetOperationKind::Difference;
            out.push_back({i, kind});
        }
        if (in.out >= 0 && std::size_t(in.out) < writer.size())
            writer[std::size_t(in.out)] = std::ptrdiff_t(i);
    }
    return out;
}

formula::Tape withOperationReplaced(const formula::Tape& tape, std::size_t index, int operand) {
    formula::Tape t = tape;
    formula::Instruction& in = t.code[index];
    const formula::Operand kept = operand == 0 ? in.a : in.b;
    in.op = formula::Op::Add; // kept + 0: a copy (-0 becomes +0: the same side)
    in.a = kept;
    in.b = formula::Operand::constant(0);
    in.c = {};
    in.imm0 = in.imm1 = 0;
    return t;
}

formula::Tape operandGap(const formula::Tape& tape, std::size_t index, int which) {
    formula::Tape t = tape;
    const formula::Instruction op = tape.code[index];
    t.code.resize(index);
    formula::Instruction gap;
    gap.op = formula::Op::Sub;
    gap.out = t.registerCount++;
    gap.a = which == 0 ? op.a : op.b;
    gap.b = which == 0 ? op.b : op.a;
    gap.origin = op.origin;
    t.code.push_back(gap);
    t.outputs = {{"value", formula::Operand::ofReg(gap.out)}};
    return t;
}

} // namespace fl::grading
