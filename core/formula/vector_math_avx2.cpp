// AVX2 + FMA variant. This file alone is compiled with -mavx2 -mfma and is
// only called after the dispatcher has checked the CPU; it uses no inline
// library templates, so no AVX2 code can leak into baseline paths.
#include "vector_math.h"

#include <sleef.h>

#include <immintrin.h>

namespace fl::formula::vmath {

namespace {

// SLEEF declares its results `const double`; these give plain function types.
#define FL_SCALAR_UNARY(name, sleef)                                                               \
    double sleef##Scalar(double a) {                                                               \
        return Sleef_##sleef##d1_u10purecfma(a);                                                   \
    }
FL_VMATH_UNARY(FL_SCALAR_UNARY)
#undef FL_SCALAR_UNARY
#define FL_SCALAR_BINARY(name, sleef)                                                              \
    double sleef##Scalar(double a, double b) {                                                     \
        return Sleef_##sleef##d1_u10purecfma(a, b);                                                \
    }
FL_VMATH_BINARY(FL_SCALAR_BINARY)
#undef FL_SCALAR_BINARY

// Four lanes per step; the tail uses purecfma, the scalar routine with the
// same fused operations as the AVX2 one, so every element matches eval().
#define FL_AVX2_UNARY(name, sleef)                                                                 \
    void sleef##Array(const double* a, double* out, std::size_t n) {                               \
        std::size_t i = 0;                                                                         \
        for (; i + 4 <= n; i += 4)                                                                 \
            _mm256_storeu_pd(out + i, Sleef_##sleef##d4_u10avx2(_mm256_loadu_pd(a + i)));          \
        for (; i < n; ++i)                                                                         \
            out[i] = Sleef_##sleef##d1_u10purecfma(a[i]);                                          \
    }
FL_VMATH_UNARY(FL_AVX2_UNARY)
#undef FL_AVX2_UNARY

#define FL_AVX2_BINARY(name, sleef)                                                                \
    void sleef##Array(const double* a, double ca, const double* b, double cb, double* out,         \
                      std::size_t n) {                                                             \
        std::size_t i = 0;                                                                         \
        const __m256d va = _mm256_set1_pd(ca), vb = _mm256_set1_pd(cb);                            \
        for (; i + 4 <= n; i += 4)                                                                 \
            _mm256_storeu_pd(out + i, Sleef_##sleef##d4_u10avx2(a ? _mm256_loadu_pd(a + i) : va,   \
                                                                b ? _mm256_loadu_pd(b + i) : vb)); \
        for (; i < n; ++i)                                                                         \
            out[i] = Sleef_##sleef##d1_u10purecfma(a ? a[i] : ca, b ? b[i] : cb);                  \
    }
FL_VMATH_BINARY(FL_AVX2_BINARY)
#undef FL_AVX2_BINARY

Implementation makeAvx2() {
    Implementation impl{};
    impl.name = "SLEEF AVX2+FMA";
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

const Implementation* makeAvx2Implementation() {
    static const Implementation impl = makeAvx2();
    return &impl;
}

} // namespace fl::formula::vmath
