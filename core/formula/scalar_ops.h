#pragma once
// Point semantics of every opcode, shared by the scalar and batch evaluators
// and the constant folder so that all of them agree bit for bit.
//
// Truth: a value is true when it is non-zero and not NaN; comparisons and
// logic give exactly 0 or 1. NaN and infinities follow IEEE 754 and never trap.
#include "minmax.h"
#include "noise.h"
#include "opcodes.h"
#include "rfunctions.h"
#include "vector_math.h"

#include <cmath>

namespace fl::formula::ops {

inline bool truth(double v) {
    return v < 0.0 || v > 0.0;
}

inline double powi(double a, int n) {
    // exact repeated squaring for |n| small; sign of negative bases is right
    // for every integer n (-2)^3 = -8.
    unsigned m = n < 0 ? 0u - static_cast<unsigned>(n) : static_cast<unsigned>(n);
    double r = 1.0, base = a;
    while (m) {
        if (m & 1u) r *= base;
        base *= base;
        m >>= 1;
    }
    return n < 0 ? 1.0 / r : r;
}

// GLSL-style modulo: the result has the sign of b; mod(a, 0) is NaN.
inline double mod(double a, double b) {
    double r = std::fmod(a, b);
    if (r != 0.0 && ((r < 0.0) != (b < 0.0))) r += b;
    return r;
}

// min and max: NaN-propagating, operand order kept (minmax.h)
inline double min(double a, double b) {
    return minPropagating(a, b);
}
inline double max(double a, double b) {
    return maxPropagating(a, b);
}

inline double sign(double a) {
    return a > 0.0 ? 1.0 : (a < 0.0 ? -1.0 : (a == 0.0 ? 0.0 : a));
}

inline double unary(Op op, double a, double imm0) {
    switch (op) {
    case Op::Neg:
        return -a;
    case Op::Abs:
        return std::fabs(a);
    case Op::Square:
        return a * a;
    case Op::Sqrt:
        return std::sqrt(a);
    case Op::Cbrt:
        return vmath::eval(vmath::Unary::Cbrt, a);
    case Op::Exp:
        return vmath::eval(vmath::Unary::Exp, a);
    case Op::Log:
        return vmath::eval(vmath::Unary::Log, a);
    case Op::Log2:
        return vmath::eval(vmath::Unary::Log2, a);
    case Op::Log10:
        return vmath::eval(vmath::Unary::Log10, a);
    case Op::Sin:
        return vmath::eval(vmath::Unary::Sin, a);
    case Op::Cos:
        return vmath::eval(vmath::Unary::Cos, a);
    case Op::SinOfPair:
        return vmath::sinCos(a).sin;
    case Op::CosOfPair:
        return vmath::sinCos(a).cos;
    case Op::Tan:
        return vmath::eval(vmath::Unary::Tan, a);
    case Op::Asin:
        return vmath::eval(vmath::Unary::Asin, a);
    case Op::Acos:
        return vmath::eval(vmath::Unary::Acos, a);
    case Op::Atan:
        return vmath::eval(vmath::Unary::Atan, a);
    case Op::Sinh:
        return vmath::eval(vmath::Unary::Sinh, a);
    case Op::Cosh:
        return vmath::eval(vmath::Unary::Cosh, a);
    case Op::Tanh:
        return vmath::eval(vmath::Unary::Tanh, a);
    case Op::Floor:
        return std::floor(a);
    case Op::Ceil:
        return std::ceil(a);
    case Op::Round:
        return std::round(a);
    case Op::Sign:
        return sign(a);
    case Op::Not:
        return truth(a) ? 0.0 : 1.0;
    case Op::PowI:
        return powi(a, static_cast<int>(imm0));
    default:
        return NAN;
    }
}

inline double binary(Op op, double a, double b, double imm0, double imm1) {
    switch (op) {
    case Op::Add:
        return a + b;
    case Op::Sub:
        return a - b;
    case Op::Mul:
        return a * b;
    case Op::Div:
        return a / b;
    case Op::Pow:
        return vmath::eval(vmath::Binary::Pow, a, b);
    case Op::Min:
        return min(a, b);
    case Op::Max:
        return max(a, b);
    case Op::Atan2:
        return vmath::eval(vmath::Binary::Atan2, a, b);
    case Op::Hypot:
        return std::hypot(a, b);
    case Op::Mod:
        return mod(a, b);
    case Op::Less:
        return a < b ? 1.0 : 0.0;
    case Op::LessEq:
        return a <= b ? 1.0 : 0.0;
    case Op::Greater:
        return a > b ? 1.0 : 0.0;
    case Op::GreaterEq:
        return a >= b ? 1.0 : 0.0;
    case Op::Equal:
        return a == b ? 1.0 : 0.0;
    case Op::NotEqual:
        return a != b ? 1.0 : 0.0;
    case Op::And:
        return truth(a) && truth(b) ? 1.0 : 0.0;
    case Op::Or:
        return truth(a) || truth(b) ? 1.0 : 0.0;
    case Op::RIntersect:
        return rIntersect(a, b, imm0, imm1);
    case Op::RUnion:
        return rUnion(a, b, imm0, imm1);
    default:
        return NAN;
    }
}

inline double ternary(Op op, double a, double b, double c) {
    switch (op) {
    case Op::Select:
        return truth(a) ? b : c;
    case Op::Noise:
        return noise3(a, b, c);
    default:
        return NAN;
    }
}

// Any opcode on constant operands (operands beyond the opcode's arity are ignored).
inline double apply(Op op, double a, double b, double c, double imm0, double imm1) {
    switch (opArity(op)) {
    case 1:
        return unary(op, a, imm0);
    case 2:
        return binary(op, a, b, imm0, imm1);
    default:
        return ternary(op, a, b, c);
    }
}

} // namespace fl::formula::ops
