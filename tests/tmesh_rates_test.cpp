// Convergence rates of generalized splines on the dyadic hierarchical T-mesh of the notes (§7.5):
// 10, 40, 160, 640 cells on [0, pi]^2 with T-junctions at every level.
#include <gtest/gtest.h>

#include <cstdio>

#include "solver/solve_problem.hpp"
#include "test_support.hpp"

using namespace iga;

namespace {

struct Rates {
  double l2, h1, h2;
};

/// Solve on levels 0..levels-1, print the table, return the rates between the last two levels.
Rates last_rates(const std::string& yaml, int levels) {
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  std::vector<LevelResult> rows;
  for (int level = 0; level < levels; ++level) {
    const SpacePtr space = test::space_from_yaml(yaml, level);
    rows.push_back(solve_problem(*space, problem, SolverKind::cholmod).result);
    const LevelResult& b = rows.back();
    std::printf("level %d cells %d dofs %d h %.4f  L2 %.3e H1 %.3e H2 %.3e", level, space->num_elements(),
                space->dimension(), b.h, *b.l2, *b.h1, b.h2.value_or(0.0));
    if (level > 0) {
      const LevelResult& a = rows[level - 1];
      std::printf("  rates %.2f %.2f", *rate(a.l2, b.l2, a.h, b.h), *rate(a.h1, b.h1, a.h, b.h));
      if (a.h2 && b.h2) std::printf(" %.2f", *rate(a.h2, b.h2, a.h, b.h));
    }
    std::printf("\n");
  }
  const LevelResult &a = rows[levels - 2], &b = rows[levels - 1];
  Rates r{*rate(a.l2, b.l2, a.h, b.h), *rate(a.h1, b.h1, a.h, b.h), 0.0};
  if (a.h2 && b.h2) r.h2 = *rate(a.h2, b.h2, a.h, b.h);
  return r;
}

const char* kDyadic =
    "domain: {type: rectangle, min: [0, 0], max: [3.141592653589793, 3.141592653589793]}\n";
const char* kRefine = ", elements: [2, 2], refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}\n";

}  // namespace

TEST(TmeshRates, ClampedPlateC1CubicTrig) {
  const Rates r = last_rates(std::string(kDyadic) + "space: {type: tmesh, section: trig, n: 3, regularity: 1, frequency: 1" +
                                 kRefine +
                                 "problem: {pde: biharmonic, exact: \"sin(x)^2*sin(y)^2\", boundary: {all: clamped}}\n",
                             4);
  EXPECT_GE(r.l2, 3.8);
  EXPECT_GE(r.h1, 2.8);
  EXPECT_GE(r.h2, 1.9);
}

TEST(TmeshRates, PoissonC0QuadraticTrig) {
  const Rates r = last_rates(std::string(kDyadic) + "space: {type: tmesh, section: trig, n: 2, regularity: 0, frequency: 1" +
                                 kRefine +
                                 "problem: {pde: poisson, exact: \"sin(3*x)*sin(2*y)\", boundary: {all: dirichlet}}\n",
                             4);
  EXPECT_GE(r.l2, 2.8);
  EXPECT_GE(r.h1, 1.9);
}

TEST(TmeshRates, PoissonC1CubicPolynomial) {
  const Rates r = last_rates(std::string(kDyadic) + "space: {type: tmesh, section: poly, n: 3, regularity: 1" + kRefine +
                                 "problem: {pde: poisson, exact: \"sin(2*x)*sin(y)\", boundary: {all: dirichlet}}\n",
                             4);
  EXPECT_GE(r.l2, 3.7);
  EXPECT_GE(r.h1, 2.8);
  EXPECT_GE(r.h2, 1.9);
}

TEST(TmeshRates, PoissonC1CubicHyperbolic) {
  // Notes §8.6: hyperbolic w = 1, u = sin3x sin2y, levels 2 -> 3: 3.67 / 2.81 / 2.05 (pre-asymptotic in L2).
  const Rates r = last_rates(std::string(kDyadic) +
                                 "space: {type: tmesh, section: hyperbolic, n: 3, regularity: 1, frequency: 1" + kRefine +
                                 "problem: {pde: poisson, exact: \"sin(3*x)*sin(2*y)\", boundary: {all: dirichlet}}\n",
                             4);
  EXPECT_GE(r.l2, 3.5);
  EXPECT_GE(r.h1, 2.7);
  EXPECT_GE(r.h2, 1.9);
}
