// geometry/surface_jet and the covariant Hessians of spaces/surface_values on analytic maps whose
// geometry is known in closed form: the unit sphere in spherical coordinates (H = 2, K = 1 with
// the outward normal) and the torus of radii R = 2, r = 1 (H = 1/r + cos v/(R + r cos v),
// K = cos v/(r (R + r cos v))). For a linear function u = a·x, ∇_Γ∇_Γu = −(a·n) (shape operator
// in ambient coordinates), which on the unit sphere is −(a·n) P, and Δ_Γu = −H a·n.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "geometry/surface_jet.hpp"
#include "spaces/surface_values.hpp"

namespace iga {
namespace {

struct MapPoint {
  Eigen::Vector3d x;
  Eigen::Matrix<double, 3, 2> J;
  std::array<Eigen::Vector3d, 3> second;  // x_ξξ, x_ξη, x_ηη
};

MapPoint sphere(double t, double p) {  // ξ = θ (polar), η = φ
  MapPoint m;
  const double st = std::sin(t), ct = std::cos(t), sp = std::sin(p), cp = std::cos(p);
  m.x << st * cp, st * sp, ct;
  m.J.col(0) << ct * cp, ct * sp, -st;
  m.J.col(1) << -st * sp, st * cp, 0;
  m.second = {-m.x, Eigen::Vector3d(-ct * sp, ct * cp, 0), Eigen::Vector3d(-st * cp, -st * sp, 0)};
  return m;
}

MapPoint torus(double u, double v, double R = 2, double r = 1) {
  MapPoint m;
  const double su = std::sin(u), cu = std::cos(u), sv = std::sin(v), cv = std::cos(v), rho = R + r * cv;
  m.x << rho * cu, rho * su, r * sv;
  m.J.col(0) << -rho * su, rho * cu, 0;
  m.J.col(1) << -r * sv * cu, -r * sv * su, r * cv;
  m.second = {Eigen::Vector3d(-rho * cu, -rho * su, 0), Eigen::Vector3d(r * sv * su, -r * sv * cu, 0),
              Eigen::Vector3d(-r * cv * cu, -r * cv * su, -r * sv)};
  return m;
}

/// The covariant Hessian of u = a·x at the jet's point, through complete_surface_hessians.
Eigen::Matrix3d hessian_of_linear(const SurfaceJet& jet, const Eigen::Vector3d& a) {
  Eigen::MatrixXd dxi(1, 1), deta(1, 1), dxixi(1, 1), dxieta(1, 1), detaeta(1, 1);
  dxi(0, 0) = a.dot(jet.jacobian.col(0));
  deta(0, 0) = a.dot(jet.jacobian.col(1));
  dxixi(0, 0) = a.dot(jet.second[0]);
  dxieta(0, 0) = a.dot(jet.second[1]);
  detaeta(0, 0) = a.dot(jet.second[2]);
  PointValues pv;
  const std::vector<SurfaceJet> jets = {jet};
  complete_surface_gradients(jets, dxi, deta, pv);
  complete_surface_hessians(jets, dxi, deta, {dxixi, dxieta, detaeta}, pv);
  return pv.hessian(0, 0);
}

const Eigen::Vector3d a(0.3, -1.1, 0.7);

TEST(SurfaceJet, UnitSphereHasMeanCurvatureTwoAndGaussCurvatureOne) {
  for (double t : {0.3, 1.1, 2.5})
    for (double p : {0.0, 1.7, 4.0}) {
      const MapPoint m = sphere(t, p);
      const SurfaceJet j = surface_jet(m.x, m.J, m.second);
      EXPECT_NEAR((j.normal - m.x).norm(), 0.0, 1e-15);  // outward
      EXPECT_NEAR(j.area, std::sin(t), 1e-15);
      EXPECT_NEAR(j.mean_curvature, 2.0, 1e-14);
      EXPECT_NEAR(j.gauss_curvature, 1.0, 1e-14);
      EXPECT_NEAR((j.shape_operator + Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-14);
      // ∇_Γ∇_Γ(a·x) = −(a·n) P on the unit sphere.
      const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - j.normal * j.normal.transpose();
      EXPECT_NEAR((hessian_of_linear(j, a) + a.dot(j.normal) * P).norm(), 0.0, 1e-14);
    }
}

TEST(SurfaceJet, TorusCurvaturesAndLaplaceBeltramiOfLinearFunctions) {
  const double R = 2, r = 1;
  for (double u : {0.2, 2.0, 5.1})
    for (double v : {0.0, 1.3, 3.0, 4.4}) {
      const MapPoint m = torus(u, v, R, r);
      const SurfaceJet j = surface_jet(m.x, m.J, m.second);
      const double rho = R + r * std::cos(v);
      EXPECT_NEAR(j.mean_curvature, 1 / r + std::cos(v) / rho, 1e-14);
      EXPECT_NEAR(j.gauss_curvature, std::cos(v) / (r * rho), 1e-14);
      const Eigen::Matrix3d H = hessian_of_linear(j, a);
      EXPECT_NEAR(H.trace(), -j.mean_curvature * a.dot(j.normal), 1e-14);  // Δ_Γ(a·x) = −H a·n
      EXPECT_NEAR((H * j.normal).norm(), 0.0, 1e-15);                       // tangential
      EXPECT_NEAR((H - H.transpose()).norm(), 0.0, 1e-15);
      // Along the principal directions (the parameter lines of the torus): −(a·n) κ_i.
      const Eigen::Vector3d e_u = m.J.col(0).normalized(), e_v = m.J.col(1).normalized();
      EXPECT_NEAR(e_u.dot(H * e_u), -a.dot(j.normal) * std::cos(v) / rho, 1e-14);
      EXPECT_NEAR(e_v.dot(H * e_v), -a.dot(j.normal) / r, 1e-14);
      EXPECT_NEAR(e_u.dot(H * e_v), 0.0, 1e-14);
    }
}

}  // namespace
}  // namespace iga
