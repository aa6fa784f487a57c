#include "assembly/parallel.hpp"
#include "assembly/boundary_conditions.hpp"
#include "assembly/boundary_projection.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/QR>
#include <Eigen/SPQRSupport>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "config/errors.hpp"
#include "spaces/element_values.hpp"

namespace iga {

namespace {

struct EdgeKind {
  bool value = false;
  bool normal = false;
};

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
  int position(int k) const { return position_[k]; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return llt_.solve(b); }
  /// α of dependent column k; throws when its trace is not (to 1e-8 of its size) in their span.
  Eigen::VectorXd alpha(int k) const {
    Eigen::VectorXd mik = Eigen::VectorXd::Zero(rank_);
    double mkk = 0;
    for (SparseMatrix::InnerIterator it(M_, k); it; ++it) {
      if (position_[it.row()] >= 0) mik(position_[it.row()]) = it.value();
      if (it.row() == k) mkk = it.value();
    }
    Eigen::VectorXd a = llt_.solve(mik);
    const double residual = mkk - 2 * a.dot(mik) + a.dot(M_ii_ * a);
    if (residual > 1e-8 * mkk)
      throw NumericalError("boundary projection: a boundary trace is neither independent nor dependent (ill-conditioned)");
    return a;
  }

 private:
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
      const Eigen::VectorXd a = traces.alpha(k);
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

/// The singular case of impose_essential: M (m x m, Gram matrix of the boundary data of the
/// functions `order`) has dependent columns. Constrain an independent subset, keep the others free
/// with their trace combinations subtracted. Fills c.values, c.constrained, c.free, c.basis_change.
/// Sparse but for small clusters: the dependencies are local (a few functions at a corner or a
/// crossing), but there are some at every such place, so m grows with the boundary — a dense QR of
/// M cost O(m³) time and m² memory on every rank (1.3·10⁶ 4-split DOFs: 6 395 functions).
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

  // Each dependent φ_k: its trace equals Σ α_j tr φ_j exactly (checked by alpha()).
  for (int k : s.dependent) {
    const Eigen::VectorXd alpha = traces.alpha(k);
    const int column = static_cast<int>(std::lower_bound(c.free.begin(), c.free.end(), order[k]) - c.free.begin());
    const double amax = alpha.cwiseAbs().maxCoeff();
    for (int j = 0; j < rank; ++j)
      if (std::abs(alpha(j)) > 1e-14 * amax) c.basis_change.emplace_back(order[s.independent[j]], column, -alpha(j));
  }
}

/// Iterative refinement of the projection with residuals from the unsummed integrals in long
/// double: a few corrections remove the round-off of M's sums and of its factorization.
void refine_projection(const Eigen::SimplicialLDLT<SparseMatrix>& ldlt, const std::vector<Eigen::Triplet<double>>& m,
                       const std::vector<std::pair<int, double>>& rhs, Eigen::VectorXd& u) {
  std::vector<long double> r(u.size());
  Eigen::VectorXd rounded(u.size());
  for (int step = 0; step < 3; ++step) {
    std::fill(r.begin(), r.end(), 0.0L);
    for (const auto& [i, v] : rhs) r[i] += v;
    for (const auto& t : m) r[t.row()] -= static_cast<long double>(t.value()) * u(t.col());
    for (int i = 0; i < u.size(); ++i) rounded(i) = static_cast<double>(r[i]);
    u += ldlt.solve(rounded);
  }
}

}  // namespace

