#include "assembly/error_norms.hpp"
#include "config/progress.hpp"


#include <array>
#include <cmath>
#include <memory>

#include "assembly/parallel.hpp"
#include "assembly/surface_calculus.hpp"
#include "spaces/space.hpp"
#include "spaces/surface_values.hpp"

namespace iga {

namespace {

/// The element being summed, for norms that evaluate more there (the surface shape operator).
struct Where {
  Space::Evaluator& evaluator;
  int element;
  const QuadratureRule& rule;
};

/// The element loop both norms share: u_h and its derivatives from Space::Evaluator::
/// evaluate_function (coefficients contracted once per element, then one table product per
/// array), then `add(geometry, uh, jxw, sums)` accumulates the element's squared errors.
template <int N, class Add>
std::array<double, N> sum_over_elements(const Space& space, const Eigen::VectorXd& coefficients, unsigned flags,
                                        int quad_degree, const std::vector<int>* elements, Add&& add) {
  keep_eigen_serial();
  const int ne = elements ? static_cast<int>(elements->size()) : space.num_elements();
  std::array<double, N> total{};
#pragma omp parallel if (worth_threads(ne))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    FunctionValues uh;
    Eigen::VectorXd jxw;
    std::array<double, N> sums{};
#pragma omp for schedule(dynamic, 16) nowait
    for (int k = 0; k < ne; ++k) {
      progress_tick();
      const int e = elements ? (*elements)[k] : k;
      const RulePtr rule_ptr = space.quadrature(e, quad_degree);  // keeps the rule alive
      const QuadratureRule& rule = *rule_ptr;
      evaluator->evaluate_function(e, rule, coefficients, flags, geometry, uh);
      integration_weights(rule, geometry, jxw);
      add(geometry, uh, jxw, sums, Where{*evaluator, e, rule});
    }
#pragma omp critical(iga_error_norms)
    for (int i = 0; i < N; ++i) total[i] += sums[i];
  }
  return total;
}

double square(double v) { return v * v; }


}  // namespace

ErrorNorms error_norms(const Space& space, const Eigen::VectorXd& coefficients, const ExactSolution& exact,
                       int quad_degree, const std::vector<int>* elements) {
  const bool grad = exact.has_gradient(), hess = exact.has_hessian();
  const unsigned flags = update_values | (grad ? update_gradients : 0u) | (hess ? update_hessians : 0u);
  const auto sums = sum_over_elements<3>(
      space, coefficients, flags, quad_degree, elements,
      [&](const PointValues& geometry, const FunctionValues& uh, const Eigen::VectorXd& w, std::array<double, 3>& s,
          const Where&) {
        const int q = static_cast<int>(w.size());
        // The exact solution and its derivatives, one row each (u, ux, uy, uxx, uxy, uyy).
        thread_local Eigen::MatrixXd jet;
        if (exact.jet) {
          exact.jet(geometry.x, jet);
        } else {
          jet.resize(6, q);
          const ScalarField* fields[6] = {&exact.u, &exact.ux, &exact.uy, &exact.uxx, &exact.uxy, &exact.uyy};
          for (int i = 0; i < 6; ++i)
            if (*fields[i])
              for (int k = 0; k < q; ++k) jet(i, k) = (*fields[i])(geometry.x.col(k));
        }
        // One pass over the points, each reading its column of the jet (contiguous) rather than
        // six passes along strided rows.
        double l2 = 0, h1 = 0, h2 = 0;
        for (int k = 0; k < q; ++k) {
          const double* e = jet.col(k).data();
          l2 += w(k) * square(uh.value(k) - e[0]);
          if (grad) h1 += w(k) * (square(uh.dx(k) - e[1]) + square(uh.dy(k) - e[2]));
          if (hess) h2 += w(k) * (square(uh.dxx(k) - e[3]) + 2 * square(uh.dxy(k) - e[4]) + square(uh.dyy(k) - e[5]));
        }
        s[0] += l2;
        s[1] += h1;
        s[2] += h2;
      });
  ErrorNorms r;
  r.l2 = std::sqrt(sums[0]);
  if (grad) r.h1 = std::sqrt(sums[1]);
  if (hess) r.h2 = std::sqrt(sums[2]);
  return r;
}

ErrorNorms surface_error_norms(const Space& space, const Eigen::VectorXd& coefficients,
                               const SurfaceExactSolution& exact, int quad_degree, const std::vector<int>* elements) {
  const bool grad = exact.has_gradient(), hess = grad && exact.has_hessian();
  const unsigned flags = update_values | (grad ? update_gradients : 0u) | (hess ? update_hessians : 0u);
  const auto sums = sum_over_elements<3>(
      space, coefficients, flags, quad_degree, elements,
      [&](const PointValues& geometry, const FunctionValues& uh, const Eigen::VectorXd& w, std::array<double, 3>& s,
          const Where& where) {
        thread_local ShapeOperatorByDifferences differences;
        thread_local std::vector<Eigen::Matrix3d> W;
        if (hess)
          differences.compute(where.evaluator, where.element, where.rule,
                              space.cell_shape(where.element) == CellShape::triangle, geometry.jacobian3, W);
        for (int k = 0; k < w.size(); ++k) {
          const Eigen::Vector3d x = geometry.x3.col(k);
          s[0] += w(k) * std::pow(uh.value(k) - exact.u(x), 2);
          if (grad) {
            // The error of the surface gradient: the exact ambient gradient projected onto the
            // tangent plane, ∇_Γu = ∇u − (∇u·n) n.
            const Eigen::Vector3d n = surface_normal(geometry.jacobian3[k]);
            Eigen::Vector3d g(exact.ux(x), exact.uy(x), exact.uz(x));
            const Eigen::Vector3d g_surface = g - g.dot(n) * n;
            const Eigen::Vector3d e3 = Eigen::Vector3d(uh.dx(k), uh.dy(k), uh.dz(k)) - g_surface;
            s[1] += w(k) * e3.squaredNorm();
            if (hess) {
              Eigen::Matrix3d D;
              D << exact.uxx(x), exact.uxy(x), exact.uxz(x), exact.uxy(x), exact.uyy(x), exact.uyz(x), exact.uxz(x),
                  exact.uyz(x), exact.uzz(x);
              Eigen::Matrix3d Hh;
              Hh << uh.dxx(k), uh.dxy(k), uh.dxz(k), uh.dxy(k), uh.dyy(k), uh.dyz(k), uh.dxz(k), uh.dyz(k), uh.dzz(k);
              s[2] += w(k) * (Hh - covariant_hessian_of_ambient(D, g, n, W[k])).squaredNorm();
            }
          }
        }
      });
  ErrorNorms r;
  r.l2 = std::sqrt(sums[0]);
  if (grad) r.h1 = std::sqrt(sums[1]);
  if (hess) r.h2 = std::sqrt(sums[2]);
  return r;
}

}  // namespace iga
