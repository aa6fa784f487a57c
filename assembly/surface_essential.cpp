#include "assembly/surface_essential.hpp"

#include <Eigen/Geometry>  // cross
#include <set>
#include <stdexcept>
#include <utility>

#include "assembly/boundary_projection.hpp"
#include "config/errors.hpp"

namespace iga {

Constraints surface_essential_constraints(const Space& space, const std::vector<BoundaryEdge>& edges,
                                          const SurfaceField& g, const SurfaceConormalField& g_conormal,
                                          int quad_degree) {
  return surface_essential_constraints(space, EssentialBoundary{edges, g_conormal ? edges : std::vector<BoundaryEdge>{}},
                                       g, g_conormal, quad_degree);
}

Constraints surface_essential_constraints(const Space& space, const EssentialBoundary& boundary,
                                          const SurfaceField& g, const SurfaceConormalField& g_conormal,
                                          int quad_degree) {
  if (space.ambient_dimension() != 3)
    throw std::logic_error("surface_essential_constraints: the space is not on a surface in 3D");
  if (!boundary.normal_edges.empty() && !g_conormal)
    throw std::logic_error("surface_essential_constraints: conormal edges without conormal data");
  const int dim = space.dimension();
  std::set<std::pair<int, int>> clamped;
  for (const BoundaryEdge& e : boundary.normal_edges) clamped.insert({e.element, e.local_edge});
  const auto evaluator = space.make_evaluator();
  PointValues v;
  std::vector<int> local_of(dim, -1), order, active;
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<std::pair<int, double>> rhs_entries;
  for (const BoundaryEdge& edge : boundary.value_edges) {
    const bool conormal = clamped.count({edge.element, edge.local_edge}) > 0;
    const RulePtr rule = space.edge_quadrature(edge.element, edge.local_edge, quad_degree);
    evaluator->evaluate(edge.element, *rule,
                        update_values | (conormal ? update_gradients | update_surface_curvature : 0u), v);
    const CellShape shape = space.cell_shape(edge.element);
    const Point2 t2 = reference_edge_tangent(shape, edge.local_edge);
    const int q = rule->size(), n = v.num_functions();
    Eigen::VectorXd ds(q), gv(q), gn = Eigen::VectorXd::Zero(q);
    Eigen::MatrixXd dnu = Eigen::MatrixXd::Zero(n, q);
    for (int k = 0; k < q; ++k) {
      const Eigen::Matrix<double, 3, 2>& J = v.jacobian3[k];
      const Eigen::Vector3d t = J * Eigen::Vector2d(t2.x(), t2.y());
      ds(k) = rule->weights[k] * t.norm();
      const Eigen::Vector3d x = v.x3.col(k);
      gv(k) = g(x);
      if (!conormal) continue;
      // ν ⟂ t in the tangent plane, turned away from the element: the reference point moved
      // towards the cell's centre maps to an inward tangent vector.
      Eigen::Vector3d nu = t.cross(Eigen::Vector3d(v.normal3.col(k))).normalized();
      const Point2 p = reference_edge_point(shape, edge.local_edge, 0.5);
      const Eigen::Vector2d centre =
          shape == CellShape::quadrilateral ? Eigen::Vector2d(0.5, 0.5) : Eigen::Vector2d(1.0 / 3, 1.0 / 3);
      const Eigen::Vector2d inward = centre - Eigen::Vector2d(p.x(), p.y());
      if (nu.dot(J * inward) > 0) nu = -nu;
      gn(k) = g_conormal(x, nu);
      dnu.col(k) = v.dx.col(k) * nu(0) + v.dy.col(k) * nu(1) + v.dz.col(k) * nu(2);
    }
    if (!gv.allFinite() || !gn.allFinite())
      throw InputError("the boundary data are not finite on the boundary of the surface");
    const double vmax = v.value.cwiseAbs().maxCoeff(), nmax = conormal ? dnu.cwiseAbs().maxCoeff() : 0.0;
    active.clear();
    for (int i = 0; i < n; ++i) {
      const bool seen_value = v.value.row(i).cwiseAbs().maxCoeff() > kActiveTolerance * vmax;
      const bool seen_normal = conormal && dnu.row(i).cwiseAbs().maxCoeff() > kActiveTolerance * nmax;
      if (!seen_value && !seen_normal) continue;
      active.push_back(i);
      if (local_of[v.dofs[i]] < 0) {
        local_of[v.dofs[i]] = static_cast<int>(order.size());
        order.push_back(v.dofs[i]);
      }
    }
    const double length = ds.sum(), wn = length * length;  // h_E² balances the units of u and ∂_ν u
    for (int k = 0; k < q; ++k)
      for (int i : active) {
        const int li = local_of[v.dofs[i]];
        rhs_entries.emplace_back(li, ds(k) * (gv(k) * v.value(i, k) + wn * gn(k) * dnu(i, k)));
        for (int j : active)
          triplets.emplace_back(li, local_of[v.dofs[j]],
                                ds(k) * (v.value(i, k) * v.value(j, k) + wn * dnu(i, k) * dnu(j, k)));
      }
  }
  return solve_boundary_projection(dim, triplets, rhs_entries, order, local_of);
}

}  // namespace iga