Constraints impose_essential(const Space& space, const EssentialBoundary& boundary, const BoundaryField& g,
                             const BoundaryField& g_n, int quad_degree) {
  const int dim = space.dimension();
  Constraints c;
  c.values = Eigen::VectorXd::Zero(dim);
  if (boundary.empty()) {
    c.free.resize(dim);
    for (int i = 0; i < dim; ++i) c.free[i] = i;
    return c;
  }
  // Merge the two edge lists: an edge can carry both kinds of data.
  std::map<std::pair<int, int>, EdgeKind> edges;
  for (const BoundaryEdge& e : boundary.value_edges) edges[{e.element, e.local_edge}].value = true;
  for (const BoundaryEdge& e : boundary.normal_edges) edges[{e.element, e.local_edge}].normal = true;

  // Pass 1: which functions are seen by the data, and the projection integrals in global indices.
  std::vector<int> local_of(dim, -1);
  std::vector<int> order;  // global indices in order of discovery
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<int, double>> rhs_entries;
  ElementValues ev(space, update_values | update_gradients);
  std::vector<int> active;
  Eigen::VectorXd dn;
  for (const auto& [key, kind] : edges) {
    const auto [element, edge] = key;
    ev.reinit_edge(element, edge, *space.edge_quadrature(element, edge, quad_degree));
    const PointValues& v = ev.values();
    const int n = ev.num_functions(), q = ev.num_points();
    const double length = ev.jxw().sum();
    Eigen::MatrixXd dnv(n, q);
    for (int k = 0; k < q; ++k) dnv.col(k) = v.dx.col(k) * ev.normal()(0, k) + v.dy.col(k) * ev.normal()(1, k);
    const double vmax = v.value.cwiseAbs().maxCoeff();
    const double nmax = dnv.cwiseAbs().maxCoeff();
    active.clear();
    for (int i = 0; i < n; ++i) {
      const bool seen_value = kind.value && v.value.row(i).cwiseAbs().maxCoeff() > kActiveTolerance * vmax;
      const bool seen_normal = kind.normal && dnv.row(i).cwiseAbs().maxCoeff() > kActiveTolerance * nmax;
      if (!seen_value && !seen_normal) continue;
      active.push_back(i);
      const int gi = ev.dofs()[i];
      if (local_of[gi] < 0) {
        local_of[gi] = static_cast<int>(order.size());
        order.push_back(gi);
      }
    }
    const double wn = length * length;  // h_E^2 balances the units of u and ∂u/∂n
    for (int k = 0; k < q; ++k) {
      const Point2 x = v.x.col(k), nrm = ev.normal().col(k);
      const double w = ev.jxw()(k);
      const double gv = kind.value ? g(x, nrm) : 0.0;
      const double gnv = kind.normal ? g_n(x, nrm) : 0.0;
      for (int i : active) {
        const int li = local_of[ev.dofs()[i]];
        double r = 0;
        if (kind.value) r += w * gv * v.value(i, k);
        if (kind.normal) r += wn * w * gnv * dnv(i, k);
        rhs_entries.emplace_back(li, r);
        for (int j : active) {
          double m = 0;
          if (kind.value) m += w * v.value(i, k) * v.value(j, k);
          if (kind.normal) m += wn * w * dnv(i, k) * dnv(j, k);
          triplets.emplace_back(li, local_of[ev.dofs()[j]], m);
        }
      }
    }
  }

  return solve_boundary_projection(dim, triplets, rhs_entries, order, local_of);
}

