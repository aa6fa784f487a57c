// Mixed boundary parts of the surface biharmonic: problem.boundary: {left: clamped, bottom: clamped,
// right: simply_supported, top: simply_supported}. u on every edge, ∂_ν u on the clamped ones, Δ_Γu
// natural on the simply supported ones (a given source gains ∫ Δ_Γu ∂_ν v over those edges only).
// Graph surfaces through their planar space, other open surfaces (a NURBS cylinder closed around its
// axis) through the surface's own conormal. docs/surface-biharmonic.md#mixed-boundary-parts.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/gismo_surface_example.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const std::string kMixed = "{left: clamped, bottom: clamped, right: simply_supported, top: simply_supported}";

std::string paraboloid(const std::string& boundary, const std::string& space) {
  return "problem: {pde: surface_biharmonic, exact: \"sin(2*x + z)*cos(y)\", boundary: " + boundary + "}\n"
         "domain: {type: graph, height: \"0.5*(x^2 + y^2)\", over: {type: rectangle, min: [0, 0], max: [1, 1]}}\n"
         "space: " + space + "\n";
}

int free_functions(const std::string& yaml, int level) {
  const SpacePtr space = test::space_from_yaml(yaml, level);
  return static_cast<int>(make_formulation(*space, test::problem_from_yaml(yaml))->constraints().free.size());
}

TEST(SurfaceMixedBoundary, ClampedSidesFixTwoLayersSimplySupportedOne) {
  // Cubic B-splines on 4 × 4 elements: n = 7 functions per direction. A clamped side fixes the two
  // layers of functions its values and normal derivatives see, a simply supported side one: free
  // (n − 4)² all clamped, (n − 2)² all simply supported, (n − 3)² with two sides of each kind.
  const std::string space = "{type: bspline, degree: 3, elements: [2, 2]}";
  const int n = 7;
  EXPECT_EQ(free_functions(paraboloid("{all: clamped}", space), 1), (n - 4) * (n - 4));
  EXPECT_EQ(free_functions(paraboloid("{all: simply_supported}", space), 1), (n - 2) * (n - 2));
  EXPECT_EQ(free_functions(paraboloid(kMixed, space), 1), (n - 3) * (n - 3));
  // "all" first, named parts override it: the same split.
  EXPECT_EQ(free_functions(paraboloid("{all: clamped, right: simply_supported, top: simply_supported}", space), 1),
            (n - 3) * (n - 3));
  // Not a lift: a cylinder of radius 1 about the x axis, periodic around it with 8 cubic elements,
  // C2 except C1 at the 4 joints of the exact circle (8 + 4 = 12 functions per ring), 2 elements
  // along it (5 rings); clamped at x = 0 (bottom), simply supported at x = 2 (top): 12 · (5 − 3) free.
  const std::string cylinder =
      "problem: {pde: surface_biharmonic, exact: \"sin(x)*cos(y) + x*z\", "
      "boundary: {bottom: clamped, top: simply_supported}}\n"
      "domain: {type: surface_patch, shape: cylinder, radius: 1, length: 2}\n"
      "space: {type: bspline, degree: 3, elements: [8, 2]}\n";
  EXPECT_EQ(free_functions(cylinder, 0), 12 * (5 - 3));
}

TEST(SurfaceMixedBoundary, NaturalConditionOnlyOnTheSimplySupportedSides) {
  // G+Smo's biharmonic_surface_example data (u = z on z = x² − y² over [−0.5, 0.5]², c = 0, its
  // source f = Δ_Γ²z applied pointwise), clamped on two sides and simply supported on two: u ∘ X
  // = x² − y² is in the cubic space, so the solution is z up to the quadrature of the rational f
  // (measured L2 1.9e−12, H2 8.6e−10 at level 2) when the simply supported sides get ∫ Δ_Γz ∂_ν v;
  // without that term L2 2.0e−3, H2 0.15 (checked by removing it).
  const std::string yaml =
      "problem:\n"
      "  pde: surface_biharmonic\n"
      "  exact: \"z\"\n"
      "  source: \"" + std::string(test::kGismoSurfaceSource) + "\"\n"
      "  reaction: 0\n"
      "  boundary: " + kMixed + "\n"
      "domain: {type: graph, height: \"x^2 - y^2\", over: {type: rectangle, min: [-0.5, -0.5], max: [0.5, 0.5]}}\n"
      "space: {type: bspline, degree: 3, regularity: 2, elements: [2, 2]}\n";
  test::expect_errors_below(test::level_result(yaml, 2), 1e-10, 1e-9, 1e-7);
}

TEST(SurfaceMixedBoundary, G1SpacesReproduceAQuadraticLiftAcrossTheMixedCorners) {
  // u = x + 2y − 3z + 5 on the paraboloid: u ∘ X is quadratic, in every planar space below, and the
  // Galerkin solution with c = 0 whatever the parts: the mixed corners' least-squares fit must
  // not spoil it where the G1 vertex functions carry derivative data (and dependent traces get a
  // basis change). Measured at level 0: g1 L2 1.5e−13, H2 2.0e−11; g1_4split L2 5.1e−14, H2 5.8e−11.
  for (const std::string block : {"space: {type: g1, degree: 5}\n"
                                   "domain: {type: graph, height: \"0.5*(x^2 + y^2)\", over: {type: multipatch, name: 3p_square}}\n",
                                   "space: {type: g1_4split, degree: 4}\n"
                                   "domain: {type: graph, height: \"0.5*(x^2 + y^2)\", over: {type: multipatch, name: grid2x2}}\n"}) {
    SCOPED_TRACE(block);
    const std::string yaml =
        "problem: {pde: surface_biharmonic, exact: \"x + 2*y - 3*z + 5\", reaction: 0, boundary: " + kMixed + "}\n" + block;
    test::expect_errors_below(test::level_result(yaml, 0), 1e-10, 1e-9, 1e-8);
  }
}

TEST(SurfaceMixedBoundary, LiftedSplinesConvergeAtTheirRates) {
  // u = sin(2x + z) cos(y) on the paraboloid, two clamped and two simply supported sides (two
  // corners join one of each), the load a(u, ·); expected 4 / 3 / 2. Measured, levels 2→3: cubic C2
  // B-splines 4.01 / 3.01 / 2.02, cubic C1 T-mesh splines 3.96 / 2.97 / 2.01.
  for (const std::string space :
       {"{type: bspline, degree: 3, elements: [2, 2]}", "{type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2]}"}) {
    SCOPED_TRACE(space);
    const test::Rates r = test::last_rates(paraboloid(kMixed, space), 4);
    test::expect_rates(r, 4.0, 3.0, 2.0);
  }
}

TEST(SurfaceMixedBoundary, CylinderClampedAtOneEndSimplySupportedAtTheOther) {
  // Not a lift (periodic around the axis): u and ∂_ν u through the surface's own conormal on the
  // clamped circle, u only on the simply supported one. Cubic, expected 4 / 3 / 2; measured levels
  // 2→3: 4.14 / 3.09 / 2.04.
  const test::Rates r = test::last_rates(
      "problem: {pde: surface_biharmonic, exact: \"sin(x)*cos(y) + x*z\", "
      "boundary: {bottom: clamped, top: simply_supported}}\n"
      "domain: {type: surface_patch, shape: cylinder, radius: 1, length: 2}\n"
      "space: {type: bspline, degree: 3, elements: [8, 2]}\n",
      4);
  test::expect_rates(r, 4.0, 3.0, 2.0);
}

}  // namespace
}  // namespace iga
