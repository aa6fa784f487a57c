#include <Eigen/Geometry>  // cross

#include <cmath>
#include <memory>

#include "assembly/error_norms.hpp"
#include "assembly/parallel.hpp"

namespace iga {

ErrorNorms surface_error_norms(const Space& space, const Eigen::VectorXd& coefficients,
                               const SurfaceExactSolution& exact, int quad_degree) {
  const bool grad = exact.has_gradient();
  const unsigned flags = update_values | (grad ? update_gradients : 0u);
  const int ne = space.num_elements();
  double l2 = 0, h1 = 0;
#pragma omp parallel reduction(+ : l2, h1) if (worth_threads(ne))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    FunctionValues uh;
    Eigen::VectorXd jxw;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < ne; ++e) {
      const RulePtr rule_ptr = space.quadrature(e, quad_degree);
      const QuadratureRule& rule = *rule_ptr;
      evaluator->evaluate_function(e, rule, coefficients, flags, geometry, uh);
      integration_weights(rule, geometry, jxw);
      for (int k = 0; k < rule.size(); ++k) {
        const Eigen::Vector3d x = geometry.x3.col(k);
        const double w = jxw(k);
        l2 += w * std::pow(uh.value(k) - exact.u(x), 2);
        if (grad) {
          const Eigen::Vector3d n =
              geometry.jacobian3[k].col(0).cross(geometry.jacobian3[k].col(1)).normalized();
          Eigen::Vector3d g(exact.ux(x), exact.uy(x), exact.uz(x));
          g -= g.dot(n) * n;
          const Eigen::Vector3d e3 = Eigen::Vector3d(uh.dx(k), uh.dy(k), uh.dz(k)) - g;
          h1 += w * e3.squaredNorm();
        }
      }
    }
  }
  ErrorNorms r;
  r.l2 = std::sqrt(l2);
  if (grad) r.h1 = std::sqrt(h1);
  return r;
}

}  // namespace iga
