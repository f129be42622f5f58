#pragma once
// The one opcode table. Every evaluator (scalar, batch, interval, gradient),
// the constant folder and the tape printer are driven by this list, so adding
// an operation means adding one row here and one case per evaluator — the
// compiler refuses to build an evaluator that misses a case (-Wswitch).
#include <cstdint>

namespace fl::formula {

// X(Name, arity, spelling)
#define FL_OPCODES(X)                                                                              \
    X(Neg, 1, "neg")                                                                               \
    X(Abs, 1, "abs")                                                                               \
    X(Square, 1, "square")                                                                         \
    X(Sqrt, 1, "sqrt")                                                                             \
    X(Cbrt, 1, "cbrt")                                                                             \
    X(Exp, 1, "exp")                                                                               \
    X(Log, 1, "log")                                                                               \
    X(Log2, 1, "log2")                                                                             \
    X(Log10, 1, "log10")                                                                           \
    X(Sin, 1, "sin")                                                                               \
    X(Cos, 1, "cos")                                                                               \
    X(SinOfPair, 1, "sincos.sin") /* sin where the tape also takes cos of the same value */        \
    X(CosOfPair, 1, "sincos.cos") /* ... computed together: vmath::sinCos, not sin and cos */      \
    X(Tan, 1, "tan")                                                                               \
    X(Asin, 1, "asin")                                                                             \
    X(Acos, 1, "acos")                                                                             \
    X(Atan, 1, "atan")                                                                             \
    X(Sinh, 1, "sinh")                                                                             \
    X(Cosh, 1, "cosh")                                                                             \
    X(Tanh, 1, "tanh")                                                                             \
    X(Floor, 1, "floor")                                                                           \
    X(Ceil, 1, "ceil")                                                                             \
    X(Round, 1, "round")                                                                           \
    X(Sign, 1, "sign")                                                                             \
    X(Not, 1, "not")                                                                               \
    X(PowI, 1, "powi") /* integer power; the exponent is imm0 */                                   \
    X(Add, 2, "add")                                                                               \
    X(Sub, 2, "sub")                                                                               \
    X(Mul, 2, "mul")                                                                               \
    X(Div, 2, "div")                                                                               \
    X(Pow, 2, "pow")                                                                               \
    X(Min, 2, "min")                                                                               \
    X(Max, 2, "max")                                                                               \
    X(Atan2, 2, "atan2")                                                                           \
    X(Hypot, 2, "hypot")                                                                           \
    X(Mod, 2, "mod")                                                                               \
    X(Less, 2, "lt")                                                                               \
    X(LessEq, 2, "le")                                                                             \
    X(Greater, 2, "gt")                                                                            \
    X(GreaterEq, 2, "ge")                                                                          \
    X(Equal, 2, "eq")                                                                              \
    X(NotEqual, 2, "ne")                                                                           \
    X(And, 2, "and")                                                                               \
    X(Or, 2, "or")                                                                                 \
    X(RIntersect, 2, "rintersect") /* imm0 = m (continuity), imm1 = alpha */                       \
    X(RUnion, 2, "runion")         /* imm0 = m, imm1 = alpha */                                    \
    X(Select, 3, "select")         /* a != 0 ? b : c */                                            \
    X(Noise, 3, "noise")

enum class Op : std::uint8_t {
#define FL_OP_ENUM(name, arity, spelling) name,
    FL_OPCODES(FL_OP_ENUM)
#undef FL_OP_ENUM
};

constexpr int opCount() {
    int n = 0;
#define FL_OP_COUNT(name, arity, spelling) ++n;
    FL_OPCODES(FL_OP_COUNT)
#undef FL_OP_COUNT
    return n;
}

constexpr int opArity(Op op) {
    switch (op) {
#define FL_OP_ARITY(name, arity, spelling)                                                         \
    case Op::name:                                                                                 \
        return arity;
        FL_OPCODES(FL_OP_ARITY)
#undef FL_OP_ARITY
    }
    return 0;
}

constexpr const char* opName(Op op) {
    switch (op) {
#define FL_OP_NAME(name, arity, spelling)                                                          \
    case Op::name:                                                                                 \
        return spelling;
        FL_OPCODES(FL_OP_NAME)
#undef FL_OP_NAME
    }
    return "?";
}

// The name the student wrote, for messages about the source.
constexpr const char* opSourceName(Op op) {
    switch (op) {
    case Op::SinOfPair:
        return "sin";
    case Op::CosOfPair:
        return "cos";
    default:
        return opName(op);
    }
}

// Operations whose operands the compiler may swap (to share a*b with b*a):
// only those that give the same value either way for every pair of doubles.
// min, max and the R-functions are left out: at ties they may return -0 or
// +0 depending on the order.
constexpr bool opIsCommutative(Op op) {
    switch (op) {
    case Op::Add:
    case Op::Mul:
    case Op::Hypot:
    case Op::Equal:
    case Op::NotEqual:
    case Op::And:
    case Op::Or:
        return true;
    default:
        return false;
    }
}

} // namespace fl::formula
