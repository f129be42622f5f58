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

// What walkTape calls before each instruction of two or more operands, with
// the first two operands' values (the interval evaluator records there what
// each min, max and select decides: tape_simplify.h).
struct NoOperandHook {
    template <typename Value>
    void operator()(std::size_t, const Instruction&, const Value&, const Value&) const {}
};

template <typename Domain, typename Hook = NoOperandHook>
void walkTape(const Tape& tape, typename Domain::Value* regs, Hook hook = {}) {
    auto get = [regs](const Operand& o) {
        return o.isConst() ? Domain::constant(o.value) : regs[o.reg];
    };
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
        const Instruction& ins = tape.code[i];
        switch (opArity(ins.op)) {
        case 1:
            regs[ins.out] = Domain::unary(ins.op, get(ins.a), ins.imm0);
            break;
        case 2: {
            const typename Domain::Value a = get(ins.a), b = get(ins.b);
            hook(i, ins, a, b);
            regs[ins.out] = Domain::binary(ins.op, a, b, ins.imm0, ins.imm1);
            break;
        }
        default: {
            const typename Domain::Value a = get(ins.a), b = get(ins.b);
            hook(i, ins, a, b);
            regs[ins.out] = Domain::ternary(ins.op, a, b, get(ins.c));
            break;
        }
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
