#include "spaces/surface_values.hpp"

#include <Eigen/LU>  // Matrix2d::inverse
#include <stdexcept>

namespace iga {

double surface_measure(const Eigen::Matrix<double, 3, 2>& jacobian) {
  return area_element(jacobian.col(0), jacobian.col(1));
}

void take_surface_geometry(const std::vector<SurfaceJet>& jets, unsigned flags, PointValues& out) {
  const int q = static_cast<int>(jets.size());
  const bool curvature = flags & update_surface_curvature;
  out.x3.resize(3, q);
  out.jacobian3.resize(q);
  out.jacobian.clear();
  if (curvature) {
    out.normal3.resize(3, q);
    out.mean_curvature.resize(q);
  }
  for (int k = 0; k < q; ++k) {
    out.x3.col(k) = jets[k].x;
    out.jacobian3[k] = jets[k].jacobian;
    if (curvature) {
      out.normal3.col(k) = jets[k].normal;
      out.mean_curvature(k) = jets[k].mean_curvature;
    }
  }
  out.x = out.x3.topRows(2);
}

void complete_surface_gradients(const std::vector<SurfaceJet>& jets, const Eigen::MatrixXd& dxi,
                                const Eigen::MatrixXd& deta, PointValues& out) {
  const int n = static_cast<int>(dxi.rows()), q = static_cast<int>(dxi.cols());
  out.dx.resize(n, q);
  out.dy.resize(n, q);
  out.dz.resize(n, q);
  for (int k = 0; k < q; ++k) {
    // ∇_Γφ = J G⁻¹ ∇̂φ: one 3×2 matrix per point, applied to the n reference gradients.
    const Eigen::Matrix<double, 3, 2>& M = jets[k].dual;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d g = M.col(0) * dxi(i, k) + M.col(1) * deta(i, k);
      out.dx(i, k) = g.x();
      out.dy(i, k) = g.y();
      out.dz(i, k) = g.z();
    }
  }
}

void complete_surface_hessians(const std::vector<SurfaceJet>& jets, const Eigen::MatrixXd& dxi,
                               const Eigen::MatrixXd& deta, const ReferenceHessians& second, PointValues& out) {
  const int n = static_cast<int>(dxi.rows()), q = static_cast<int>(dxi.cols());
  Eigen::MatrixXd* const h[6] = {&out.dxx, &out.dxy, &out.dxz, &out.dyy, &out.dyz, &out.dzz};
  const int row[6] = {0, 0, 0, 1, 1, 2}, col[6] = {0, 1, 2, 1, 2, 2};
  for (Eigen::MatrixXd* m : h) m->resize(n, q);
  const Eigen::MatrixXd* const ref[3] = {&second.dxixi, &second.dxieta, &second.detaeta};
  for (int k = 0; k < q; ++k) {
    const SurfaceJet& jet = jets[k];
    if (!jet.has_second) throw std::logic_error("complete_surface_hessians: the jets need second derivatives");
    const Eigen::Matrix<double, 3, 2>& M = jet.dual;
    // H = M D Mᵀ = Σ_ab D_ab M_a M_bᵀ with D_ab = ∂_ab φ̂ − x_ab · ∇_Γφ and ∇_Γφ = M ∇̂φ: the three
    // symmetric products S_ab per point, then one axpy per component over the n functions.
    const Eigen::Matrix3d S[3] = {M.col(0) * M.col(0).transpose(),
                                  M.col(0) * M.col(1).transpose() + M.col(1) * M.col(0).transpose(),
                                  M.col(1) * M.col(1).transpose()};
    Eigen::VectorXd D[3];
    for (int ab = 0; ab < 3; ++ab) {
      const Eigen::Vector2d c = M.transpose() * jet.second[ab];  // Christoffel symbols Γ^k_ab
      D[ab] = ref[ab]->col(k) - c(0) * dxi.col(k) - c(1) * deta.col(k);
    }
    for (int t = 0; t < 6; ++t)
      h[t]->col(k) = S[0](row[t], col[t]) * D[0] + S[1](row[t], col[t]) * D[1] + S[2](row[t], col[t]) * D[2];
  }
}

}  // namespace iga