Constraints solve_boundary_projection(int dim, const std::vector<Eigen::Triplet<double>>& triplets,
                                      const std::vector<std::pair<int, double>>& rhs_entries,
                                      const std::vector<int>& order, const std::vector<int>& local_of) {
  Constraints c;
  c.values = Eigen::VectorXd::Zero(dim);
  // Pass 2: solve the small SPD projection system.
  const int m = static_cast<int>(order.size());
  SparseMatrix M(m, m);
  M.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::VectorXd r = Eigen::VectorXd::Zero(m);
  for (const auto& [i, val] : rhs_entries) r(i) += val;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(M);
  const double dmax = ldlt.info() == Eigen::Success ? ldlt.vectorD().cwiseAbs().maxCoeff() : 0.0;
  if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 1e-13 * dmax) {
    Eigen::VectorXd u = ldlt.solve(r);
    refine_projection(ldlt, triplets, rhs_entries, u);
    for (int k = 0; k < m; ++k) c.values(order[k]) = u(k);
    c.constrained = order;
    std::sort(c.constrained.begin(), c.constrained.end());
    for (int i = 0; i < dim; ++i)
      if (local_of[i] < 0) c.free.push_back(i);
    return c;
  }
  split_dependent_traces(M, r, order, local_of, c);
  return c;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> free_basis(const Constraints& c) {
  std::vector<Eigen::Triplet<double>> t = c.basis_change;
  for (int k = 0; k < static_cast<int>(c.free.size()); ++k) t.emplace_back(c.free[k], k, 1.0);
  Eigen::SparseMatrix<double, Eigen::RowMajor> T(static_cast<int>(c.values.size()), static_cast<int>(c.free.size()));
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

Eigen::VectorXd reduced_residual(const SplitMatrix& A, const Eigen::VectorXd& b, const Constraints& c,
                                 const Eigen::VectorXd& u_free) {
  const int nf = static_cast<int>(c.free.size());
  std::vector<long double> x(c.values.data(), c.values.data() + c.values.size());
  for (int k = 0; k < nf; ++k) x[c.free[k]] = u_free(k);
  for (const auto& t : c.basis_change) x[t.row()] += static_cast<long double>(t.value()) * u_free(t.col());
  // r = b − K x is b itself when x = 0 (homogeneous conditions, first residual): skip the product.
  const bool zero = std::all_of(x.begin(), x.end(), [](long double v) { return v == 0; });
  const std::vector<long double> r = zero ? std::vector<long double>(b.data(), b.data() + b.size())
                                          : residual_extended(A, x, b);
  std::vector<long double> out(nf);
  for (int k = 0; k < nf; ++k) out[k] = r[c.free[k]];
  for (const auto& t : c.basis_change) out[t.col()] += static_cast<long double>(t.value()) * r[t.row()];
  Eigen::VectorXd rounded(nf);
  for (int k = 0; k < nf; ++k) rounded(k) = static_cast<double>(out[k]);
  return rounded;
}

void reduce_system(const SparseMatrix& A, const Eigen::VectorXd& b, const Constraints& c, SparseMatrix& A_free,
                   Eigen::VectorXd& b_free) {
  reduce_system(SplitMatrix{A, Eigen::VectorXd()}, b, c, A_free, b_free);
}

void reduce_system(const SplitMatrix& K, const Eigen::VectorXd& b, const Constraints& c, SparseMatrix& A_free,
                   Eigen::VectorXd& b_free) {
  const SparseMatrix& A = K.high;
  const int dim = static_cast<int>(A.rows());
  const int nf = static_cast<int>(c.free.size());
  b_free = reduced_residual(K, b, c, Eigen::VectorXd::Zero(nf));
  if (!c.basis_change.empty()) {  // rare: dependent boundary traces (see impose_essential)
    const SparseMatrix T = free_basis(c);
    const SparseMatrix AT = A * T;
    A_free = SparseMatrix(T.transpose() * AT);
    return;
  }
  std::vector<int> free_of(dim, -1);
  for (int k = 0; k < nf; ++k) free_of[c.free[k]] = k;

  // Column by column: keep entries whose row and column are both free (inner order stays sorted).
  A_free.resize(nf, nf);
  std::vector<int> outer(nf + 1, 0);
#pragma omp parallel for schedule(static) if (worth_threads(nf))
  for (int k = 0; k < nf; ++k) {
    int count = 0;
    for (SparseMatrix::InnerIterator it(A, c.free[k]); it; ++it) count += free_of[it.row()] >= 0;
    outer[k + 1] = count;
  }
  for (int k = 0; k < nf; ++k) outer[k + 1] += outer[k];
  A_free.resizeNonZeros(outer[nf]);
  std::copy(outer.begin(), outer.end(), A_free.outerIndexPtr());
#pragma omp parallel for schedule(static) if (worth_threads(nf))
  for (int k = 0; k < nf; ++k) {
    int pos = outer[k];
    for (SparseMatrix::InnerIterator it(A, c.free[k]); it; ++it)
      if (free_of[it.row()] >= 0) {
        A_free.innerIndexPtr()[pos] = free_of[it.row()];
        A_free.valuePtr()[pos] = it.value();
        ++pos;
      }
  }
}

Eigen::VectorXd expand_solution(const Eigen::VectorXd& u_free, const Constraints& c) {
  // Column-major: the product adds into the values column by column (the row-major one would
  // sum each row first and round differently).
  if (!c.basis_change.empty()) return c.values + SparseMatrix(free_basis(c)) * u_free;
  Eigen::VectorXd u = c.values;
  for (int k = 0; k < static_cast<int>(c.free.size()); ++k) u(c.free[k]) = u_free(k);
  return u;
}

}  // namespace iga
