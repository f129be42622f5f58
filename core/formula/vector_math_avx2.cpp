// AVX2 + FMA variant. This file alone is compiled with -mavx2 -mfma and is
// only called after the dispatcher has checked the CPU; it uses no inline
// library templates, so no AVX2 code can leak into baseline paths.
#include "vector_math.h"

#include <sleef.h>

#include <immintrin.h>

namespace fl::formula::vmath {

namespace {
#define FL_VEC __m256d
#define FL_LANES 4
#define FL_LOAD(p) _mm256_loadu_pd(p)
#define FL_STORE(p, v) _mm256_storeu_pd(p, v)
#define FL_SET1(x) _mm256_set1_pd(x)
#define FL_VECTOR(f) Sleef_##f##d4_u10avx2
#define FL_SCALAR(f) Sleef_##f##d1_u10purecfma // the same fused operations as AVX2
#define FL_VARIANT_NAME "SLEEF AVX2+FMA"
bool inOneTrigRange(const double* p) {
    const __m256d v = _mm256_andnot_pd(_mm256_set1_pd(-0.0), _mm256_loadu_pd(p)); // |lanes|
    const int fast = _mm256_movemask_pd(_mm256_cmp_pd(v, _mm256_set1_pd(15.0), _CMP_LT_OQ));
    const int medium =
        _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(v, _mm256_set1_pd(15.0), _CMP_GE_OQ),
                                         _mm256_cmp_pd(v, _mm256_set1_pd(1e14), _CMP_LT_OQ)));
    return fast == 0xF || medium == 0xF;
}
#define FL_IN_ONE_TRIG_RANGE(p) inOneTrigRange(p)
#include "vector_math_variant.inc"
} // namespace

const Implementation* makeAvx2Implementation() {
    static const Implementation impl = makeVariant();
    return &impl;
}

} // namespace fl::formula::vmath
