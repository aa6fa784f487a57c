#include "spaces/ws4/ws4_reference_matrices.hpp"

#include <Eigen/LU>
#include <cmath>

#include "spaces/ws4/ws4_basis.hpp"

namespace iga::ws4 {

namespace {

/// Index in {ξξ, ξη, ηη} of the second derivative ∂_a ∂_b.
int hessian_index(int a, int b) { return a + b; }

Ws4ReferenceMatrices build() {
  const Ws4Basis& basis = Ws4Basis::reference();
  const QuadratureRule rule = basis.split().composite_rule(8);
  ReferenceDerivatives t;
  basis.tabulate(rule.points, t);
  const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), rule.size());
  const Eigen::MatrixXd* d1[2] = {&t.dxi, &t.deta};
  const Eigen::MatrixXd* d2[3] = {&t.dxixi, &t.dxieta, &t.detaeta};
  Ws4ReferenceMatrices m;
  m.mass = t.value * w.asDiagonal() * t.value.transpose();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) m.grad[a][b] = *d1[a] * w.asDiagonal() * d1[b]->transpose();
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) m.hess[p][q] = *d2[p] * w.asDiagonal() * d2[q]->transpose();
  return m;
}

}  // namespace

const Ws4ReferenceMatrices& Ws4ReferenceMatrices::get() {
  static const Ws4ReferenceMatrices m = build();
  return m;
}

Eigen::MatrixXd ws4_form_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian) {
  const Ws4ReferenceMatrices& r = Ws4ReferenceMatrices::get();
  const double det = std::abs(jacobian.determinant());
  // ∇_x = J^{-T} ∇_ξ and H_x = J^{-T} H_ξ J^{-1}; G = J^{-1} J^{-T} collects the metric.
  const Eigen::Matrix2d jinv = jacobian.inverse();
  const Eigen::Matrix2d g = jinv * jinv.transpose();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(Ws4Basis::size, Ws4Basis::size);
  switch (form) {
    case BilinearForm::mass:
      k = det * r.mass;
      break;
    case BilinearForm::laplace:
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) k += (det * g(a, b)) * r.grad[a][b];
      break;
    case BilinearForm::bilaplace: {
      // Δ_x B = Σ_ab G_ab ∂_ab B = G_00 ∂ξξ + 2 G_01 ∂ξη + G_11 ∂ηη.
      const double alpha[3] = {g(0, 0), 2 * g(0, 1), g(1, 1)};
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) k += (det * alpha[p] * alpha[q]) * r.hess[p][q];
      break;
    }
    case BilinearForm::hessian:
      // H_x(B_i) : H_x(B_j) = Σ_abcd G_ac G_bd ∂_ab B_i ∂_cd B_j.
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          for (int c = 0; c < 2; ++c)
            for (int d = 0; d < 2; ++d)
              k += (det * g(a, c) * g(b, d)) * r.hess[hessian_index(a, b)][hessian_index(c, d)];
      break;
  }
  return k;
}

}  // namespace iga::ws4
