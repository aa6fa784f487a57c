// Graph surfaces z = g(x, y) with a planar space lifted onto them (spaces/graph/): the evaluator
// against central differences (check_space), the surface biharmonic of G+Smo's
// biharmonic_surface_example (u = z on z = x² − y², clamped) with three planar C1 spaces.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "spaces/graph/graph_surface_space.hpp"
#include "tests/support/check_space.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const char* kHeight = "x^2 - y^2";

SpacePtr graph(const std::string& yaml, int level) {
  return std::make_shared<GraphSurfaceSpace>(test::space_from_yaml(yaml, level),
                                             SymbolicFunction::parse(kHeight, "test"), kHeight);
}

const char* kBspline = "domain: {type: rectangle, min: [0, 0], max: [1, 1]}\nspace: {type: bspline, degree: 3}\n";
const char* kWs4 = "domain: {type: unit_square}\nspace: {type: ws4}\n";
const char* kG1 = "domain: {type: multipatch, name: 3p_square}\nspace: {type: g1, degree: 5}\n";

TEST(GraphSurface, SurfaceDerivativesMatchDifferencesOfTheLift) {
  for (const char* yaml : {kBspline, kWs4, kG1}) {
    const SpacePtr s = graph(yaml, 1);
    ASSERT_EQ(s->ambient_dimension(), 3);
    const test::SpaceCheck c = test::check_space(*s, 3);
    std::printf("%s: gradient fd %.2e (h/2 %.2e), hessian fd %.2e (h/2 %.2e), gradient jump %.2e, f %.2e\n",
                s->type().c_str(), c.gradient_fd, c.gradient_fd_half, c.hessian_fd, c.hessian_fd_half,
                c.gradient_jump, c.function_values);
    // Central differences with step h = 1e-4: O(h²) relative to the derivatives' scale over an
    // element (measured 1e-8 … 2e-6); halving the step divides the difference by 4 when it is the
    // truncation, i.e. when the evaluator's derivatives are the derivatives.
    EXPECT_LT(c.gradient_fd, 1e-5);
    EXPECT_LT(c.hessian_fd, 1e-5);
    EXPECT_LT(c.gradient_fd_half, c.gradient_fd / 3);
    EXPECT_LT(c.hessian_fd_half, c.hessian_fd / 3);
    EXPECT_LT(c.function_values, 1e-12);
    EXPECT_LT(c.gradient_jump, 1e-9);  // C1 planar spaces stay C1 on the surface
  }
}

/// Levels 0..levels-1 of u = z on the graph, clamped; prints the table and returns the last rates.
test::Rates rates(const std::string& yaml, int levels, const std::string& exact) {
  const ProblemSpec problem =
      test::problem_from_yaml("problem: {pde: surface_biharmonic, exact: \"" + exact + "\"}");
  std::vector<LevelResult> rows;
  for (int level = 0; level < levels; ++level) {
    const SpacePtr s = graph(yaml, level);
    const auto start = std::chrono::steady_clock::now();
    rows.push_back(solve_problem(*s, problem, SolverKind::cholmod).result);
    const LevelResult& r = rows.back();
    std::printf("%s level %d dofs %d h %.4f  L2 %.3e H1 %.3e H2 %.3e  (%.1f s)\n", s->type().c_str(), level,
                s->dimension(), r.h, *r.l2, *r.h1, *r.h2,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::fflush(stdout);
  }
  const LevelResult &a = rows[levels - 2], &b = rows[levels - 1];
  return {*rate(a.l2, b.l2, a.h, b.h), *rate(a.h1, b.h1, a.h, b.h), *rate(a.h2, b.h2, a.h, b.h)};
}

TEST(GraphSurface, BiharmonicSurfaceExampleIsAPatchTest) {
  // G+Smo's biharmonic_surface_example: u = z on z = x² − y², clamped. Pulled back to the plane
  // u ∘ X = x² − y² lies in every planar space of degree ≥ 2, so the Galerkin solution is u and
  // every error is rounding: the load a(u, ·), the clamped data through the lift, the covariant
  // Hessians and the surface H2 norm (with its shape operator by differences) all at once.
  for (const char* yaml : {kBspline, kWs4, kG1}) {
    const ProblemSpec problem = test::problem_from_yaml("problem: {pde: surface_biharmonic, exact: \"z\"}");
    for (int level = 0; level < (yaml == kWs4 ? 1 : 2); ++level) {  // ws4: 3 s per level
      const SpacePtr s = graph(yaml, level);
      const LevelResult r = solve_problem(*s, problem, SolverKind::cholmod).result;
      std::printf("%s level %d dofs %d  L2 %.3e H1 %.3e H2 %.3e\n", s->type().c_str(), level, s->dimension(), *r.l2,
                  *r.h1, *r.h2);
      EXPECT_LT(*r.l2, 1e-12);
      EXPECT_LT(*r.h1, 1e-11);
      EXPECT_LT(*r.h2, 1e-8);
    }
  }
}

TEST(GraphSurface, OptimalRatesOfTheLiftedBsplineAndG1Spaces) {
  // u = sin(2x + z) cos(y) on z = x² − y², clamped; expected p + 1 / p / p − 1: bspline p = 3
  // (C2) 4 / 3 / 2, g1 k = 5 6 / 5 / 4, between the last two of five levels (1 s). The lifted
  // ws4 space converges too (docs/surface-biharmonic.md) but its level 3 takes minutes (the
  // shape operator's differences over its 342-piece rules), too long for the suite.
  const std::string u = "sin(2*x + z)*cos(y)";
  const test::Rates b = rates(kBspline, 5, u);
  EXPECT_NEAR(b.l2, 4.0, 0.3);
  EXPECT_NEAR(b.h1, 3.0, 0.3);
  EXPECT_NEAR(b.h2, 2.0, 0.3);
  const test::Rates g = rates(kG1, 5, u);
  // L2 runs above p + 1 at these levels (measured 6.34), as on the plane (docs/spaces/g1.md: L2
  // rates 6.13 … 7.31 on 3p_square): a lower bound only.
  EXPECT_GT(g.l2, 6.0 - 0.3);
  EXPECT_NEAR(g.h1, 5.0, 0.3);
  EXPECT_NEAR(g.h2, 4.0, 0.3);
}

}  // namespace
}  // namespace iga
