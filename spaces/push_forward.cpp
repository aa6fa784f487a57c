#include "spaces/push_forward.hpp"

#include <Eigen/LU>  // Matrix2d::inverse

namespace iga {

void push_forward(const std::vector<GeometryJet>& geometry, const ReferenceDerivatives& ref, unsigned flags,
                  PointValues& out) {
  const int q = static_cast<int>(geometry.size());
  const bool grads = (flags & (update_gradients | update_hessians)) != 0;
  const bool hess = (flags & update_hessians) != 0;
  const int n = static_cast<int>((flags & update_values) ? ref.value.rows() : ref.dxi.rows());
  out.x.resize(2, q);
  out.jacobian.resize(q);
  if (flags & update_values) out.value = ref.value;
  if (grads) {
    out.dx.resize(n, q);
    out.dy.resize(n, q);
  }
  if (hess) {
    out.dxx.resize(n, q);
    out.dxy.resize(n, q);
    out.dyy.resize(n, q);
  }
  for (int k = 0; k < q; ++k) {
    const GeometryJet& g = geometry[k];
    out.x.col(k) = g.x;
    out.jacobian[k] = g.jacobian;
    if (!grads) continue;
    // G = J^{-1}; grad_x N = G^T grad_xi N.
    const Eigen::Matrix2d G = g.jacobian.inverse();
    const double g00 = G(0, 0), g01 = G(0, 1), g10 = G(1, 0), g11 = G(1, 1);
    out.dx.col(k) = g00 * ref.dxi.col(k) + g10 * ref.deta.col(k);
    out.dy.col(k) = g01 * ref.dxi.col(k) + g11 * ref.deta.col(k);
    if (!hess) continue;
    // H_xi N = J^T H_x N J + sum_m (d N / d x_m) H_xi x_m, so
    // H_x N = G^T (H_xi N - N_x H_xi x - N_y H_xi y) G.
    const Eigen::Matrix2d& hx = g.hessian_x;
    const Eigen::Matrix2d& hy = g.hessian_y;
    for (int i = 0; i < n; ++i) {
      const double nx = out.dx(i, k), ny = out.dy(i, k);
      const double a = ref.dxixi(i, k) - nx * hx(0, 0) - ny * hy(0, 0);
      const double b = ref.dxieta(i, k) - nx * hx(0, 1) - ny * hy(0, 1);
      const double c = ref.detaeta(i, k) - nx * hx(1, 1) - ny * hy(1, 1);
      // (G^T M G)(r, s) = sum_kl G(k, r) M(k, l) G(l, s) with M = [[a, b], [b, c]].
      out.dxx(i, k) = g00 * g00 * a + 2 * g00 * g10 * b + g10 * g10 * c;
      out.dxy(i, k) = g00 * g01 * a + (g00 * g11 + g10 * g01) * b + g10 * g11 * c;
      out.dyy(i, k) = g01 * g01 * a + 2 * g01 * g11 * b + g11 * g11 * c;
    }
  }
}

void extract_reference_derivatives(const Eigen::SparseMatrix<double>& extraction, const Eigen::MatrixXd (&tables)[6],
                                   unsigned flags, ReferenceDerivatives& ref) {
  const auto ct = extraction.transpose();
  if (flags & update_values) ref.value = ct * tables[0];
  if (flags & (update_gradients | update_hessians)) {
    ref.dxi = ct * tables[1];
    ref.deta = ct * tables[2];
  }
  if (flags & update_hessians) {
    ref.dxixi = ct * tables[3];
    ref.dxieta = ct * tables[4];
    ref.detaeta = ct * tables[5];
  }
}

}  // namespace iga
