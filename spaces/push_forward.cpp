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

void extract_reference_derivatives(const Extraction& extraction, const LocalTables& tables, unsigned flags,
                                   ReferenceDerivatives& ref) {
  // Per point, a gather over each row's few nonzeros (10-15 % of a G1 extraction): the tables'
  // column of that point is a few hundred bytes, the output written in order. Eigen's product with
  // the transposed sparse matrix walks rows of column-major arrays instead, several times slower.
  const bool values = (flags & update_values) != 0;
  const bool grads = (flags & (update_gradients | update_hessians)) != 0;
  const bool hess = (flags & update_hessians) != 0;
  Eigen::MatrixXd* out[6] = {&ref.value, &ref.dxi, &ref.deta, &ref.dxixi, &ref.dxieta, &ref.detaeta};
  const bool wanted[6] = {values, grads, grads, hess, hess, hess};
  const Eigen::Index n = extraction.rows();
  const Eigen::Index q = tables[0].cols();
  const int* begin = extraction.outerIndexPtr();
  const int* row = extraction.innerIndexPtr();
  const double* value = extraction.valuePtr();
  for (int t = 0; t < 6; ++t) {
    if (!wanted[t]) continue;
    out[t]->resize(n, q);
    // Four points at a time: four independent sums per nonzero read (one sum alone waits on
    // its own additions).
    const Eigen::Index L = tables[t].rows();
    Eigen::Index k = 0;
    for (; k + 4 <= q; k += 4) {
      const double* table = tables[t].col(k).data();
      double* result = out[t]->col(k).data();
      for (Eigen::Index i = 0; i < n; ++i) {
        double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
        for (int nz = begin[i]; nz < begin[i + 1]; ++nz) {
          const double v = value[nz];
          const double* a = table + row[nz];
          s0 += v * a[0];
          s1 += v * a[L];
          s2 += v * a[2 * L];
          s3 += v * a[3 * L];
        }
        result[i] = s0;
        result[i + n] = s1;
        result[i + 2 * n] = s2;
        result[i + 3 * n] = s3;
      }
    }
    for (; k < q; ++k) {
      const double* table = tables[t].col(k).data();
      double* result = out[t]->col(k).data();
      for (Eigen::Index i = 0; i < n; ++i) {
        double sum = 0.0;
        for (int nz = begin[i]; nz < begin[i + 1]; ++nz) sum += value[nz] * table[row[nz]];
        result[i] = sum;
      }
    }
  }
}

void contract_local_derivatives(const LocalTables& tables, const Eigen::VectorXd& local, unsigned flags,
                                ReferenceDerivatives& one) {
  const bool grads = (flags & (update_gradients | update_hessians)) != 0;
  const bool hess = (flags & update_hessians) != 0;
  one.value.noalias() = local.transpose() * tables[0];  // push_forward of one function reads values
  if (grads) {
    one.dxi.noalias() = local.transpose() * tables[1];
    one.deta.noalias() = local.transpose() * tables[2];
  }
  if (hess) {
    one.dxixi.noalias() = local.transpose() * tables[3];
    one.dxieta.noalias() = local.transpose() * tables[4];
    one.detaeta.noalias() = local.transpose() * tables[5];
  }
}

void take_geometry(const std::vector<GeometryJet>& jets, PointValues& out) {
  const auto q = static_cast<Eigen::Index>(jets.size());
  out.x.resize(2, q);
  out.jacobian.resize(jets.size());
  for (Eigen::Index p = 0; p < q; ++p) {
    out.x.col(p) = jets[p].x;
    out.jacobian[p] = jets[p].jacobian;
  }
}

void take_single_function(const PointValues& single, unsigned flags, PointValues& geometry, FunctionValues& out) {
  geometry.x = single.x;
  geometry.jacobian = single.jacobian;
  geometry.x3 = single.x3;  // surfaces in 3D (empty in the plane)
  geometry.jacobian3 = single.jacobian3;
  geometry.normal3 = single.normal3;
  geometry.mean_curvature = single.mean_curvature;
  if (flags & update_values) out.value = single.value.row(0).transpose();
  if (flags & update_gradients) {
    out.dx = single.dx.row(0).transpose();
    out.dy = single.dy.row(0).transpose();
    if (single.dz.size() > 0) out.dz = single.dz.row(0).transpose();
  }
  if (flags & update_hessians) {
    out.dxx = single.dxx.row(0).transpose();
    out.dxy = single.dxy.row(0).transpose();
    out.dyy = single.dyy.row(0).transpose();
    if (single.dzz.size() > 0) {
      out.dxz = single.dxz.row(0).transpose();
      out.dyz = single.dyz.row(0).transpose();
      out.dzz = single.dzz.row(0).transpose();
    }
  }
}

}  // namespace iga
