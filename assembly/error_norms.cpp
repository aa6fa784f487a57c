#include "assembly/parallel.hpp"
#include "assembly/error_norms.hpp"
#include "config/progress.hpp"

#include <cmath>

#include <memory>

#include "spaces/space.hpp"

namespace iga {

ErrorNorms error_norms(const Space& space, const Eigen::VectorXd& coefficients, const ExactSolution& exact,
                       int quad_degree) {
  const bool grad = exact.has_gradient(), hess = exact.has_hessian();
  const unsigned flags = update_values | (grad ? update_gradients : 0u) | (hess ? update_hessians : 0u);
  const int ne = space.num_elements();
  double l2 = 0, h1 = 0, h2 = 0;
#pragma omp parallel reduction(+ : l2, h1, h2) if (worth_threads(ne))
  {
    // u_h and its derivatives come from Space::Evaluator::evaluate_function (one contraction per
    // element instead of one table per active function).
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    FunctionValues uh;
    Eigen::VectorXd jxw;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < ne; ++e) {
      progress_tick();
      const RulePtr rule_ptr = space.quadrature(e, quad_degree);  // keeps the rule alive
      const QuadratureRule& rule = *rule_ptr;
      evaluator->evaluate_function(e, rule, coefficients, flags, geometry, uh);
      integration_weights(rule, geometry, jxw);
      for (int k = 0; k < rule.size(); ++k) {
        const Point2 x = geometry.x.col(k);
        const double w = jxw(k);
        l2 += w * std::pow(uh.value(k) - exact.u(x), 2);
        if (grad) {
          const double ex = uh.dx(k) - exact.ux(x), ey = uh.dy(k) - exact.uy(x);
          h1 += w * (ex * ex + ey * ey);
        }
        if (hess) {
          const double exx = uh.dxx(k) - exact.uxx(x);
          const double exy = uh.dxy(k) - exact.uxy(x);
          const double eyy = uh.dyy(k) - exact.uyy(x);
          h2 += w * (exx * exx + 2 * exy * exy + eyy * eyy);
        }
      }
    }
  }
  ErrorNorms r;
  r.l2 = std::sqrt(l2);
  if (grad) r.h1 = std::sqrt(h1);
  if (hess) r.h2 = std::sqrt(h2);
  return r;
}

}  // namespace iga
