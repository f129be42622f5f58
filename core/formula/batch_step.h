#pragma once
// One instruction of the batch evaluator after specialisation: operands that
// are uniform for the call became constants, and hot sequences may have been
// fused into one pass (batch_fusion.h). Private to the batch evaluator.
#include "opcodes.h"

#include <cstdint>

namespace fl::formula {

enum class Fused : std::uint8_t {
    None,
    SquareOfDiff,   // out = (a - ca)^2
    SquareTerms,    // out = A + sign[0]*(r[0] - off[0])^2 + ... (1 to 3 terms, in order)
    NegatedOperand, // op (min or max) with operand a (negA) or b (negB) negated first
    MinMaxChain,    // op(op(op(r0, r1), r2), r3): 3 or 4 registers, each maybe negated
    SinCos,         // out = sincos.sin(a), out2 = sincos.cos(a): a paired sin and cos
};

struct BatchStep {
    Op op = Op::Add;
    Fused fused = Fused::None;
    bool constA = false, constB = false, constC = false;
    std::int32_t out = 0, a = 0, b = 0, c = 0;
    std::int32_t out2 = 0; // SinCos: the cosines' register
    double ca = 0.0, cb = 0.0, cc = 0.0;
    double imm0 = 0.0, imm1 = 0.0;
    // SquareTerms (A is operand a)
    std::uint8_t terms = 0;
    std::int32_t termReg[3] = {0, 0, 0};
    double termOffset[3] = {0.0, 0.0, 0.0};
    double termSign[3] = {1.0, 1.0, 1.0};
    // NegatedOperand
    bool negA = false, negB = false;
    // MinMaxChain (left to right, exactly the nesting it replaces)
    std::uint8_t chainCount = 0;
    std::int32_t chainReg[4] = {0, 0, 0, 0};
    double chainSign[4] = {1.0, 1.0, 1.0, 1.0}; // -1: the operand is negated first
};

// Calls f on each register field the step reads, in the order it reads them
// (a step's own fields: const for a const step, else references a caller may
// rename).
template <class Step, class F>
void forEachRead(Step& s, F&& f) {
    switch (s.fused) {
    case Fused::SquareOfDiff:
    case Fused::SinCos:
        f(s.a);
        return;
    case Fused::SquareTerms:
        if (!s.constA) f(s.a);
        for (int t = 0; t < s.terms; ++t)
            f(s.termReg[t]);
        return;
    case Fused::MinMaxChain:
        for (int t = 0; t < s.chainCount; ++t)
            f(s.chainReg[t]);
        return;
    case Fused::NegatedOperand:
    case Fused::None:
        break;
    }
    const int arity = opArity(s.op);
    if (!s.constA) f(s.a);
    if (arity >= 2 && !s.constB) f(s.b);
    if (arity >= 3 && !s.constC) f(s.c);
}

} // namespace fl::formula
