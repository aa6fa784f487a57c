// Simply supported boundaries of the surface biharmonic (problem.boundary: {all: simply_supported}):
// u imposed on the boundary curve, Δ_Γu natural. With a given source the load gains ∫ Δ_Γu ∂_ν v ds
// (assembly/surface_conormal_load.hpp); with the load a(u, ·) the natural condition is already in
// it. Graph surfaces (through the planar space), open 4-split surfaces, and C0 interior penalty
// spaces, which need no boundary edge terms for it.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/gismo_surface_example.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(SurfaceSimplySupported, GismoSecondConditionsAreExactUpToQuadrature) {
  // G+Smo's biharmonic_surface_example with "second" conditions: u = z on z = x² − y² over
  // [−0.5, 0.5]², c = 0, its source f = Δ_Γ²z applied pointwise, u and Δ_Γu = −8(x² − y²)/(1 + 4x² +
  // 4y²)² on the boundary. u ∘ X = x² − y² lies in the cubic space, so only the quadrature of the
  // rational f is left: L2 1.3e−6, 2.7e−9, 1.9e−12 at levels 0–2. Without the boundary term
  // ∫ Δ_Γu ∂_ν v the error stays at 2.0e−3 (L2) and 0.20 (H2) on every level.
  const std::string yaml =
      "problem:\n"
      "  pde: surface_biharmonic\n"
      "  exact: \"z\"\n"
      "  source: \"" + std::string(test::kGismoSurfaceSource) + "\"\n"
      "  reaction: 0\n"
      "  boundary: {all: simply_supported}\n"
      "domain: {type: graph, height: \"x^2 - y^2\", over: {type: rectangle, min: [-0.5, -0.5], max: [0.5, 0.5]}}\n"
      "space: {type: bspline, degree: 3, regularity: 2, elements: [2, 2]}\n";
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  const LevelResult r = solve_problem(*test::space_from_yaml(yaml, 2), problem, SolverKind::cholmod).result;
  EXPECT_LT(*r.l2, 1e-10);
  EXPECT_LT(*r.h1, 1e-9);
  EXPECT_LT(*r.h2, 1e-7);
}

TEST(SurfaceSimplySupported, LiftedBsplinesConvergeAtTheirRates) {
  // Cubic C2 B-splines on z = (x² + y²)/2 over the unit square, u = sin(2x + z) cos(y), c = 1, the
  // load a(u, ·): expected 4 / 3 / 2; levels 0–3 measured 4.02 / 3.01 / 2.02. (On z = x² − y² the
  // corner (1, 1) of the surface has an interior angle of 143°, and there L2 converges at 3.3 only,
  // for the C0 interior penalty form as well: with Navier conditions the dual problem is singular
  // at corners beyond 90°. The corners here are 90°, 90°, 90° and 60°.)
  const test::Rates r = test::last_rates(
      "problem: {pde: surface_biharmonic, exact: \"sin(2*x + z)*cos(y)\", boundary: {all: simply_supported}}\n"
      "domain: {type: graph, height: \"0.5*(x^2 + y^2)\", over: {type: rectangle, min: [0, 0], max: [1, 1]}}\n"
      "space: {type: bspline, degree: 3, elements: [2, 2]}\n",
      4);
  test::expect_rates(r, 4.0, 3.0, 2.0);
}

TEST(SurfaceSimplySupported, C0InteriorPenaltyNeedsNoBoundaryTerms) {
  // C0 cubic T-mesh splines on the same paraboloid: the interior penalty form with u imposed and
  // nothing on the boundary edges (Δ_Γu is natural). Expected 4 / 3 / 2; levels 0–2 measured
  // 3.96 / 2.96 / 2.03.
  const test::Rates r = test::last_rates(
      "problem: {pde: surface_biharmonic, exact: \"sin(2*x + z)*cos(y)\", boundary: {all: simply_supported}}\n"
      "domain: {type: graph, height: \"0.5*(x^2 + y^2)\", over: {type: rectangle, min: [0, 0], max: [1, 1]}}\n"
      "space: {type: tmesh, section: poly, n: 3, regularity: 0, elements: [2, 2]}\n",
      3);
  test::expect_rates(r, 4.0, 3.0, 2.0);
}

TEST(SurfaceSimplySupported, OpenFourSplitSurfaceReproducesALinearFunction) {
  // The 4-split surface is isoparametric: u = x + 2y − z + 5 is in the space, and with u imposed
  // on the boundary curve (boundary L2 projection, no conormal datum) and c = 0 it is the Galerkin
  // solution. Measured L2 1.3e−12, H1 1.7e−12, H2 1.5e−11 on the open cube, level 0.
  const std::string yaml =
      "problem: {pde: surface_biharmonic, exact: \"x + 2*y - z + 5\", reaction: 0, boundary: {all: simply_supported}}\n"
      "domain: {type: surface, mesh: open_cube}\n"
      "space: {type: g1_4split, degree: 5}\n";
  test::expect_errors_below(test::level_result(yaml, 0), 1e-10, 1e-10, 1e-9);
}

}  // namespace
}  // namespace iga
