#include "geometry/surface_jet.hpp"

#include <Eigen/Geometry>  // cross
#include <Eigen/LU>        // Matrix2d::inverse

namespace iga {

Eigen::Vector3d unit_normal(const Eigen::Vector3d& x_xi, const Eigen::Vector3d& x_eta) {
  return x_xi.cross(x_eta).normalized();
}

double area_element(const Eigen::Vector3d& x_xi, const Eigen::Vector3d& x_eta) { return x_xi.cross(x_eta).norm(); }

void fill_surface_jet(SurfaceJet& j, const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian,
                      const std::array<Eigen::Vector3d, 3>* second) {
  j.x = x;
  j.jacobian = jacobian;
  j.metric.noalias() = jacobian.transpose() * jacobian;
  j.metric_inverse = j.metric.inverse();
  j.dual.noalias() = jacobian * j.metric_inverse;
  const Eigen::Vector3d c = jacobian.col(0).cross(jacobian.col(1));
  j.area = c.norm();
  j.normal = c / j.area;
  j.has_second = second != nullptr;
  if (!second) return;
  j.second = *second;
  const double b01 = (*second)[1].dot(j.normal);
  j.second_form << (*second)[0].dot(j.normal), b01, b01, (*second)[2].dot(j.normal);
  j.shape_operator.noalias() = j.metric_inverse * j.second_form;
  j.mean_curvature = -j.shape_operator.trace();
  j.gauss_curvature = j.second_form.determinant() / j.metric.determinant();
}

SurfaceJet surface_jet(const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian) {
  SurfaceJet j;
  fill_surface_jet(j, x, jacobian);
  return j;
}

SurfaceJet surface_jet(const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian,
                       const std::array<Eigen::Vector3d, 3>& second) {
  SurfaceJet j;
  fill_surface_jet(j, x, jacobian, &second);
  return j;
}

}  // namespace iga
