// problem.eigen as the config reader sees it: the references from a formula in m, n (ascending,
// with multiplicity), from a list of expressions, and the keys' checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "config/errors.hpp"
#include "solver/eigen_spec.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(EigenSpec, FormulaGivesTheSmallestValuesWithMultiplicity) {
  // m² + n²: 2, 5, 5, 8, 10, 10, 13, 13, 17, 17, 18, 20, 20 (m, n >= 1).
  const std::vector<double> v = eigenvalues_from_formula("m^2 + n^2", "here", 13);
  EXPECT_EQ(v, (std::vector<double>{2, 5, 5, 8, 10, 10, 13, 13, 17, 17, 18, 20, 20}));
}

TEST(EigenSpec, FormulaAgreesWithBruteForceForAWholeSpectrum) {
  // A rectangle 1 x 3 (λ = π²(m² + n²/9), stretched: many more m than n) and 3000 values, as a
  // whole spectrum needs: the enumeration must not stop before the last of them.
  const int count = 3000;
  const std::vector<double> v = eigenvalues_from_formula("m^2 + n^2/9", "here", count);
  std::vector<double> all;
  for (int m = 1; m <= 200; ++m)
    for (int n = 1; n <= 600; ++n) all.push_back(m * m + n * n / 9.0);
  std::sort(all.begin(), all.end());
  ASSERT_EQ(v.size(), std::size_t(count));
  for (int i = 0; i < count; ++i) EXPECT_NEAR(v[i], all[i], 1e-12 * all[i]) << i;
}

TEST(EigenSpec, ParsesCountReferencesAndSpectrum) {
  const ProblemSpec p = test::problem_from_yaml(
      "problem: {pde: poisson, boundary: {all: dirichlet}, eigen: {count: 3, exact_eigenvalues: [2*pi^2, 5*pi^2], "
      "spectrum: true}}");
  ASSERT_TRUE(p.eigen);
  EXPECT_EQ(p.eigen->count, 3);
  EXPECT_TRUE(p.eigen->spectrum);
  const double pi2 = std::numbers::pi * std::numbers::pi;
  EXPECT_EQ(p.eigen->exact, (std::vector<double>{2 * pi2, 5 * pi2}));
  EXPECT_TRUE(p.eigen->formula.empty());
  const ProblemSpec q = test::problem_from_yaml(
      "problem: {pde: biharmonic, boundary: {all: clamped}, eigen: {count: 2, exact_eigenvalues: \"m + n\"}}");
  EXPECT_EQ(q.eigen->exact, (std::vector<double>{2, 3}));
  EXPECT_EQ(q.eigen->formula, "m + n");
}

TEST(EigenSpec, ASurfaceEigenproblemHasZeroBoundaryData) {
  const ProblemSpec p =
      test::problem_from_yaml("problem: {pde: laplace_beltrami, reaction: 0, eigen: {count: 4}}");
  EXPECT_TRUE(p.eigen);
  EXPECT_FALSE(p.surface_dirichlet);  // closed surface: none
  const ProblemSpec open = test::problem_from_yaml(
      "problem: {pde: laplace_beltrami, boundary: {all: dirichlet}, eigen: {count: 4}}");
  ASSERT_TRUE(open.surface_dirichlet);
  EXPECT_EQ((*open.surface_dirichlet).at(Eigen::Vector3d(0.3, 0.2, 0.1)), 0.0);
}

TEST(EigenSpec, NeitherSourceNorEigenIsAnError) {
  try {
    test::problem_from_yaml("problem: {pde: poisson, boundary: {all: dirichlet}}");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'eigen'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace iga
