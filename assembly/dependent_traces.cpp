#include "assembly/dependent_traces.hpp"

#include <Eigen/QR>
#include <Eigen/SPQRSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "config/errors.hpp"

namespace iga {

namespace {

/// An independent subset of the boundary traces (columns of M) and the rest.
struct TraceSelection {
  std::vector<int> independent, dependent;
};

/// M restricted to the independent columns, factored: the projection onto their span and each
/// dependent trace's coefficients α = M_ii⁻¹ M_ik in it.
class IndependentTraces {
 public:
  IndependentTraces(const SparseMatrix& M, const std::vector<int>& independent)
      : M_(M), position_(M.rows(), -1), rank_(static_cast<int>(independent.size())) {
    for (int j = 0; j < rank_; ++j) position_[independent[j]] = j;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(M.nonZeros());
    for (int k = 0; k < M.cols(); ++k)
      for (SparseMatrix::InnerIterator it(M, k); it; ++it)
        if (position_[it.row()] >= 0 && position_[k] >= 0) entries.emplace_back(position_[it.row()], position_[k], it.value());
    M_ii_.resize(rank_, rank_);
    M_ii_.setFromTriplets(entries.begin(), entries.end());
    llt_.compute(M_ii_);
    if (llt_.info() != Eigen::Success) throw NumericalError("boundary projection: independent boundary traces not found");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return llt_.solve(b); }
  /// α of dependent column k.
  Eigen::VectorXd alpha(int k) const { return combination(k).alpha; }
  /// α of dependent column k; throws when its trace is not (to 1e-8 of its size) in their span.
  Eigen::VectorXd checked_alpha(int k) const {
    const Combination c = combination(k);
    const double residual = c.mkk - 2 * c.alpha.dot(c.mik) + c.alpha.dot(M_ii_ * c.alpha);
    if (residual > 1e-8 * c.mkk)
      throw NumericalError("boundary projection: a boundary trace is neither independent nor dependent (ill-conditioned)");
    return c.alpha;
  }

