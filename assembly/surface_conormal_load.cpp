#include "assembly/surface_conormal_load.hpp"

#include <cmath>
#include <stdexcept>

#include "assembly/edge_points.hpp"
#include "config/errors.hpp"

namespace iga {

Eigen::VectorXd surface_conormal_load(const Space& space, const std::vector<BoundaryEdge>& edges,
                                      const SurfaceSource& g, int quad_degree) {
  if (space.ambient_dimension() != 3) throw std::logic_error("surface_conormal_load: a space on a surface in 3D");
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space.dimension());
  const auto evaluator = space.make_evaluator();
  PointValues v;
  for (const BoundaryEdge& edge : edges) {
    const RulePtr rule = space.edge_quadrature(edge.element, edge.local_edge, quad_degree);
    evaluator->evaluate(edge.element, *rule, update_values | update_gradients | update_surface_curvature, v);
    const CellShape shape = space.cell_shape(edge.element);
    const Point2 t2 = reference_edge_tangent(shape, edge.local_edge);
    for (int k = 0; k < rule->size(); ++k) {
      const Eigen::Vector3d nu = outward_conormal(v, k, shape, edge.local_edge);
      const double ds = rule->weights[k] * (v.jacobian3[k] * Eigen::Vector2d(t2.x(), t2.y())).norm();
      const double gk = g(v.x3.col(k), v.normal3.col(k), v.mean_curvature(k));
      if (!std::isfinite(gk)) throw InputError("the boundary data are not finite on the boundary of the surface");
      for (int i = 0; i < v.num_functions(); ++i)
        b(v.dofs[i]) += gk * ds * (v.dx(i, k) * nu(0) + v.dy(i, k) * nu(1) + v.dz(i, k) * nu(2));
    }
  }
  return b;
}

}  // namespace iga
