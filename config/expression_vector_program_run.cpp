// VectorProgram::run: compiled instructions executed over a block of points (the compiler from
// GiNaC expressions is expression_vector_program.cpp).
#include "config/expression_vector_program.hpp"
#include "config/cpu_dispatch.hpp"

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace iga::expression_detail {

namespace {

using Op = VectorProgram::Op;
using Instruction = VectorProgram::Instruction;

/// v^n by squaring (n >= 0).
double integer_power(double v, int n) {
  unsigned m = static_cast<unsigned>(n);
  double result = 1.0, base = v;
  while (m) {
    if (m & 1u) result *= base;
    base *= base;
    m >>= 1u;
  }
  return result;
}


template <bool kFused>
[[gnu::always_inline]] inline double multiply_add(double a, double b, double c) {
  if constexpr (kFused) {
    return std::fma(a, b, c);
  } else {
    return a * b + c;
  }
}

/// The body of VectorProgram::run; kFused: the multiply-adds round once (hardware FMA).
template <bool kFused>
[[gnu::always_inline]] inline void execute(const std::vector<VectorProgram::Instruction>& code, const double* x,
                                           const double* y, int count, double* work) {
  auto at = [&](int s) -> const double* {
    return s >= 0 ? work + static_cast<size_t>(s) * VectorProgram::kBlock : (s == VectorProgram::kInputX ? x : y);
  };
  for (const Instruction& in : code) {
    double* out = work + static_cast<size_t>(in.out) * VectorProgram::kBlock;
    const double* a = at(in.a);
    const double* b = in.b != -1 ? at(in.b) : nullptr;
    const double* d = in.d != -1 ? at(in.d) : nullptr;
    const double c = in.c, c2 = in.c2;
    switch (in.op) {
      case Op::constant:
        for (int k = 0; k < count; ++k) out[k] = c;
        break;
      case Op::add:
        for (int k = 0; k < count; ++k) out[k] = a[k] + b[k];
        break;
      case Op::mul:
        for (int k = 0; k < count; ++k) out[k] = a[k] * b[k];
        break;
      case Op::add_c:
        for (int k = 0; k < count; ++k) out[k] = a[k] + c;
        break;
      case Op::mul_c:
        for (int k = 0; k < count; ++k) out[k] = a[k] * c;
        break;
      case Op::div:
        for (int k = 0; k < count; ++k) out[k] = a[k] / b[k];
        break;
      case Op::div_c:
        for (int k = 0; k < count; ++k) out[k] = c / a[k];
        break;
      case Op::affine:
        for (int k = 0; k < count; ++k) out[k] = multiply_add<kFused>(a[k], c, c2);
        break;
      case Op::mul_add:
        for (int k = 0; k < count; ++k) out[k] = multiply_add<kFused>(a[k], b[k], d[k]);
        break;
      case Op::mul_c_add:
        for (int k = 0; k < count; ++k) out[k] = multiply_add<kFused>(a[k], c, d[k]);
        break;
      case Op::mul_add_c:
        for (int k = 0; k < count; ++k) out[k] = multiply_add<kFused>(a[k], b[k], c);
        break;
      case Op::power_int:
        // The common small exponents as straight products (they vectorize; the loop does not).
        if (in.n == 2) {
          for (int k = 0; k < count; ++k) out[k] = a[k] * a[k];
        } else if (in.n == 3) {
          for (int k = 0; k < count; ++k) out[k] = a[k] * a[k] * a[k];
        } else if (in.n == 4) {
          for (int k = 0; k < count; ++k) {
            const double square = a[k] * a[k];
            out[k] = square * square;
          }
        } else {
          for (int k = 0; k < count; ++k) out[k] = integer_power(a[k], in.n);
        }
        break;
      case Op::sqrt:
        for (int k = 0; k < count; ++k) out[k] = std::sqrt(a[k]);
        break;
      case Op::power:
        if (in.array2) {
          in.array2(a, b, out, count);
        } else {
          for (int k = 0; k < count; ++k) out[k] = std::pow(a[k], b[k]);
        }
        break;
      case Op::call1:
        if (in.array1) {
          in.array1(a, out, count);
        } else {
          for (int k = 0; k < count; ++k) out[k] = in.f1(a[k]);
        }
        break;
      case Op::call2:
        if (in.array2) {
          in.array2(a, b, out, count);
        } else {
          for (int k = 0; k < count; ++k) out[k] = in.f2(a[k], b[k]);
        }
        break;
    }
  }
}

// Compiled twice, the AVX2 body chosen at load time where the CPU has it: the arithmetic loops
// then run four points per instruction instead of two. Products and sums round separately here
// unless the whole build targets FMA (then cpu_has_avx2_fma() is false and this copy is the one).
IGA_AVX2_CLONES
void execute_separate(const std::vector<Instruction>& code, const double* x, const double* y, int count,
                      double* work) {
  execute<false>(code, x, y, count, work);
}

// With FMA, where the CPU has it: a multiply-add rounds once instead of twice, so its result is as
// accurate or more. Nothing here relies on the rounding of a separate product (unlike the
// error-free transformations of double_double.hpp, which is why the rest of the build has no FMA).
__attribute__((target("avx2,fma"))) void execute_fused(const std::vector<Instruction>& code, const double* x,
                                                       const double* y, int count, double* work) {
  execute<true>(code, x, y, count, work);
}

/// Results up to this many are stored by store_transposed.
constexpr int kMaxTransposed = 64;

/// values[i + k * stride] = rows[i][k] for i < m, k < count: the results of a block turned to the
/// layout of values (a point's functions together). Four functions of four points are transposed
/// in registers and stored as four vectors, a pair of functions as two halves: a quarter or half
/// of the stores of an element-by-element copy, which cost as much as a jet's arithmetic.
__attribute__((target("avx2"))) void store_transposed(const double* const* rows, int m, int count, double* values,
                                                      int stride) {
  if (m == 1 && stride == 1) {  // one function (a source): a plain copy
    std::copy(rows[0], rows[0] + count, values);
    return;
  }
  const int quads = m & ~3, full4 = count & ~3, full2 = count & ~1;
  const bool pair = m - quads >= 2;
  auto at = [&](int i, int k) { return values + i + static_cast<size_t>(k) * stride; };
  for (int i = 0; i < quads; i += 4)
    for (int k = 0; k < full4; k += 4) {
      const __m256d a0 = _mm256_loadu_pd(rows[i] + k), a1 = _mm256_loadu_pd(rows[i + 1] + k);
      const __m256d a2 = _mm256_loadu_pd(rows[i + 2] + k), a3 = _mm256_loadu_pd(rows[i + 3] + k);
      const __m256d t0 = _mm256_unpacklo_pd(a0, a1), t1 = _mm256_unpackhi_pd(a0, a1);
      const __m256d t2 = _mm256_unpacklo_pd(a2, a3), t3 = _mm256_unpackhi_pd(a2, a3);
      _mm256_storeu_pd(at(i, k), _mm256_permute2f128_pd(t0, t2, 0x20));
      _mm256_storeu_pd(at(i, k + 1), _mm256_permute2f128_pd(t1, t3, 0x20));
      _mm256_storeu_pd(at(i, k + 2), _mm256_permute2f128_pd(t0, t2, 0x31));
      _mm256_storeu_pd(at(i, k + 3), _mm256_permute2f128_pd(t1, t3, 0x31));
    }
  if (pair)
    for (int k = 0; k < full2; k += 2) {
      const __m128d a = _mm_loadu_pd(rows[quads] + k), b = _mm_loadu_pd(rows[quads + 1] + k);
      _mm_storeu_pd(at(quads, k), _mm_unpacklo_pd(a, b));
      _mm_storeu_pd(at(quads, k + 1), _mm_unpackhi_pd(a, b));
    }
  // What the vectors left: the last points of each function, and a last odd function.
  for (int i = 0; i < m; ++i) {
    const int done = i < quads ? full4 : (pair && i < quads + 2 ? full2 : 0);
    for (int k = done; k < count; ++k) *at(i, k) = rows[i][k];
  }
}

}  // namespace

void VectorProgram::run(const double* x, const double* y, int count, std::vector<double>& work, double* values,
                        int stride) const {
  if (work.size() < static_cast<size_t>(slots_) * kBlock) work.resize(static_cast<size_t>(slots_) * kBlock);
  if (cpu_has_avx2_fma()) {
    execute_fused(code_, x, y, count, work.data());
  } else {
    execute_separate(code_, x, y, count, work.data());
  }
  const int m = size();
  std::array<const double*, kMaxTransposed> rows;
  if (m <= kMaxTransposed && cpu_has_avx2()) {
    for (int i = 0; i < m; ++i) {
      const int s = results_[i];
      rows[i] = s >= 0 ? &work[static_cast<size_t>(s) * kBlock] : (s == kInputX ? x : y);
    }
    store_transposed(rows.data(), m, count, values, stride);
    return;
  }
  for (int i = 0; i < m; ++i) {
    const int s = results_[i];
    const double* r = s >= 0 ? &work[static_cast<size_t>(s) * kBlock] : (s == kInputX ? x : y);
    for (int k = 0; k < count; ++k) values[i + static_cast<size_t>(k) * stride] = r[k];
  }
}

}  // namespace iga::expression_detail
