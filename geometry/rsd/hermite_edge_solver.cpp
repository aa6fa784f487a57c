#include "geometry/rsd/hermite_edge_solver.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace iga::rsd {

namespace {

Eigen::Vector3d as_eigen(const Vec3<double>& x) { return {x[0], x[1], x[2]}; }

/// Least-squares solution of a·x + b·y = r and its relative residual.
Eigen::Vector2d solve_in_plane(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& r,
                               double& residual) {
  Eigen::Matrix<double, 3, 2> A;
  A << a, b;
  const Eigen::Vector2d xy = A.colPivHouseholderQr().solve(r);
  const double scale = std::max({r.norm(), a.norm() * std::abs(xy[0]), b.norm() * std::abs(xy[1])});
  residual = scale > 0 ? (A * xy - r).norm() / scale : 0.0;
  return xy;
}

Poly<double> smoothstep_blend(double at0, double at1) {
  // at0 + (at1 − at0)(3t² − 2t³)
  return Poly<double>(std::vector<double>{at0, 0.0, 3 * (at1 - at0), -2 * (at1 - at0)});
}

double max_coefficient(const Poly<double>& p) {
  double m = 0;
  for (double x : p.c) m = std::max(m, std::abs(x));
  return m;
}

double max_coefficient(const VecPoly<double>& p) {
  return std::max({max_coefficient(p[0]), max_coefficient(p[1]), max_coefficient(p[2])});
}

}  // namespace

Poly<double> HermiteEdgeSolution::X() const { return smoothstep_blend(X0, X1); }
Poly<double> HermiteEdgeSolution::Y() const { return smoothstep_blend(Y0, Y1); }

double delta_division_remainder(const EdgeCurves<double>& curves) {
  const Poly<double> delta = curves.Delta();
  const auto [q, r] = divide(delta, edge_bubble<double>());
  const double scale = max_coefficient(curves.v) * max_coefficient(curves.w());
  return scale > 0 ? max_coefficient(r) / scale : 0.0;
}

HermiteEdgeSolution solve_edge_hermite(RsdTuple tuple, const EdgeEndData<double>& e) {
  HermiteEdgeSolution s;
  const Eigen::Vector3d g_ij = as_eigen(e.g_ij), g_ji = as_eigen(e.g_ji);
  // t = 0 (p_j): X0·g_ji + Y0·(g_jk̄ − g_jk) = g_jk − ½ g_ji
  const Eigen::Vector2d at0 = solve_in_plane(g_ji, as_eigen(e.g_jkbar) - as_eigen(e.g_jk),
                                             as_eigen(e.g_jk) - 0.5 * g_ji, s.residual0);
  // t = 1 (p_i): −X1·g_ij + Y1·(g_ik̄ − g_ik) = g_ik − ½ g_ij
  const Eigen::Vector2d at1 = solve_in_plane(-g_ij, as_eigen(e.g_ikbar) - as_eigen(e.g_ik),
                                             as_eigen(e.g_ik) - 0.5 * g_ij, s.residual1);
  s.X0 = at0[0];
  s.Y0 = at0[1];
  s.X1 = at1[0];
  s.Y1 = at1[1];

  const EdgeCurves<double> curves = edge_curves(tuple, e);
  const VecPoly<double> d = curves.d(), w = curves.w();
  // Already G1 (e.g. planar or affine data): keep f, so that affine reproduction stays exact.
  if (max_coefficient(curves.Delta()) <= 1e-14 * max_coefficient(curves.v) * max_coefficient(w) ||
      max_coefficient(w) == 0) {
    s.already_g1 = true;
    s.z = {};
    return s;
  }
  const VecPoly<double> r = curves.v - s.X() * curves.u - s.Y() * d;
  double remainder = 0;
  for (int k = 0; k < 3; ++k) {
    auto [q, rem] = divide(r[k], edge_bubble<double>());
    s.z[k] = q;
    remainder = std::max(remainder, max_coefficient(rem));
  }
  const double scale = max_coefficient(r);
  s.division_remainder = scale > 0 ? remainder / scale : 0.0;
  return s;
}

}  // namespace iga::rsd
