#include "assembly/parallel.hpp"
#include "assembly/error_norms.hpp"

#include <cmath>

#include "spaces/element_values.hpp"

namespace iga {

ErrorNorms error_norms(const Space& space, const Eigen::VectorXd& coefficients, const ExactSolution& exact,
                       int quad_degree) {
  const bool grad = exact.has_gradient(), hess = exact.has_hessian();
  const unsigned flags = update_values | (grad ? update_gradients : 0u) | (hess ? update_hessians : 0u);
  const int ne = space.num_elements();
  double l2 = 0, h1 = 0, h2 = 0;
#pragma omp parallel reduction(+ : l2, h1, h2) if (worth_threads(ne))
  {
    ElementValues ev(space, flags);
    Eigen::VectorXd c;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < ne; ++e) {
      ev.reinit(e, *space.quadrature(e, quad_degree));
      const PointValues& v = ev.values();
      const int n = ev.num_functions();
      c.resize(n);
      for (int i = 0; i < n; ++i) c(i) = coefficients(ev.dofs()[i]);
      const Eigen::VectorXd uh = v.value.transpose() * c;
      for (int k = 0; k < ev.num_points(); ++k) {
        const Point2 x = v.x.col(k);
        const double w = ev.jxw()(k);
        l2 += w * std::pow(uh(k) - exact.u(x), 2);
        if (grad) {
          const double ex = v.dx.col(k).dot(c) - exact.ux(x), ey = v.dy.col(k).dot(c) - exact.uy(x);
          h1 += w * (ex * ex + ey * ey);
        }
        if (hess) {
          const double exx = v.dxx.col(k).dot(c) - exact.uxx(x);
          const double exy = v.dxy.col(k).dot(c) - exact.uxy(x);
          const double eyy = v.dyy.col(k).dot(c) - exact.uyy(x);
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

std::pair<double, double> integral_and_area(const Space& space, const Eigen::VectorXd& coefficients,
                                            int quad_degree) {
  double integral = 0, area = 0;
  const int ne = space.num_elements();
#pragma omp parallel reduction(+ : integral, area) if (worth_threads(ne))
  {
    ElementValues ev(space, update_values);
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < ne; ++e) {
      ev.reinit(e, *space.quadrature(e, quad_degree));
      for (int k = 0; k < ev.num_points(); ++k) {
        double uh = 0;
        for (int i = 0; i < ev.num_functions(); ++i) uh += coefficients(ev.dofs()[i]) * ev.values().value(i, k);
        integral += ev.jxw()(k) * uh;
        area += ev.jxw()(k);
      }
    }
  }
  return {integral, area};
}

}  // namespace iga
