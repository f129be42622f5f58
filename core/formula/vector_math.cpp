// Baseline (SSE2) variant and the start-up dispatcher.
#include "vector_math.h"

#include <sleef.h>

#include <emmintrin.h>

namespace fl::formula::vmath {

namespace {

// SLEEF declares its results `const double`; these give plain function types.
#define FL_SCALAR_UNARY(name, sleef)                                                               \
    double sleef##Scalar(double a) {                                                               \
        return Sleef_##sleef##d1_u10purec(a);                                                      \
    }
FL_VMATH_UNARY(FL_SCALAR_UNARY)
#undef FL_SCALAR_UNARY
#define FL_SCALAR_BINARY(name, sleef)                                                              \
    double sleef##Scalar(double a, double b) {                                                     \
        return Sleef_##sleef##d1_u10purec(a, b);                                                   \
    }
FL_VMATH_BINARY(FL_SCALAR_BINARY)
#undef FL_SCALAR_BINARY

// Two lanes per step; the tail uses the scalar routine of the same variant
// (purec: no FMA, like the SSE2 routines), so every element matches eval().
#define FL_SSE2_UNARY(name, sleef)                                                                 \
    void sleef##Array(const double* a, double* out, std::size_t n) {                               \
        std::size_t i = 0;                                                                         \
        for (; i + 2 <= n; i += 2)                                                                 \
            _mm_storeu_pd(out + i, Sleef_##sleef##d2_u10sse2(_mm_loadu_pd(a + i)));                \
        for (; i < n; ++i)                                                                         \
            out[i] = Sleef_##sleef##d1_u10purec(a[i]);                                             \
    }
FL_VMATH_UNARY(FL_SSE2_UNARY)
#undef FL_SSE2_UNARY

#define FL_SSE2_BINARY(name, sleef)                                                                \
    void sleef##Array(const double* a, double ca, const double* b, double cb, double* out,         \
                      std::size_t n) {                                                             \
        std::size_t i = 0;                                                                         \
        const __m128d va = _mm_set1_pd(ca), vb = _mm_set1_pd(cb);                                  \
        for (; i + 2 <= n; i += 2)                                                                 \
            _mm_storeu_pd(out + i, Sleef_##sleef##d2_u10sse2(a ? _mm_loadu_pd(a + i) : va,         \
                                                             b ? _mm_loadu_pd(b + i) : vb));       \
        for (; i < n; ++i)                                                                         \
            out[i] = Sleef_##sleef##d1_u10purec(a ? a[i] : ca, b ? b[i] : cb);                     \
    }
FL_VMATH_BINARY(FL_SSE2_BINARY)
#undef FL_SSE2_BINARY

Implementation makeSse2() {
    Implementation impl{};
    impl.name = "SLEEF SSE2";
#define FL_FILL_UNARY(name, sleef)                                                                 \
    impl.unary[static_cast<int>(Unary::name)] = sleef##Scalar;                                     \
    impl.unaryArray[static_cast<int>(Unary::name)] = sleef##Array;
    FL_VMATH_UNARY(FL_FILL_UNARY)
#undef FL_FILL_UNARY
#define FL_FILL_BINARY(name, sleef)                                                                \
    impl.binary[static_cast<int>(Binary::name)] = sleef##Scalar;                                   \
    impl.binaryArray[static_cast<int>(Binary::name)] = sleef##Array;
    FL_VMATH_BINARY(FL_FILL_BINARY)
#undef FL_FILL_BINARY
    return impl;
}

} // namespace

const Implementation* makeAvx2Implementation(); // vector_math_avx2.cpp

const Implementation& sse2Implementation() {
    static const Implementation impl = makeSse2();
    return impl;
}

const Implementation* avx2Implementation() {
    static const Implementation* impl =
        (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) ? makeAvx2Implementation()
                                                                          : nullptr;
    return impl;
}

const Implementation& implementation() {
    static const Implementation& impl =
        avx2Implementation() ? *avx2Implementation() : sse2Implementation();
    return impl;
}

} // namespace fl::formula::vmath
