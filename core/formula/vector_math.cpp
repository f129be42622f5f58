// Baseline (SSE2) variant and the start-up dispatcher.
#include "vector_math.h"

#include <sleef.h>

#include <emmintrin.h>

#include <cstdlib>
#include <cstring>

namespace fl::formula::vmath {

namespace {
#define FL_VEC __m128d
#define FL_LANES 2
#define FL_LOAD(p) _mm_loadu_pd(p)
#define FL_STORE(p, v) _mm_storeu_pd(p, v)
#define FL_SET1(x) _mm_set1_pd(x)
#define FL_VECTOR(f) Sleef_##f##d2_u10sse2
#define FL_SCALAR(f) Sleef_##f##d1_u10purec // no FMA, like the SSE2 routines
#define FL_VARIANT_NAME "SLEEF SSE2"
bool inOneTrigRange(const double* p) {
    const __m128d v = _mm_andnot_pd(_mm_set1_pd(-0.0), _mm_loadu_pd(p)); // |lanes|
    const int fast = _mm_movemask_pd(_mm_cmplt_pd(v, _mm_set1_pd(15.0)));
    const int medium = _mm_movemask_pd(
        _mm_and_pd(_mm_cmpge_pd(v, _mm_set1_pd(15.0)), _mm_cmplt_pd(v, _mm_set1_pd(1e14))));
    return fast == 0x3 || medium == 0x3;
}
#define FL_IN_ONE_TRIG_RANGE(p) inOneTrigRange(p)
#include "vector_math_variant.inc"
} // namespace

const Implementation* makeAvx2Implementation();   // vector_math_avx2.cpp
const Implementation* makeAvx512Implementation(); // vector_math_avx512.cpp

const Implementation& sse2Implementation() {
    static const Implementation impl = makeVariant();
    return impl;
}

const Implementation* avx2Implementation() {
    static const Implementation* impl =
        (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) ? makeAvx2Implementation()
                                                                          : nullptr;
    return impl;
}

const Implementation* avx512Implementation() {
    static const Implementation* impl = (avx2Implementation() && __builtin_cpu_supports("avx512f"))
                                            ? makeAvx512Implementation()
                                            : nullptr;
    return impl;
}

namespace {
// FUNCTIONLAB_NO_AVX512=1 keeps the AVX2 arrays on a CPU with AVX-512 (the
// same bits either way: for comparing their speed in one build, or for a CPU
// that lowers its clock under 512-bit work).
bool avx512Refused() {
    const char* off = std::getenv("FUNCTIONLAB_NO_AVX512");
    return off && *off && std::strcmp(off, "0") != 0;
}
} // namespace

const Implementation& implementation() {
    static const Implementation& impl = (avx512Implementation() && !avx512Refused())
                                            ? *avx512Implementation()
                                        : avx2Implementation() ? *avx2Implementation()
                                                               : sse2Implementation();
    return impl;
}

} // namespace fl::formula::vmath
