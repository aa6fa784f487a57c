#include "assembly/split_matrix.hpp"

#include <algorithm>
#include <cassert>

#include "assembly/parallel.hpp"
#include "config/double_double.hpp"

namespace iga {

void scatter_add(const std::vector<int>& dofs, const MatrixXld& local, const SparseMatrix& pattern,
                 std::vector<long double>& values) {
  scatter_add_values(dofs, local, pattern, values.data());
}

SplitMatrix split_matrix(const SparseMatrix& pattern, const std::vector<long double>& values) {
  SplitMatrix k{pattern, Eigen::VectorXd(pattern.nonZeros())};
  double* high = k.high.valuePtr();
  for (Eigen::Index p = 0; p < pattern.nonZeros(); ++p) {
    high[p] = static_cast<double>(values[p]);
    k.low(p) = static_cast<double>(values[p] - high[p]);
  }
  return k;
}

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
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* high = a.valuePtr();
  const double* low = has_low ? K.low.data() : nullptr;
  std::vector<DoubleDouble> xd(x.size());
  for (size_t j = 0; j < x.size(); ++j) xd[j] = DoubleDouble::from_long_double(x[j]);
#pragma omp parallel for schedule(static) if (worth_threads(n / 64))
  for (int i = 0; i < n; ++i) {
    DoubleDouble s = b(i);
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      s -= (low ? DoubleDouble(high[p], low[p]) : DoubleDouble(high[p])) * xd[inner[p]];
    r[i] = s.to_long_double();
  }
  return r;
}

}  // namespace iga
