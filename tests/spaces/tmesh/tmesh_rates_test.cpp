// Convergence rates of generalized splines on the dyadic hierarchical T-mesh of the notes (§7.5):
// 10, 40, 160, 640 cells on [0, pi]^2 with T-junctions at every level.
#include <gtest/gtest.h>

#include <cstdio>

#include "solver/solve_problem.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

using test::last_rates;
using test::Rates;

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

TEST(TmeshRates, PoissonC1CubicTrigOnCellsThatAreNotSquare) {
  // 1.5 x 1 cells: the x and y sides of a cell have different physical lengths, and trigonometric
  // sections depend on them (until 2026-11 the x side's basis served both, and the basis jumped).
  const Rates r = last_rates("domain: {type: rectangle, min: [0, 0], max: [3, 2]}\n"
                             "space: {type: tmesh, section: trig, n: 3, regularity: 1, frequency: 1, elements: [2, 2]}\n"
                             "problem: {pde: poisson, exact: \"sin(3*x)*sin(2*y)\", boundary: {all: dirichlet}}\n",
                             4);
  // Measured levels 2 -> 3: 3.68 / 2.82 / 2.07 (L2 pre-asymptotic, as for the hyperbolic case above).
  EXPECT_GE(r.l2, 3.5);
  EXPECT_GE(r.h1, 2.7);
  EXPECT_GE(r.h2, 1.9);
}
