#include "assembly/split_matrix.hpp"

#include <algorithm>
#include <cassert>

#include "assembly/parallel.hpp"
#include "config/double_double.hpp"

namespace iga {

SplitMatrix split_matrix(const SparseMatrix& pattern, const std::vector<DoubleDouble>& values) {
  SplitMatrix k{pattern, Eigen::VectorXd(pattern.nonZeros())};
  double* high = k.high.valuePtr();
  for (Eigen::Index p = 0; p < pattern.nonZeros(); ++p) {
    // Renormalised so that high is the entry rounded to double.
    const DoubleDouble v = values[p] + DoubleDouble(0.0);
    high[p] = v.hi;
    k.low(p) = v.lo;
  }
  return k;
}

namespace {

/// r_i = b_i − Σ_p K_ip x_p for rows [first, last) (compiled twice, see exact_product in
/// double_double.hpp; the OpenMP loop stays outside: its outlined body would not inherit the target).
/// Each row is summed in four interleaved compensated sums (exact products, two-sum of the running
/// sum, the rounding errors and the low-order product terms gathered in a double): the same
/// accuracy as a double-double accumulator (error ≈ n ε² Σ|K_ip x_p|), but one double-double
/// addition per entry made the loop latency-bound (≈ 25 % of a surface solve in refinement).
template <bool kFma>
[[gnu::always_inline]] inline void residual_rows(int first, int last, const int* outer, const int* inner,
                                                 const double* high, const double* low,
                                                 const std::vector<DoubleDouble>& xd, const Eigen::VectorXd& b,
                                                 std::vector<long double>& r) {
  constexpr int kSums = 4;
  for (int i = first; i < last; ++i) {
    double sum[kSums] = {b(i), 0, 0, 0}, error[kSums] = {0, 0, 0, 0};
    const auto subtract = [&](int k, int p) {
      const DoubleDouble& x = xd[inner[p]];
      const DoubleDouble product = exact_product<kFma>(high[p], x.hi);
      const double small = high[p] * x.lo + (low ? low[p] * x.hi : 0.0);
      const DoubleDouble t = dd_detail::two_sum(sum[k], -product.hi);
      sum[k] = t.hi;
      error[k] += t.lo - product.lo - small;
    };
    int p = outer[i];
    const int end = outer[i + 1];
    for (; p + kSums <= end; p += kSums)
      for (int k = 0; k < kSums; ++k) subtract(k, p + k);
    for (int k = 0; p < end; ++p, ++k) subtract(k, p);
    DoubleDouble total = dd_detail::two_sum(sum[0], error[0]);
    for (int k = 1; k < kSums; ++k) total += dd_detail::two_sum(sum[k], error[k]);
    r[i] = total.to_long_double();
  }
}

[[gnu::target("avx2,fma")]] void residual_rows_fma(int first, int last, const int* outer, const int* inner,
                                                    const double* high, const double* low,
                                                    const std::vector<DoubleDouble>& xd, const Eigen::VectorXd& b,
                                                    std::vector<long double>& r) {
  residual_rows<true>(first, last, outer, inner, high, low, xd, b, r);
}

}  // namespace

std::vector<long double> residual_extended(const SplitMatrix& K, const std::vector<long double>& x,
                                           const Eigen::VectorXd& b) {
  // Row i of a symmetric K is its column i: each entry of r is one independent sum (parallel).
  // Products and sums in double-double: r cancels to O(h²) from terms of size |K||x| ~ h⁻², and
  // long double sums (ε ≈ 5e-20 of those terms) leave a noise that K⁻¹ amplifies by h⁻² again.
  const SparseMatrix& a = K.high;
  const bool has_low = K.low.size() == a.nonZeros();
  std::vector<long double> r(b.size());
  const int n = static_cast<int>(a.outerSize());
  assert(a.isCompressed());
  const double* low = has_low ? K.low.data() : nullptr;
  std::vector<DoubleDouble> xd(x.size());
  for (size_t j = 0; j < x.size(); ++j) xd[j] = DoubleDouble::from_long_double(x[j]);
  const bool fma = cpu_has_avx2_fma();
  constexpr int rows = 256;
  const int blocks = (n + rows - 1) / rows;
#pragma omp parallel for schedule(static) if (worth_threads(n / 64))
  for (int block = 0; block < blocks; ++block) {
    const int first = block * rows, last = std::min(n, first + rows);
    if (fma)
      residual_rows_fma(first, last, a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(), low, xd, b, r);
    else
      residual_rows<false>(first, last, a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(), low, xd, b, r);
  }
  return r;
}

}  // namespace iga
