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
template <bool kFma>
[[gnu::always_inline]] inline void residual_rows(int first, int last, const int* outer, const int* inner,
                                                 const double* high, const double* low,
                                                 const std::vector<DoubleDouble>& xd, const Eigen::VectorXd& b,
                                                 std::vector<long double>& r) {
  for (int i = first; i < last; ++i) {
    DoubleDouble s = b(i);
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      s -= multiply<kFma>(low ? DoubleDouble(high[p], low[p]) : DoubleDouble(high[p]), xd[inner[p]]);
    r[i] = s.to_long_double();
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
