// Rates on the unit square with B-splines, against the thresholds of the issue (and of G+Smo's
// gsBiharmonic_test: L2 > 3.75, H1 > 2.85, H2 > 1.85 for the clamped cubic plate).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/solve_problem.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

using test::last_rates;
using test::Rates;

std::string poisson_yaml(int p) {
  return R"yaml(
problem: {pde: poisson, exact: "sin(pi*x)*sin(2*pi*y)", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: )yaml" +
         std::to_string(p) + ", regularity: " + std::to_string(p - 1) + ", elements: [4, 4]}\n";
}

}  // namespace

TEST(ConvergenceRates, PoissonQuadratic) {
  const Rates r = last_rates(poisson_yaml(2), 4);
  EXPECT_GE(r.l2, 3 - 0.2);
  EXPECT_GE(r.h1, 2 - 0.2);
}

TEST(ConvergenceRates, PoissonCubic) {
  const Rates r = last_rates(poisson_yaml(3), 4);
  EXPECT_GE(r.l2, 4 - 0.2);
  EXPECT_GE(r.h1, 3 - 0.2);
  EXPECT_GE(r.h2, 2 - 0.2);
}

TEST(ConvergenceRates, ClampedPlateCubic) {
  const Rates r = last_rates(R"yaml(
problem: {pde: biharmonic, exact: "(cos(4*pi*x)-1)*(cos(4*pi*y)-1)", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [4, 4]}
)yaml",
                             5);
  EXPECT_GT(r.l2, 3.75);
  EXPECT_GT(r.h1, 2.85);
  EXPECT_GT(r.h2, 1.85);
}

TEST(ConvergenceRates, SimplySupportedPlateOnQuarterAnnulus) {
  const Rates r = last_rates(R"yaml(
problem: {pde: biharmonic, exact: "sin(x*y) + x^3", boundary: {all: simply_supported}}
domain: {type: quarter_annulus, inner: 1, outer: 2}
space: {type: bspline, degree: 4, elements: [2, 2]}
)yaml",
                             4);
  EXPECT_GT(r.l2, 5 - 0.3);
  EXPECT_GT(r.h1, 4 - 0.3);
  EXPECT_GT(r.h2, 3 - 0.3);
}
