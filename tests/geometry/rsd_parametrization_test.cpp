// How regular the RSD patches are as parametrisations (what finite elements on them see): the
// in-plane part of the patch's second derivative along its edge directions, relative to h. A
// regular family of maps (Ciarlet–Raviart) has it O(h²), i.e. the ratio ∝ h; Π0, without linear
// precision, keeps an in-plane distortion of the patch's own size on every mesh (the ratio stays
// near 4.9), so the H2 approximation of polynomials in its parameters does not improve with the
// base mesh (the C0 interior penalty form on Π0 surfaces gave errors of the size of u:
// docs/surface-biharmonic.md). The Hermite G1 correction is not the cause: without it (method
// none) the numbers are the same.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/rsd/bezier_jet.hpp"
#include "geometry/rsd/rsd_surface.hpp"

namespace iga::rsd {
namespace {

/// max over patches and sample points of |in-plane part of ∂²F/∂e²| / h, e the three edge
/// directions of the patch's mesh triangle (dt = e_a − e_b in barycentrics), "in-plane" the part in
/// the flat triangle's plane, h the longest mesh edge.
double in_plane_distortion(int icosphere_level, RsdTuple tuple, RsdMethod method) {
  const TriangleSurfaceMesh mesh = icosphere(icosphere_level);
  RsdOptions options;
  options.tuple = tuple;
  options.method = method;
  const RsdSurface s = build_rsd_surface(mesh, options);
  double h = 0, worst = 0;
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) h = std::max(h, (mesh.points[t[c]] - mesh.points[t[(c + 1) % 3]]).norm());
  for (int n = 0; n < mesh.num_triangles(); ++n) {
    const auto& tri = mesh.triangles[n];
    const Eigen::Vector3d normal =
        (mesh.points[tri[1]] - mesh.points[tri[0]]).cross(mesh.points[tri[2]] - mesh.points[tri[0]]).normalized();
    const int m = 8;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const BezierJet jet = bezier_jet(s.patches[n], Eigen::Vector3d(m - i - j, i, j) / m, true);
        for (const auto& [a, b] : {std::pair{1, 2}, std::pair{0, 1}, std::pair{0, 2}}) {
          const Eigen::Vector3d second = jet.dd[a][a] - 2 * jet.dd[a][b] + jet.dd[b][b];
          worst = std::max(worst, (second - second.dot(normal) * normal).norm() / h);
        }
      }
  }
  std::printf("icosphere %d  %s %-7s  max |F_ee in-plane| / h = %.3f\n", icosphere_level, tuple_name(tuple).c_str(),
              method_name(method).c_str(), worst);
  return worst;
}

TEST(RsdParametrization, Pi1IsRegularAndPi0KeepsItsInPlaneDistortion) {
  // Measured on icosphere levels 1, 2, 3 (h = 0.618, 0.325, 0.165):
  //   Π0 hermite 4.89, 4.87, 4.90; Π0 none 5.21, 5.00, 4.94; Π1 hermite 1.19, 0.33, 0.086.
  double pi1_previous = 0;
  for (int level = 1; level <= 3; ++level) {
    const double pi0 = in_plane_distortion(level, RsdTuple::pi0, RsdMethod::hermite);
    const double pi0_uncorrected = in_plane_distortion(level, RsdTuple::pi0, RsdMethod::none);
    const double pi1 = in_plane_distortion(level, RsdTuple::pi1, RsdMethod::hermite);
    EXPECT_GT(pi0, 4.0);              // does not shrink with h
    EXPECT_GT(pi0_uncorrected, 4.0);  // the RSD interpolant's, not the correction's
    // Π1: O(h³) in-plane second derivatives, ratio ∝ h² (h halves: factor 3.7 and 3.9 measured).
    if (level > 1) EXPECT_GT(pi1_previous / pi1, 3.0);
    pi1_previous = pi1;
  }
  EXPECT_LT(pi1_previous, 0.1);
}

}  // namespace
}  // namespace iga::rsd
