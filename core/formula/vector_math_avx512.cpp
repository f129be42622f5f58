// AVX-512F variant: eight lanes a call, where the CPU has AVX-512F (and AVX2
// and FMA). This file alone is compiled with -mavx512f and is only called
// after the dispatcher has checked the CPU. Its scalar twin is the AVX2
// variant's (SLEEF's fused scalar code): the 512-bit routines run the same
// algorithm with the same fused operations, so a machine with AVX-512 gets
// the very bits one without it gets (vector_math_test.cpp checks it).
#include "vector_math.h"

#include <sleef.h>

#include <immintrin.h>

namespace fl::formula::vmath {

namespace {
#define FL_VEC __m512d
#define FL_LANES 8
#define FL_LOAD(p) _mm512_loadu_pd(p)
#define FL_STORE(p, v) _mm512_storeu_pd(p, v)
#define FL_SET1(x) _mm512_set1_pd(x)
#define FL_VECTOR(f) Sleef_##f##d8_u10avx512f
#define FL_SCALAR(f) Sleef_##f##d1_u10purecfma // the AVX2 variant's twin too
#define FL_VARIANT_NAME "SLEEF AVX-512F"
bool inOneTrigRange(const double* p) {
    const __m512d v = _mm512_abs_pd(_mm512_loadu_pd(p));
    const __mmask8 fast = _mm512_cmp_pd_mask(v, _mm512_set1_pd(15.0), _CMP_LT_OQ);
    const __mmask8 medium = _mm512_cmp_pd_mask(v, _mm512_set1_pd(15.0), _CMP_GE_OQ) &
                            _mm512_cmp_pd_mask(v, _mm512_set1_pd(1e14), _CMP_LT_OQ);
    return fast == 0xFF || medium == 0xFF;
}
#define FL_IN_ONE_TRIG_RANGE(p) inOneTrigRange(p)
#include "vector_math_variant.inc"
} // namespace

const Implementation* makeAvx512Implementation() {
    static const Implementation impl = makeVariant();
    return &impl;
}

} // namespace fl::formula::vmath
