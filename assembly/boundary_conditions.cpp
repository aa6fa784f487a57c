#include "assembly/parallel.hpp"
#include "assembly/boundary_conditions.hpp"
#include "assembly/boundary_projection.hpp"
#include "assembly/dependent_traces.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <map>

#include "config/errors.hpp"
#include "spaces/element_values.hpp"

namespace iga {

namespace {

struct EdgeKind {
  bool value = false;
  bool normal = false;
};

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

Constraints all_free(int n) {
  Constraints c;
  c.values = Eigen::VectorXd::Zero(n);
  c.free.resize(n);
  for (int i = 0; i < n; ++i) c.free[i] = i;
  return c;
}

Constraints impose_essential(const Space& space, const EssentialBoundary& boundary, const BoundaryField& g,
                             const BoundaryField& g_n, int quad_degree) {
  const int dim = space.dimension();
  if (boundary.empty()) return all_free(dim);
  Constraints c;
  c.values = Eigen::VectorXd::Zero(dim);
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
