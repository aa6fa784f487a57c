#include "spaces/g1_4split/fair_geometry.hpp"

#include <Eigen/Dense>
#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cmath>

#include "config/errors.hpp"
#include "quadrature/quadrature_rule.hpp"
#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/g1_4split/edge_equations.hpp"

namespace iga {

Eigen::MatrixXd derivative_gram_1d(const SplitBSpline& b, int n) {
  const int k = b.degree();
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(b.size(), b.size());
  if (n > k) return G;
  const QuadratureRule g = gauss_legendre(k + 1);
  for (int h = 0; h < 2; ++h) {
    // n-th derivative of the Bernstein form on the half: n forward differences, degree k - n; the
    // half has length 1/2, so d/dt = 2 d/ds.
    Eigen::MatrixXd D = b.bernstein_extraction(h);
    for (int j = 0; j < n; ++j) D = ((k - j) * (D.bottomRows(D.rows() - 1) - D.topRows(D.rows() - 1))).eval();
    D *= std::pow(2.0, n);
    for (int q = 0; q < g.size(); ++q) {
      const Eigen::RowVectorXd N = bernstein_derivatives(k - n, g.points[q].x(), 0).row(0) * D;
      G += 0.5 * g.weights[q] * N.transpose() * N;
    }
  }
  return G;
}

namespace {

/// The face matrix of ∫ |D^n f|² + w f² (all ordered n-th partials: Σ_i C(n,i) ∂u^i ∂v^(n-i)).
Eigen::MatrixXd face_energy(const SplitBSpline& b, const FairFit& fit) {
  const int s = b.size();
  std::vector<Eigen::MatrixXd> G;
  for (int j = 0; j <= fit.order; ++j) G.push_back(derivative_gram_1d(b, j));
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(s * s, s * s);
  for (int i = 0; i <= fit.order; ++i) E += binomial(fit.order, i) * face_tensor_product(G[i], G[fit.order - i]);
  E += fit.fit_weight * face_tensor_product(G[0], G[0]);
  return E;
}

/// The faces' coefficients of the map with coefficients c = (c_x, c_y) in the basis B.
FaceGeometry to_faces(const Eigen::SparseMatrix<double>& B, const Eigen::VectorXd& c, int F, int fs) {
  const int dim = static_cast<int>(B.cols());
  const Eigen::VectorXd hx = B * c.head(dim), hy = B * c.tail(dim);
  FaceGeometry out;
  for (int f = 0; f < F; ++f) {
    out.x.push_back(hx.segment(f * fs, fs));
    out.y.push_back(hy.segment(f * fs, fs));
  }
  return out;
}

/// One linear condition on a broken coefficient (x, y): cx x + cy y = value.
struct PointCondition {
  int row;
  double cx, cy, value;
};

/// Boundary vertices at their mesh positions; every other trace coefficient of a boundary edge on
/// the line through its two vertices (a trace is a spline in t: on the line iff its coefficients are).
std::vector<PointCondition> boundary_conditions(const QuadTopology& t, const PatchMesh& mesh, const SplitBSpline& b) {
  std::vector<PointCondition> out;
  std::vector<bool> fixed(t.num_vertices(), false);
  const int fs = b.face_size(), m = b.last();
  for (int e = 0; e < t.num_edges(); ++e) {
    const QuadEdge& edge = t.edge(e);
    if (!edge.boundary()) continue;
    const QuadSide side = edge.sides[0];
    const int v0 = t.face(side.face)[side.local_edge], v1 = t.face(side.face)[(side.local_edge + 1) % 4];
    const Point2 p0 = mesh.vertex(v0), p1 = mesh.vertex(v1);
    const Point2 d = (p1 - p0).normalized(), n(-d.y(), d.x());
    const std::vector<int> row = side_row(b, side.local_edge, 0);
    for (int i = 0; i <= m; ++i) {
      const int r = side.face * fs + row[i];
      if (i == 0 || i == m) {
        const int v = i == 0 ? v0 : v1;
        if (fixed[v]) continue;
        fixed[v] = true;
        out.push_back({r, 1.0, 0.0, mesh.vertex(v).x()});
        out.push_back({r, 0.0, 1.0, mesh.vertex(v).y()});
      } else {
        out.push_back({r, n.x(), n.y(), n.dot(p0)});
      }
    }
  }
  return out;
}

}  // namespace

FaceGeometry fair_geometry(const G14Basis& basis, const QuadTopology& topology, const PatchMesh& mesh,
                           const FairFit& fit) {
  const SplitBSpline& b = basis.bspline;
  const int fs = b.face_size(), F = topology.num_faces(), dim = basis.dimension();
  const FaceGeometry bilinear = bilinear_geometry(mesh, b);
  const Eigen::SparseMatrix<double> E = block_diagonal(face_energy(b, fit), F);
  const Eigen::SparseMatrix<double>& B = basis.functions;
  const Eigen::SparseMatrix<double> EB = E * B;
  const Eigen::SparseMatrix<double> A = Eigen::SparseMatrix<double>(B.transpose()) * EB;

  // Constraints on (c_x, c_y): rows of B combined per condition, scaled to unit norm.
  const std::vector<PointCondition> conditions = boundary_conditions(topology, mesh, b);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Br = B;
  const int nc = static_cast<int>(conditions.size());
  std::vector<Eigen::Triplet<double>> ct;
  Eigen::VectorXd d(nc);
  for (int i = 0; i < nc; ++i) {
    const PointCondition& p = conditions[i];
    double norm2 = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Br, p.row); it; ++it)
      norm2 += it.value() * it.value() * (p.cx * p.cx + p.cy * p.cy);
    const double s = 1.0 / std::sqrt(std::max(norm2, 1e-300));
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Br, p.row); it; ++it) {
      if (p.cx != 0.0) ct.emplace_back(i, static_cast<int>(it.col()), s * p.cx * it.value());
      if (p.cy != 0.0) ct.emplace_back(i, dim + static_cast<int>(it.col()), s * p.cy * it.value());
    }
    d(i) = s * p.value;
  }
  Eigen::SparseMatrix<double> C(nc, 2 * dim);
  C.setFromTriplets(ct.begin(), ct.end());

  Eigen::VectorXd gx(F * fs), gy(F * fs);
  for (int f = 0; f < F; ++f) {
    gx.segment(f * fs, fs) = bilinear.x[f];
    gy.segment(f * fs, fs) = bilinear.y[f];
  }
  // Solve for the change from the least-squares map c0: where the bilinear map is in the space,
  // c0 is it and every right-hand side below is round-off, so the map stays at round-off
  // (the energy's conditioning multiplies residuals, not the data).
  FairFit mass_only;
  mass_only.order = 0;
  mass_only.fit_weight = 0.0;
  const Eigen::SparseMatrix<double> MB = block_diagonal(face_energy(b, mass_only), F) * B;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> gram(Eigen::SparseMatrix<double>(B.transpose()) * MB);
  if (gram.info() != Eigen::Success) throw NumericalError("g1_4split: fair geometry: singular Gram matrix");
  Eigen::VectorXd c0(2 * dim);
  c0.head(dim) = gram.solve(Eigen::VectorXd(MB.transpose() * gx));
  c0.tail(dim) = gram.solve(Eigen::VectorXd(MB.transpose() * gy));
  Eigen::VectorXd r(2 * dim);
  r.head(dim) = EB.transpose() * Eigen::VectorXd(gx - B * c0.head(dim));
  r.tail(dim) = EB.transpose() * Eigen::VectorXd(gy - B * c0.tail(dim));
  d -= C * c0;
  // The bilinear map in the space (regular and once-split fans): it is the minimum (energy 0, the
  // conditions hold), and the least-squares map is it to the rounding of the Gram solve: keep that
  // map bit for bit, rather than add the energy's rounding to it. Rounding: the misfit is ~1e-11
  // of the domain's size on the split fans; a map within 1e-8 of the bilinear one is as fair.
  double scale = 1.0;
  for (int v = 0; v < mesh.num_vertices(); ++v) scale = std::max(scale, mesh.vertex(v).norm());
  const double off = std::max((gx - B * c0.head(dim)).lpNorm<Eigen::Infinity>(),
                              (gy - B * c0.tail(dim)).lpNorm<Eigen::Infinity>());
  if (off <= 1e-8 * scale && d.lpNorm<Eigen::Infinity>() <= 1e-8 * scale) return project_geometry(basis, bilinear);
  if (nc == 0) return project_geometry(basis, bilinear);  // no boundary: not a planar domain
  // Minimise with the conditions by the method of multipliers: one factorization of
  // H + β CᵀC (H = diag(A, A)), then c = (H + β CᵀC)⁻¹ (r + Cᵀ(β d − λ)) and λ += β (C c − d) until
  // the conditions hold to round-off (each step shrinks their residual by the factor
  // 1 / (1 + β μ) of the smallest μ of C H⁻¹ Cᵀ off its kernel). Conditions repeat at straight
  // boundary vertices (both edges' first derivatives on one line): λ is then not unique, the map
  // is. The Schur complement C H⁻¹ Cᵀ this replaces took one pair of solves per condition (26 s
  // for a 400-quad mesh against 1 s for the least-squares map). A last minimum-norm correction
  // is kept for a residual the iteration leaves.
  std::vector<Eigen::Triplet<double>> ht;
  ht.reserve(2 * A.nonZeros());
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) {
      ht.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
      ht.emplace_back(dim + static_cast<int>(it.row()), dim + static_cast<int>(it.col()), it.value());
    }
  Eigen::SparseMatrix<double> H(2 * dim, 2 * dim);
  H.setFromTriplets(ht.begin(), ht.end());
  const Eigen::SparseMatrix<double> Ct = C.transpose();
  const double beta = 1e3 * A.diagonal().maxCoeff();  // C's rows have unit norm
  const Eigen::SparseMatrix<double> K = H + beta * Eigen::SparseMatrix<double>(Ct * C);
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> solver(K);
  if (solver.info() != Eigen::Success) throw NumericalError("g1_4split: fair geometry: singular energy matrix");
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(nc), sol;
  for (int step = 0; step < 100; ++step) {
    sol = solver.solve(Eigen::VectorXd(r + Ct * (beta * d - lambda)));
    const Eigen::VectorXd misfit = C * sol - d;
    if (misfit.lpNorm<Eigen::Infinity>() <= 1e-13 * scale) break;
    lambda += beta * misfit;
  }
  if ((C * sol - d).lpNorm<Eigen::Infinity>() > 1e-13 * scale) {
    const Eigen::MatrixXd CCt = Eigen::MatrixXd(C * Ct);
    sol -= Ct * CCt.completeOrthogonalDecomposition().solve(Eigen::VectorXd(C * sol - d));
  }
  const Eigen::VectorXd residual = C * sol - d;
  sol += c0;
  if (!(residual.lpNorm<Eigen::Infinity>() <= 1e-9 * scale))
    throw NumericalError("g1_4split: fair geometry: the space cannot keep the boundary on the mesh's segments (residual " +
                         std::to_string(residual.lpNorm<Eigen::Infinity>()) + ")");
  return to_faces(B, sol, F, fs);
}

}  // namespace iga
