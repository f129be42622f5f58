#pragma once
// The interpreter loop shared by the point-wise evaluators (scalar, interval,
// gradient): one place resolves operands and dispatches on arity; each
// evaluator supplies a Domain with its value type and operations:
//
//   struct Domain {
//       using Value = ...;
//       static Value constant(double);
//       static Value unary(Op, const Value&, double imm0);
//       static Value binary(Op, const Value&, const Value&, double imm0, double imm1);
//       static Value ternary(Op, const Value&, const Value&, const Value&);
//   };
#include "tape.h"

#include <cstddef>

namespace fl::formula {

template <typename Domain>
void walkTape(const Tape& tape, typename Domain::Value* regs) {
    auto get = [regs](const Operand& o) {
        return o.isConst() ? Domain::constant(o.value) : regs[o.reg];
    };
    for (const Instruction& ins : tape.code) {
        switch (opArity(ins.op)) {
        case 1:
            regs[ins.out] = Domain::unary(ins.op, get(ins.a), ins.imm0);
            break;
        case 2:
            regs[ins.out] = Domain::binary(ins.op, get(ins.a), get(ins.b), ins.imm0, ins.imm1);
            break;
        default:
            regs[ins.out] = Domain::ternary(ins.op, get(ins.a), get(ins.b), get(ins.c));
            break;
        }
    }
}

// The tape's i-th output after a walk.
template <typename Domain>
typename Domain::Value tapeOutput(const Tape& tape, const typename Domain::Value* regs,
                                  std::size_t i) {
    const Operand& o = tape.outputs[i].value;
    return o.isConst() ? Domain::constant(o.value) : regs[o.reg];
}

} // namespace fl::formula
