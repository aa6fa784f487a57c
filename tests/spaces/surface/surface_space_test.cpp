// The C0 Bernstein space on G1 surfaces: DOF sharing, surface gradients, the area element, the
// sign of the mean curvature, and Laplace–Beltrami rates (docs/spaces/surface.md).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "assembly/assembler.hpp"
#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/rsd/surface_measures.hpp"
#include "spaces/element_values.hpp"
#include "spaces/surface/surface_space.hpp"
#include "spaces/surface_values.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

std::shared_ptr<const rsd::RsdSurface> surface_of(const TriangleSurfaceMesh& mesh) {
  return std::make_shared<const rsd::RsdSurface>(rsd::build_rsd_surface(mesh));
}

TEST(SurfaceSpace, DimensionCountsSharedLatticePoints) {
  // Closed surface: V + E (N − 1) + T (N − 1)(N − 2)/2 with N = m p lattice intervals per edge.
  const auto oct = surface_of(regular_octahedron());  // V = 6, E = 12, T = 8
  for (int p : {1, 2, 3, 5})
    for (int m : {1, 2, 4}) {
      const SurfaceBernsteinSpace space(oct, p, m);
      const int N = m * p;
      EXPECT_EQ(space.dimension(), 6 + 12 * (N - 1) + 8 * (N - 1) * (N - 2) / 2) << "p " << p << " m " << m;
      EXPECT_EQ(space.num_elements(), 8 * m * m);
      EXPECT_TRUE(space.boundary_edges("all").empty());
    }
}

TEST(SurfaceSpace, SurfaceGradientOfALinearFunctionIsTheProjectedGradient) {
  // φ = a·F on an element has reference gradient (a·F_ξ, a·F_η); its surface gradient must be
  // a − (a·n) n, the projection of the ambient gradient onto the tangent plane.
  const SurfaceBernsteinSpace space(surface_of(perturbed_octahedron()), 3, 2);
  const Eigen::Vector3d a(0.3, -1.2, 0.7);
  ElementValues ev(space, update_values);
  const RulePtr rule = space.quadrature(0, 6);
  for (int e = 0; e < space.num_elements(); e += 5) {
    ev.reinit(e, *rule);
    PointValues pv = ev.values();
    const int q = pv.num_points();
    Eigen::MatrixXd dxi(1, q), deta(1, q);
    std::vector<SurfaceJet> jets;
    for (int k = 0; k < q; ++k) {
      dxi(0, k) = a.dot(pv.jacobian3[k].col(0));
      deta(0, k) = a.dot(pv.jacobian3[k].col(1));
      jets.push_back(surface_jet(pv.x3.col(k), pv.jacobian3[k]));
    }
    complete_surface_gradients(jets, dxi, deta, pv);
    for (int k = 0; k < q; ++k) {
      const Eigen::Vector3d n = pv.jacobian3[k].col(0).cross(pv.jacobian3[k].col(1)).normalized();
      const Eigen::Vector3d expected = a - a.dot(n) * n;
      EXPECT_NEAR((Eigen::Vector3d(pv.dx(0, k), pv.dy(0, k), pv.dz(0, k)) - expected).norm(), 0.0, 1e-13);
    }
  }
}

TEST(SurfaceSpace, MassOfOneIsTheSurfaceArea) {
  // 1 = Σ N_i (partition of unity), so 1ᵀ M 1 = ∫_Γ 1: the area of the geometry study, whatever
  // the subdivision (the sub-triangles tile the same patches).
  const auto sphere = surface_of(icosphere(1));
  const double area = rsd::area_and_volume(*sphere, 27).area;
  for (int m : {1, 2}) {
    const SurfaceBernsteinSpace space(sphere, 2, m);
    const SparseMatrix M = Assembler(space).matrix(BilinearForm::mass, 27);
    const Eigen::VectorXd one = Eigen::VectorXd::Ones(space.dimension());
    // m = 1: the same rule on the same patches (round-off); m = 2: the finer rule differs by the
    // quadrature error of the degree-27 rule on the rational integrand (~1e-9 measured, 1e-7 allowed).
    EXPECT_NEAR(one.dot(M * one), area, (m == 1 ? 1e-13 : 1e-7) * area) << "m " << m;
    // And the Laplace–Beltrami matrix annihilates constants.
    const SparseMatrix K = Assembler(space).matrix(BilinearForm::laplace, 8);
    EXPECT_LT((K * one).norm(), 1e-11);
  }
}