 private:
  struct Combination {
    Eigen::VectorXd mik, alpha;  ///< M_ik and α = M_ii⁻¹ M_ik
    double mkk = 0;
  };
  Combination combination(int k) const {
    Combination c;
    c.mik = Eigen::VectorXd::Zero(rank_);
    for (SparseMatrix::InnerIterator it(M_, k); it; ++it) {
      if (position_[it.row()] >= 0) c.mik(position_[it.row()]) = it.value();
      if (it.row() == k) c.mkk = it.value();
    }
    c.alpha = llt_.solve(c.mik);
    return c;
  }
  const SparseMatrix& M_;
  std::vector<int> position_;
  int rank_;
  SparseMatrix M_ii_;
  Eigen::SimplicialLLT<SparseMatrix> llt_;
};

/// Which traces are dependent, found by SuiteSparseQR's rank-revealing sparse QR: a column whose
/// part outside the span of the columns before it (in its fill-reducing order, which depends on the
/// pattern only, so every rank and the serial run choose alike) is below the threshold (relative,
/// as a column-pivoted QR's) is dependent; the first `rank` columns of its permutation are the
/// others. (Eigen's own SparseQR chose alike but took 7 s for 8 000 functions: it recomputes its
/// elimination tree at every dependent column.)
TraceSelection sparse_selection(const SparseMatrix& M) {
  const int m = static_cast<int>(M.cols());
  double largest = 0;
  for (int k = 0; k < m; ++k) largest = std::max(largest, M.col(k).norm());
  Eigen::SPQR<SparseMatrix> qr;
  qr.setPivotThreshold(1e-10 * largest);
  qr.compute(M);
  if (qr.info() != Eigen::Success) throw NumericalError("boundary projection: the QR of the boundary traces failed");
  const int rank = static_cast<int>(qr.rank());
  const auto perm = qr.colsPermutation();
  const auto& order = perm.indices();
  TraceSelection s;
  for (int j = 0; j < m; ++j) (j < rank ? s.independent : s.dependent).push_back(static_cast<int>(order[j]));
  return s;
}

/// The QR's order knows nothing of the traces' sizes: it may keep a small trace and express a large
/// one through it (large α, an ill-conditioned basis change: CG + GAMG needed twice the iterations
/// and stopped 40× farther from the solution on the 4-split fan5 plate at 3.3·10⁵ DOFs). Each
/// dependency is local, so the choice is redone where it matters: the dependent traces and the
/// independent ones they are combinations of form small clusters, and in each a dense
/// column-pivoted QR (largest remaining trace first) chooses which to keep. A cluster's span is
/// the same whichever of its columns are kept, so the union is again independent and complete.
void pivot_within_clusters(const SparseMatrix& M, TraceSelection& s) {
  const int m = static_cast<int>(M.cols());
  std::vector<int> root(m);
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&](int k) {
    while (root[k] != k) k = root[k] = root[root[k]];
    return k;
  };
  {
    const IndependentTraces traces(M, s.independent);
    for (int k : s.dependent) {
      const Eigen::VectorXd a = traces.alpha(k);  // only which traces: the final choice is checked
      const double amax = a.cwiseAbs().maxCoeff();
      for (std::size_t j = 0; j < s.independent.size(); ++j)
        if (std::abs(a(j)) > 1e-12 * amax) root[find(s.independent[j])] = find(k);
    }
  }
  std::vector<char> is_dependent(m, 0);
  for (int k : s.dependent) is_dependent[k] = 1;
  std::map<int, std::vector<int>> clusters;  // by root, each increasing
  for (int k = 0; k < m; ++k) clusters[find(k)].push_back(k);
  constexpr int kLargestCluster = 400;  // a dense QR of this many columns is still cheap
  TraceSelection chosen;
  for (const auto& [r, columns] : clusters) {
    int kept = 0;
    for (int k : columns) kept += !is_dependent[k];
    bool done = false;
    if (kept < static_cast<int>(columns.size()) && static_cast<int>(columns.size()) <= kLargestCluster) {
      Eigen::MatrixXd block = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(columns.size()), static_cast<Eigen::Index>(columns.size()));
      for (int b = 0; b < static_cast<int>(columns.size()); ++b)
        for (SparseMatrix::InnerIterator it(M, columns[b]); it; ++it) {
          const auto at = std::lower_bound(columns.begin(), columns.end(), static_cast<int>(it.row()));
          if (at != columns.end() && *at == it.row()) block(at - columns.begin(), b) = it.value();
        }
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(block);
      qr.setThreshold(1e-10);
      if (qr.rank() == kept) {  // otherwise the cluster missed a coefficient below 1e-12: keep the QR's
        const auto& perm = qr.colsPermutation().indices();
        for (int j = 0; j < static_cast<int>(columns.size()); ++j)
          (j < kept ? chosen.independent : chosen.dependent).push_back(columns[perm[j]]);
        done = true;
      }
    }
    if (!done)
      for (int k : columns) (is_dependent[k] ? chosen.dependent : chosen.independent).push_back(k);
  }
  s = std::move(chosen);
}

}  // namespace

void split_dependent_traces(const SparseMatrix& M, const Eigen::VectorXd& r, const std::vector<int>& order,
                            const std::vector<int>& local_of, Constraints& c) {
  TraceSelection s = sparse_selection(M);
  pivot_within_clusters(M, s);
  const int rank = static_cast<int>(s.independent.size());
  const IndependentTraces traces(M, s.independent);
  Eigen::VectorXd r_i(rank);
  for (int j = 0; j < rank; ++j) r_i(j) = r(s.independent[j]);
  const Eigen::VectorXd a = traces.solve(r_i);
  for (int j = 0; j < rank; ++j) c.values(order[s.independent[j]]) = a(j);

  for (int j : s.independent) c.constrained.push_back(order[j]);
  std::sort(c.constrained.begin(), c.constrained.end());
  std::vector<char> is_constrained(local_of.size(), 0);
  for (int g : c.constrained) is_constrained[g] = 1;
  for (int i = 0; i < static_cast<int>(local_of.size()); ++i)
    if (!is_constrained[i]) c.free.push_back(i);

  // Each dependent φ_k: its trace equals Σ α_j tr φ_j exactly (checked).
  for (int k : s.dependent) {
    const Eigen::VectorXd alpha = traces.checked_alpha(k);
    const int column = static_cast<int>(std::lower_bound(c.free.begin(), c.free.end(), order[k]) - c.free.begin());
    const double amax = alpha.cwiseAbs().maxCoeff();
    for (int j = 0; j < rank; ++j)
      if (std::abs(alpha(j)) > 1e-14 * amax) c.basis_change.emplace_back(order[s.independent[j]], column, -alpha(j));
  }
}

}  // namespace iga
