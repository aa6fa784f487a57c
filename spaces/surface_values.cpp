#include "spaces/surface_values.hpp"

#include <Eigen/Geometry>  // cross
#include <Eigen/LU>        // Matrix2d::inverse

namespace iga {

double surface_measure(const Eigen::Matrix<double, 3, 2>& jacobian) {
  return jacobian.col(0).cross(jacobian.col(1)).norm();
}

double mean_curvature(const Eigen::Matrix<double, 3, 2>& jacobian, const Eigen::Matrix2d& second_form) {
  const Eigen::Matrix2d G = jacobian.transpose() * jacobian;
  return -(G.inverse() * second_form).trace();
}

void complete_surface_gradients(const Eigen::MatrixXd& dxi, const Eigen::MatrixXd& deta, PointValues& out) {
  const int n = static_cast<int>(dxi.rows()), q = static_cast<int>(dxi.cols());
  out.dx.resize(n, q);
  out.dy.resize(n, q);
  out.dz.resize(n, q);
  for (int k = 0; k < q; ++k) {
    const Eigen::Matrix<double, 3, 2>& J = out.jacobian3[k];
    // ∇_Γφ = J G⁻¹ ∇̂φ: one 3×2 matrix per point, applied to the n reference gradients.
    const Eigen::Matrix<double, 3, 2> M = J * (J.transpose() * J).inverse();
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d g = M.col(0) * dxi(i, k) + M.col(1) * deta(i, k);
      out.dx(i, k) = g.x();
      out.dy(i, k) = g.y();
      out.dz(i, k) = g.z();
    }
  }
}

}  // namespace iga
