#include "assembly/split_matrix.hpp"

#include <algorithm>
#include <cassert>

#include "assembly/parallel.hpp"

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

std::vector<long double> residual_extended(const SplitMatrix& K, const std::vector<long double>& x,
                                           const Eigen::VectorXd& b) {
  // Row i of a symmetric K is its column i: each entry of r is one independent sum (parallel).
  const SparseMatrix& a = K.high;
  const bool has_low = K.low.size() == a.nonZeros();
  std::vector<long double> r(b.size());
  const int n = static_cast<int>(a.outerSize());
  assert(a.isCompressed());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* high = a.valuePtr();
#pragma omp parallel for schedule(static) if (worth_threads(n / 64))
  for (int i = 0; i < n; ++i) {
    long double s = b(i);
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      s -= (has_low ? static_cast<long double>(high[p]) + K.low(p) : static_cast<long double>(high[p])) * x[inner[p]];
    r[i] = s;
  }
  return r;
}

}  // namespace iga
