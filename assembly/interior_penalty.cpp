#include "assembly/interior_penalty.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "assembly/edge_points.hpp"

namespace iga {

namespace {

/// One side of an edge at its points: per active function the conormal derivative and Δ_Γ.
struct Side {
  Eigen::MatrixXd conormal, laplacian;  // n × q
};

Side side_values(const PointValues& g, CellShape shape, int edge) {
  const int n = static_cast<int>(g.dofs.size()), q = static_cast<int>(g.x3.cols());
  Side s{Eigen::MatrixXd(n, q), Eigen::MatrixXd(n, q)};
  for (int k = 0; k < q; ++k) {
    const Eigen::Vector3d nu = outward_conormal(g, k, shape, edge);
    s.conormal.col(k) = g.dx.col(k) * nu.x() + g.dy.col(k) * nu.y() + g.dz.col(k) * nu.z();
    s.laplacian.col(k) = g.dxx.col(k) + g.dyy.col(k) + g.dzz.col(k);
  }
  return s;
}

/// Runs `visit(edge, a, b, values_a, values_b, ds)` over every interior edge, with both sides
/// evaluated (values, surface gradients, covariant Hessians, normals and curvature) at the same
/// physical points, ds the length elements.
template <class Visit>
void for_each_edge(const Space& space, int quadrature_degree, Visit&& visit) {
  const std::vector<InteriorEdge> edges = space.interior_edges();
  const QuadratureRule line = gauss_legendre_for_degree(quadrature_degree);
  const int ne = static_cast<int>(edges.size());
  // Point sets of both sides, alive for the whole call: evaluators may cache tables by rule address.
  const EdgeSideRules sides = edge_side_rules(space, edges, line);
  const std::vector<QuadratureRule>& side_a = sides.a;
  const std::vector<QuadratureRule>& side_b = sides.b;
  const unsigned flags = update_values | update_gradients | update_hessians | update_surface_curvature;
  std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues a, b;
  Eigen::VectorXd ds(line.size());
  for (int k = 0; k < ne; ++k) {
    const InteriorEdge& e = edges[k];
    evaluator->evaluate(e.element_a, side_a[k], flags, a);
    evaluator->evaluate(e.element_b, side_b[k], flags, b);
    const Point2 t = reference_edge_tangent(space.cell_shape(e.element_a), e.edge_a);
    for (int q = 0; q < line.size(); ++q)
      ds(q) = line.weights[q] * (a.jacobian3[q] * Eigen::Vector2d(t.x(), t.y())).norm() * std::abs(e.a1 - e.a0);
    visit(e, a, b, ds);
  }
}

}  // namespace

SparseMatrix c0ip_edge_matrix(const Space& space, double eta, int quadrature_degree) {
  if (space.ambient_dimension() != 3) throw std::invalid_argument("c0ip_edge_matrix: a space on a surface in 3D");
  std::vector<Eigen::Triplet<double>> entries;
  for_each_edge(space, quadrature_degree, [&](const InteriorEdge& e, const PointValues& a, const PointValues& b,
                                              const Eigen::VectorXd& ds) {
    const Side sa = side_values(a, space.cell_shape(e.element_a), e.edge_a);
    const Side sb = side_values(b, space.cell_shape(e.element_b), e.edge_b);
    const int na = static_cast<int>(a.dofs.size()), nb = static_cast<int>(b.dofs.size()), n = na + nb;
    // Both sides' functions in one local list (a function active on both appears twice; the
    // triplets add its two parts): jump J = [∂_ν ·], average A = {Δ_Γ ·}.
    Eigen::MatrixXd J(n, ds.size()), A(n, ds.size());
    J << sa.conormal, sb.conormal;
    A << 0.5 * sa.laplacian, 0.5 * sb.laplacian;
    const double h = ds.sum();
    const Eigen::MatrixXd JW = J * ds.asDiagonal();
    const Eigen::MatrixXd local = -(A * JW.transpose() + JW * A.transpose()) + (eta / h) * (J * JW.transpose());
    std::vector<int> dofs(a.dofs);
    dofs.insert(dofs.end(), b.dofs.begin(), b.dofs.end());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) entries.emplace_back(dofs[i], dofs[j], local(i, j));
  });
  SparseMatrix E(space.dimension(), space.dimension());
  E.setFromTriplets(entries.begin(), entries.end());
  return E;
}

Eigen::VectorXd c0ip_edge_load(const Space& space, const SurfaceSource& laplacian, int quadrature_degree) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(space.dimension());
  for_each_edge(space, quadrature_degree, [&](const InteriorEdge& e, const PointValues& a, const PointValues& b,
                                              const Eigen::VectorXd& ds) {
    const Side sa = side_values(a, space.cell_shape(e.element_a), e.edge_a);
    const Side sb = side_values(b, space.cell_shape(e.element_b), e.edge_b);
    Eigen::VectorXd w(ds.size());  // −{Δ_Γu} ds at each point
    for (int q = 0; q < ds.size(); ++q)
      w(q) = -0.5 *
             (laplacian(a.x3.col(q), a.normal3.col(q), a.mean_curvature(q)) +
              laplacian(b.x3.col(q), b.normal3.col(q), b.mean_curvature(q))) *
             ds(q);
    const Eigen::VectorXd la = sa.conormal * w, lb = sb.conormal * w;
    for (int i = 0; i < la.size(); ++i) load(a.dofs[i]) += la(i);
    for (int i = 0; i < lb.size(); ++i) load(b.dofs[i]) += lb(i);
  });
  return load;
}

}  // namespace iga
