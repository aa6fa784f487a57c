#include "config/expression_vector_math.hpp"
#include "config/cpu_dispatch.hpp"

#include <immintrin.h>

#include <map>

namespace iga::expression_detail {

namespace {

// The vector ABI names of libmvec: b = SSE (2 lanes; glibc picks an SSE4.1 or SSE2 body), d = AVX2
// (4 lanes). Every value of a block, the remainder included, goes through the same function, so
// a point's value does not depend on where it falls in a block.
#define IGA_MVEC_DECLARE1(f)                          \
  extern "C" __m128d _ZGVbN2v_##f(__m128d);           \
  extern "C" __m256d _ZGVdN4v_##f(__m256d);
#define IGA_MVEC_DECLARE2(f)                          \
  extern "C" __m128d _ZGVbN2vv_##f(__m128d, __m128d); \
  extern "C" __m256d _ZGVdN4vv_##f(__m256d, __m256d);

IGA_MVEC_DECLARE1(sin)
IGA_MVEC_DECLARE1(cos)
IGA_MVEC_DECLARE1(tan)
IGA_MVEC_DECLARE1(asin)
IGA_MVEC_DECLARE1(acos)
IGA_MVEC_DECLARE1(atan)
IGA_MVEC_DECLARE1(sinh)
IGA_MVEC_DECLARE1(cosh)
IGA_MVEC_DECLARE1(tanh)
IGA_MVEC_DECLARE1(asinh)
IGA_MVEC_DECLARE1(acosh)
IGA_MVEC_DECLARE1(atanh)
IGA_MVEC_DECLARE1(exp)
IGA_MVEC_DECLARE1(log)
IGA_MVEC_DECLARE2(pow)
IGA_MVEC_DECLARE2(atan2)

template <__m128d (*F)(__m128d)>
void sse1(const double* a, double* out, int count) {
  int k = 0;
  for (; k + 2 <= count; k += 2) _mm_storeu_pd(out + k, F(_mm_loadu_pd(a + k)));
  if (k < count) {
    double in[2] = {a[k], a[k]}, res[2];
    _mm_storeu_pd(res, F(_mm_loadu_pd(in)));
    out[k] = res[0];
  }
}

template <__m256d (*F)(__m256d)>
__attribute__((target("avx2"))) void avx1(const double* a, double* out, int count) {
  int k = 0;
  for (; k + 4 <= count; k += 4) _mm256_storeu_pd(out + k, F(_mm256_loadu_pd(a + k)));
  if (k < count) {
    double in[4], res[4];
    for (int i = 0; i < 4; ++i) in[i] = a[k + (k + i < count ? i : 0)];
    _mm256_storeu_pd(res, F(_mm256_loadu_pd(in)));
    for (int i = 0; k + i < count; ++i) out[k + i] = res[i];
  }
}

template <__m128d (*F)(__m128d, __m128d)>
void sse2(const double* a, const double* b, double* out, int count) {
  int k = 0;
  for (; k + 2 <= count; k += 2) _mm_storeu_pd(out + k, F(_mm_loadu_pd(a + k), _mm_loadu_pd(b + k)));
  if (k < count) {
    double ia[2] = {a[k], a[k]}, ib[2] = {b[k], b[k]}, res[2];
    _mm_storeu_pd(res, F(_mm_loadu_pd(ia), _mm_loadu_pd(ib)));
    out[k] = res[0];
  }
}

template <__m256d (*F)(__m256d, __m256d)>
__attribute__((target("avx2"))) void avx2(const double* a, const double* b, double* out, int count) {
  int k = 0;
  for (; k + 4 <= count; k += 4) _mm256_storeu_pd(out + k, F(_mm256_loadu_pd(a + k), _mm256_loadu_pd(b + k)));
  if (k < count) {
    double ia[4], ib[4], res[4];
    for (int i = 0; i < 4; ++i) {
      const int j = k + (k + i < count ? i : 0);
      ia[i] = a[j];
      ib[i] = b[j];
    }
    _mm256_storeu_pd(res, F(_mm256_loadu_pd(ia), _mm256_loadu_pd(ib)));
    for (int i = 0; k + i < count; ++i) out[k + i] = res[i];
  }
}

#define IGA_MVEC_ENTRY1(f) {#f, cpu_has_avx2() ? &avx1<_ZGVdN4v_##f> : &sse1<_ZGVbN2v_##f>}

}  // namespace

ArrayFunction1 array_function(const std::string& name) {
  static const std::map<std::string, ArrayFunction1> table = {
      IGA_MVEC_ENTRY1(sin),   IGA_MVEC_ENTRY1(cos),   IGA_MVEC_ENTRY1(tan),   IGA_MVEC_ENTRY1(asin),
      IGA_MVEC_ENTRY1(acos),  IGA_MVEC_ENTRY1(atan),  IGA_MVEC_ENTRY1(sinh),  IGA_MVEC_ENTRY1(cosh),
      IGA_MVEC_ENTRY1(tanh),  IGA_MVEC_ENTRY1(asinh), IGA_MVEC_ENTRY1(acosh), IGA_MVEC_ENTRY1(atanh),
      IGA_MVEC_ENTRY1(exp),   IGA_MVEC_ENTRY1(log)};
  const auto it = table.find(name);
  return it == table.end() ? nullptr : it->second;
}

ArrayFunction2 array_pow() { return cpu_has_avx2() ? &avx2<_ZGVdN4vv_pow> : &sse2<_ZGVbN2vv_pow>; }
ArrayFunction2 array_atan2() { return cpu_has_avx2() ? &avx2<_ZGVdN4vv_atan2> : &sse2<_ZGVbN2vv_atan2>; }

}  // namespace iga::expression_detail
