#include "geometry/surface_jet.hpp"

#include <Eigen/Geometry>  // cross
#include <Eigen/LU>        // Matrix2d::inverse

namespace iga {

Eigen::Vector3d unit_normal(const Eigen::Vector3d& x_xi, const Eigen::Vector3d& x_eta) {
  return x_xi.cross(x_eta).normalized();
}

double area_element(const Eigen::Vector3d& x_xi, const Eigen::Vector3d& x_eta) { return x_xi.cross(x_eta).norm(); }

SurfaceJet surface_jet(const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian) {
  SurfaceJet j;
  j.x = x;
  j.jacobian = jacobian;
  j.metric = jacobian.transpose() * jacobian;
  j.metric_inverse = j.metric.inverse();
  j.dual = jacobian * j.metric_inverse;
  const Eigen::Vector3d c = jacobian.col(0).cross(jacobian.col(1));
  j.area = c.norm();
  j.normal = c.normalized();
  return j;
}

SurfaceJet surface_jet(const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian,
                       const std::array<Eigen::Vector3d, 3>& second) {
  SurfaceJet j = surface_jet(x, jacobian);
  j.has_second = true;
  j.second = second;
  const double b01 = second[1].dot(j.normal);
  j.second_form << second[0].dot(j.normal), b01, b01, second[2].dot(j.normal);
  j.shape_operator = j.metric.inverse() * j.second_form;
  j.mean_curvature = -j.shape_operator.trace();
  j.gauss_curvature = j.second_form.determinant() / j.metric.determinant();
  return j;
}

}  // namespace iga
