#pragma once
// Transcendental functions for every evaluator, from SLEEF (bounded 1-ulp
// error, vectorised). The batch evaluator calls the array forms (8 lanes with
// AVX-512F, 4 with AVX2+FMA, 2 with SSE2, chosen once at start-up from the
// CPU); everything
// else — the scalar evaluator, the constant folder, the interval endpoints —
// calls the scalar form of the *same* SLEEF variant, so all evaluators agree
// bit for bit on every machine (checked by the batch-versus-scalar tests).
#include <cstddef>
#include <cstdint>

namespace fl::formula::vmath {

// X(name, sleef-name)
#define FL_VMATH_UNARY(X)                                                                          \
    X(Sin, sin)                                                                                    \
    X(Cos, cos)                                                                                    \
    X(Tan, tan)                                                                                    \
    X(Asin, asin)                                                                                  \
    X(Acos, acos)                                                                                  \
    X(Atan, atan)                                                                                  \
    X(Exp, exp)                                                                                    \
    X(Log, log)                                                                                    \
    X(Log2, log2) X(Log10, log10) X(Sinh, sinh) X(Cosh, cosh) X(Tanh, tanh) X(Cbrt, cbrt)
#define FL_VMATH_BINARY(X) X(Atan2, atan2) X(Pow, pow)

enum class Unary : std::uint8_t {
#define FL_VMATH_ENUM(name, sleef) name,
    FL_VMATH_UNARY(FL_VMATH_ENUM)
#undef FL_VMATH_ENUM
        Count
};
enum class Binary : std::uint8_t {
#define FL_VMATH_ENUM(name, sleef) name,
    FL_VMATH_BINARY(FL_VMATH_ENUM)
#undef FL_VMATH_ENUM
        Count
};

using ScalarUnary = double (*)(double);
using ScalarBinary = double (*)(double, double);
using ArrayUnary = void (*)(const double* a, double* out, std::size_t n);
// Binary arrays: either operand may be a broadcast constant (aConst / bConst).
using ArrayBinary = void (*)(const double* a, double ca, const double* b, double cb, double* out,
                             std::size_t n);
// sin and cos of one argument from one reduction (SLEEF's sincos). Its bits
// are not sin's and cos's (about 4 % of arguments differ by an ulp): the
// tape's paired opcodes (SinOfPair, CosOfPair) are defined by it, so every
// evaluator gives them the same bits.
struct SinCos {
    double sin, cos;
};
using ScalarSinCos = SinCos (*)(double);
// Both outputs are written (neither may be nullptr; either may be a).
using ArraySinCos = void (*)(const double* a, double* sinOut, double* cosOut, std::size_t n);

struct Implementation {
    const char* name;
    ScalarUnary unary[static_cast<int>(Unary::Count)];
    ScalarBinary binary[static_cast<int>(Binary::Count)];
    ArrayUnary unaryArray[static_cast<int>(Unary::Count)];
    ArrayBinary binaryArray[static_cast<int>(Binary::Count)];
    ScalarSinCos sinCos;
    ArraySinCos sinCosArray;
};

const Implementation& implementation();

inline double eval(Unary f, double a) {
    return implementation().unary[static_cast<int>(f)](a);
}
inline double eval(Binary f, double a, double b) {
    return implementation().binary[static_cast<int>(f)](a, b);
}
inline SinCos sinCos(double a) {
    return implementation().sinCos(a);
}

// The variants, for the dispatcher and for tests. AVX-512F shares the AVX2
// variant's scalar routines, so both give the same bits.
const Implementation& sse2Implementation();
const Implementation* avx2Implementation();   // nullptr when this CPU lacks AVX2 and FMA
const Implementation* avx512Implementation(); // nullptr without AVX2, FMA and AVX-512F

} // namespace fl::formula::vmath
