/// @file
/// Differences between the solutions of successive levels (studies without an exact solution):
/// they must estimate the coarser level's true error within what the triangle inequality allows,
/// | ‖u_l − u_{l+1}‖ − ‖u − u_l‖ | ≤ ‖u − u_{l+1}‖, converge at the optimal rates, and vanish to
/// round-off for two identical spaces.

#include "solver/level_difference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/test_support.hpp"

namespace iga {
namespace {

struct Level {
  SpacePtr space;
  DiscreteSolution solution;
};

std::vector<Level> solve_levels(const std::string& yaml, int levels) {
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  std::vector<Level> out;
  for (int l = 0; l < levels; ++l) {
    Level level;
    level.space = test::space_from_yaml(yaml, l);
    level.solution = solve_problem(*level.space, problem, SolverKind::cholmod);
    out.push_back(std::move(level));
  }
  return out;
}

/// The differences of levels l, l+1 against the true errors of level l, for l = 0 .. levels-2;
/// `k` are the optimal rates of L2, H1, H2 (H2 when k[2] > 0).
/// The rule is the study's (difference_rule).
void check_against_errors(const std::string& yaml, int levels, std::array<int, 3> k) {
  const std::vector<Level> L = solve_levels(yaml, levels);
  std::vector<ErrorNorms> d;
  const bool hessians = k[2] > 0;
  for (int l = 0; l + 1 < levels; ++l) {
    const PointLocator coarse(L[l].space);
    d.push_back(level_difference(*L[l + 1].space, L[l + 1].solution.coefficients, coarse, L[l].solution.coefficients,
                                 hessians, difference_rule(*L[l + 1].space)));
  }
  for (int l = 0; l + 1 < levels; ++l) {
    const LevelResult &e = L[l].solution.result, &e_next = L[l + 1].solution.result;
    std::printf("level %d dofs %6d | L2 diff %.4e err %.4e | H1 diff %.4e err %.4e | H2 diff %.4e err %.4e\n", l,
                e.dofs, d[l].l2, *e.l2, *d[l].h1, *e.h1, d[l].h2.value_or(0), e.h2.value_or(0));
    // The triangle inequality, with a margin for quadrature and round-off.
    EXPECT_LE(std::abs(d[l].l2 - *e.l2), *e_next.l2 * 1.01 + 1e-12) << "L2, level " << l;
    EXPECT_LE(std::abs(*d[l].h1 - *e.h1), *e_next.h1 * 1.01 + 1e-12) << "H1, level " << l;
    if (hessians) EXPECT_LE(std::abs(*d[l].h2 - *e.h2), *e_next.h2 * 1.01 + 1e-12) << "H2, level " << l;
  }
  // In the asymptotic range the finer error is 2^-k times the coarser one: the ratio of the
  // difference to the coarse error lies in [1 - 2^-k, 1 + 2^-k] (with 0.05 for pre-asymptotics).
  const int l = levels - 2;
  const LevelResult& e = L[l].solution.result;
  const double r[3] = {d[l].l2 / *e.l2, *d[l].h1 / *e.h1, hessians ? *d[l].h2 / *e.h2 : 1.0};
  for (int n = 0; n < (hessians ? 3 : 2); ++n) {
    const double g = std::pow(2.0, -k[n]);
    EXPECT_GE(r[n], 1 - g - 0.05) << "norm " << n;
    EXPECT_LE(r[n], 1 + g + 0.05) << "norm " << n;
  }
  // Rates of the differences themselves (h halves per level).
  const int m = static_cast<int>(d.size()) - 1;
  EXPECT_GT(std::log2(d[m - 1].l2 / d[m].l2), k[0] - 0.2);
  EXPECT_GT(std::log2(*d[m - 1].h1 / *d[m].h1), k[1] - 0.2);
  if (hessians) EXPECT_GT(std::log2(*d[m - 1].h2 / *d[m].h2), k[2] - 0.2);
}

TEST(LevelDifference, CubicBSplinesPoissonEstimateTheCoarseError) {
  check_against_errors(R"yaml(
problem: {pde: poisson, exact: "sin(pi*x)*sin(2*pi*y)", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [4, 4]}
)yaml",
                       5, {4, 3, 2});
}

TEST(LevelDifference, CurvedQuarterAnnulusNewtonPath) {
  // Non-affine element maps: coarse points found by Newton's method on the curved maps.
  check_against_errors(R"yaml(
problem: {pde: poisson, exact: "sin(x*y) + x^3", boundary: {all: dirichlet}}
domain: {type: quarter_annulus, inner: 1, outer: 2}
space: {type: bspline, degree: 2, elements: [2, 2]}
)yaml",
                       5, {3, 2, 1});
}

