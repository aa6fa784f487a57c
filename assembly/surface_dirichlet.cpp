#include "assembly/surface_dirichlet.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "assembly/surface_essential.hpp"
#include "config/errors.hpp"

namespace iga {

Constraints surface_dirichlet_constraints(const Space& space, const std::vector<BoundaryEdge>& edges,
                                          const SurfaceField& g, int quad_degree) {
  if (space.ambient_dimension() != 3)
    throw std::logic_error("surface_dirichlet_constraints: the space is not on a surface in 3D");
  const auto evaluator = space.make_evaluator();
  PointValues v;
  // Per edge: the functions and points, kept for the second pass once the numbering is known.
  struct EdgeData {
    std::vector<int> dofs;
    Eigen::MatrixXd value;
    Eigen::VectorXd ds, g;
  };
  std::vector<EdgeData> data;
  std::map<int, int> position;  // constrained global index -> row of the projection
  for (const BoundaryEdge& edge : edges) {
    const RulePtr rule = space.edge_quadrature(edge.element, edge.local_edge, quad_degree);
    evaluator->evaluate(edge.element, *rule, update_values, v);
    const Point2 tangent = reference_edge_tangent(space.cell_shape(edge.element), edge.local_edge);
    EdgeData d;
    d.ds.resize(rule->size());
    d.g.resize(rule->size());
    for (int k = 0; k < rule->size(); ++k) {
      d.ds(k) = rule->weights[k] * (v.jacobian3[k] * Eigen::Vector2d(tangent.x(), tangent.y())).norm();
      d.g(k) = g(v.x3.col(k));
    }
    if (!d.g.allFinite()) throw InputError("the Dirichlet data are not finite on the boundary of the surface");
    // A function is seen by the data when its trace is not zero at the edge points (C0 spaces:
    // exactly the functions of the edge's nodes; the others vanish to round-off).
    for (int i = 0; i < v.num_functions(); ++i)
      if (v.value.row(i).cwiseAbs().maxCoeff() > 1e-12) {
        d.dofs.push_back(v.dofs[i]);
        position.emplace(v.dofs[i], 0);
      }
    d.value.resize(d.dofs.size(), rule->size());
    for (std::size_t a = 0, row = 0; a < v.dofs.size(); ++a)
      if (row < d.dofs.size() && v.dofs[a] == d.dofs[row]) d.value.row(row++) = v.value.row(a);
    data.push_back(std::move(d));
  }
  Constraints c;
  for (auto& [dof, row] : position) {
    row = static_cast<int>(c.constrained.size());
    c.constrained.push_back(dof);
  }
  const int n = static_cast<int>(c.constrained.size());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (const EdgeData& d : data) {
    std::vector<int> rows(d.dofs.size());
    for (std::size_t a = 0; a < d.dofs.size(); ++a) rows[a] = position.at(d.dofs[a]);
    const Eigen::MatrixXd weighted = d.value * d.ds.asDiagonal();
    const Eigen::MatrixXd local = weighted * d.value.transpose();
    const Eigen::VectorXd load = weighted * d.g;
    for (std::size_t a = 0; a < rows.size(); ++a) {
      rhs(rows[a]) += load(a);
      for (std::size_t b = 0; b < rows.size(); ++b) triplets.emplace_back(rows[a], rows[b], local(a, b));
    }
  }
  Eigen::SparseMatrix<double> M(n, n);
  M.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(M);
  // Dependent traces (the G1 vertex functions of a 4-split surface at a boundary corner): the
  // general projection constrains an independent subset and changes the basis of the others.
  if (ldlt.info() != Eigen::Success ||
      (n > 0 && ldlt.vectorD().minCoeff() <= 1e-13 * ldlt.vectorD().cwiseAbs().maxCoeff()))
    return surface_essential_constraints(space, edges, g, {}, quad_degree);
  const Eigen::VectorXd values = n > 0 ? Eigen::VectorXd(ldlt.solve(rhs)) : Eigen::VectorXd();
  c.values = Eigen::VectorXd::Zero(space.dimension());
  for (int r = 0; r < n; ++r) c.values(c.constrained[r]) = values(r);
  for (int i = 0, r = 0; i < space.dimension(); ++i) {
    if (r < n && c.constrained[r] == i) {
      ++r;
      continue;
    }
    c.free.push_back(i);
  }
  return c;
}

}  // namespace iga