TEST(SurfaceSpace, MeanCurvatureIsTwoOnTheSphereWithTheOutwardNormal) {
  // H = div_Γ n: +2 on the unit sphere for the outward normal (the convention of
  // Δ_Γu = Δu − nᵀ∇²u n − H ∂_n u). 
  const SurfaceBernsteinSpace space(surface_of(icosphere(2)), 2, 1);
  ElementValues ev(space, update_values | update_surface_curvature);
  const RulePtr rule = space.quadrature(0, 4);
  double lo = 1e9, hi = -1e9, integral = 0, area = 0;
  for (int e = 0; e < space.num_elements(); ++e) {
    ev.reinit(e, *rule);
    const PointValues& v = ev.values();
    for (int k = 0; k < v.num_points(); ++k) {
      const double outward = v.normal3.col(k).dot(v.x3.col(k)) > 0 ? 1.0 : -1.0;
      lo = std::min(lo, outward * v.mean_curvature(k));
      hi = std::max(hi, outward * v.mean_curvature(k));
      integral += outward * v.mean_curvature(k) * ev.jxw()(k);
      area += ev.jxw()(k);
    }
  }
  std::printf("H: min %.4f max %.4f mean %.6f\n", lo, hi, integral / area);
  // Pointwise the curvature of the interpolating surface is only O(1)-close (normals are O(h));
  // its mean is near 2 (1.89 measured at level 2), and its sign is that of the outward normal
  // everywhere. That H is the constructed surface's own curvature is checked by the rates below: a
  // wrong H gives a wrong source and an error that stalls.
  EXPECT_GT(lo, 1.0);
  EXPECT_LT(hi, 3.0);
  EXPECT_NEAR(integral / area, 2.0, 0.2);
}

std::string sphere_yaml(const std::string& mesh, int p, const std::string& problem) {
  return "problem: {pde: laplace_beltrami, " + problem + "}\ndomain: {type: surface, mesh: " + mesh +
         "}\nspace: {type: surface, degree: " + std::to_string(p) + "}\n";
}

TEST(SurfaceLaplaceBeltrami, SphericalHarmonicOnTheConstructedSurfaceHasItsEigenvalueSign) {
  // u = xy + x: with the source from the surface's own curvature the discrete solution converges
  // to u; a sign error in H or in the normal term would leave an O(1) error.
  const std::string yaml = sphere_yaml("icosphere, level: 1", 2, "exact: \"x*y + x\"");
  const test::Rates r = test::last_rates(yaml, 3);
  EXPECT_GT(r.l2, 2.5);
  EXPECT_GT(r.h1, 1.6);
}

TEST(SurfaceLaplaceBeltrami, OptimalRatesOnTheOctahedronSurface) {
  // Case (a): the surface is the exact geometry; rates p + 1 in L2 and p in H1.
  const std::string u = "exact: \"x*y + sin(z) + x\"";
  const test::Rates r2 = test::last_rates(sphere_yaml("octahedron", 2, u), 5);
  EXPECT_NEAR(r2.l2, 3.0, 0.25);
  EXPECT_NEAR(r2.h1, 2.0, 0.15);
  const test::Rates r4 = test::last_rates(sphere_yaml("octahedron", 4, u), 4);
  EXPECT_NEAR(r4.l2, 5.0, 0.3);
  EXPECT_NEAR(r4.h1, 4.0, 0.2);
}

TEST(SurfaceLaplaceBeltrami, OptimalRatesOnTheIcosphereSurface) {
  const std::string u = "exact: \"x*y + sin(z) + x\"";
  const test::Rates r2 = test::last_rates(sphere_yaml("icosphere, level: 1", 2, u), 4);
  EXPECT_NEAR(r2.l2, 3.0, 0.6);
  EXPECT_NEAR(r2.h1, 2.0, 0.15);
}

}  // namespace
}  // namespace iga

namespace iga {
namespace {

TEST(SurfaceLaplaceBeltrami, ZeroMeanProblemWithoutReaction) {
  // −Δ_Γu = f: unique up to constants; shifted to the exact solution's mean, the rates are optimal.
  const std::string yaml = R"(
problem: {pde: laplace_beltrami, exact: "x*y + sin(z) + x", reaction: 0}
domain: {type: surface, mesh: octahedron}
space: {type: surface, degree: 2}
)";
  const test::Rates r = test::last_rates(yaml, 5);
  EXPECT_NEAR(r.l2, 3.0, 0.25);
  EXPECT_NEAR(r.h1, 2.0, 0.15);
}

}  // namespace
}  // namespace iga