TEST(LevelDifference, Ws4PoissonEstimateTheCoarseError) {
  check_against_errors(R"yaml(
problem: {pde: poisson, exact: "sin(pi*x)*sin(pi*y)", boundary: {all: dirichlet}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml",
                       4, {5, 4, 3});
}

TEST(LevelDifference, IdenticalSpacesDifferByRoundOff) {
  for (const char* yaml : {"domain: {type: quarter_annulus, inner: 1, outer: 2}\nspace: {type: bspline, degree: 3, elements: [3, 2]}\n",
                           "domain: {type: unit_square}\nspace: {type: ws4, elements: 2}\n"}) {
    // Two separately built copies of one space, the same (arbitrary) coefficients.
    const SpacePtr a = test::space_from_yaml(yaml, 1), b = test::space_from_yaml(yaml, 1);
    Eigen::VectorXd c(a->dimension());
    for (int i = 0; i < c.size(); ++i) c(i) = std::sin(1.0 + 0.37 * i);
    const auto rule = [&b, degree = 2 * a->degree() + 2](int e) { return b->quadrature(e, degree); };
    const ErrorNorms d = level_difference(*b, c, PointLocator(a), c, true, rule);
    const ErrorNorms zero = level_difference(*b, c, PointLocator(a), Eigen::VectorXd::Zero(c.size()), true, rule);
    EXPECT_GT(zero.l2, 0.1) << yaml;
    EXPECT_LE(d.l2, 1e-12 * zero.l2) << yaml;
    EXPECT_LE(*d.h1, 1e-11 * *zero.h1) << yaml;
    EXPECT_LE(*d.h2, 1e-10 * *zero.h2) << yaml;
  }
}

TEST(LevelDifference, StudyWithoutExactSolutionReportsDifferencesWithRates) {
  const StudyResult r = test::run_study_from_yaml(R"yaml(
problem: {pde: poisson, source: "5*pi^2*sin(pi*x)*sin(2*pi*y)", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [4, 4]}
refinement: {levels: 5}
output: {vtk: false, plot: false}
)yaml",
                                                  "no_exact");
  ASSERT_EQ(r.rows.size(), 5u);
  EXPECT_FALSE(r.rows[0].difference_l2.has_value());
  for (std::size_t l = 1; l < 5; ++l) {
    ASSERT_TRUE(r.rows[l].difference_l2 && r.rows[l].difference_h1 && r.rows[l].difference_h2) << l;
    EXPECT_FALSE(r.rows[l].l2.has_value());
  }
  const LevelResult &a = r.rows[3], &b = r.rows[4];
  EXPECT_NEAR(*rate(a.difference_l2, b.difference_l2, a.h, b.h), 4.0, 0.2);
  EXPECT_NEAR(*rate(a.difference_h1, b.difference_h1, a.h, b.h), 3.0, 0.2);
  EXPECT_NEAR(*rate(a.difference_h2, b.difference_h2, a.h, b.h), 2.0, 0.2);
  // For this u = sin(πx) sin(2πy): |u_3 − u_4|_H1 is within the finer error of |u − u_3|_H1 = 1.384e-4.
  EXPECT_NEAR(*b.difference_h1, 1.384e-4, 1.8e-5);
}

}  // namespace
}  // namespace iga
