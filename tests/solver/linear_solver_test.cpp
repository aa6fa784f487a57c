/// @file
/// solve_linear_system: iterative refinement with a long double residual recovers what a plain
/// Cholesky solve loses on an ill-conditioned SPD system (the 1D biharmonic matrix T², T the second
/// difference matrix, cond ≈ 1.6e11 at n = 1000), and stops at once on a well-conditioned one.

#include "solver/linear_solver.hpp"
#include "tests/support/test_support.hpp"

#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

namespace iga {
namespace {

using test::tridiagonal;

/// T² with T the second-difference matrix (pentadiagonal 1, −4, 6, −4, 1; 5 in the first and last
/// diagonal entries): SPD, integer entries.
SparseMatrix squared_second_difference(int n) {
  const SparseMatrix t = tridiagonal(n, 2.0);
  return t * t;
}

/// Small integers, so that b = A x* is exact in double and x* is the exact solution.
Eigen::VectorXd integer_solution(int n) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = (i * 7) % 11 - 5;
  return x;
}

TEST(LinearSolver, RefinementRecoversAccuracyOnAnIllConditionedSystem) {
  const int n = 1000;
  const SparseMatrix a = squared_second_difference(n);
  const Eigen::VectorXd exact = integer_solution(n);
  const Eigen::VectorXd b = a * exact;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> plain(a);  // no refinement
  const Eigen::VectorXd x0 = plain.solve(b);
  const double error_plain = (x0 - exact).norm() / exact.norm();

  SolveReport report;
  const Eigen::VectorXd x = solve_linear_system(a, b, SolverKind::cholmod, report);
  const double error = (x - exact).norm() / exact.norm();
  std::printf("relative error %.2e -> %.2e, relative residual (long double) %.2e, %d refinement steps\n",
              error_plain, error, report.relative_residual, report.refinement_steps);
  EXPECT_EQ(report.method, "cholmod");
  // The premise: cond(A) ≈ 1.6e11, so the plain solve loses many digits on any machine (its
  // forward error is about cond(A, x) · ε_double with a kernel-dependent constant).
  EXPECT_GT(error_plain, 1e6 * std::numeric_limits<double>::epsilon());
  // Refinement with a long double residual (Higham, Accuracy and Stability, §12.1): each step
  // multiplies the error by about the solver's own relative error (here ≤ error_plain) until the
  // floor u_double + cond(A, x) · ε_long double. The floor and the plain error are the same
  // cond(A, x) times a precision, so the gain is at most ε_double / ε_long double = 2048; kernels
  // differ in the constants (this machine gains more, AVX-512 kernels about 950×). Allow a factor
  // 16 in the constants: a refinement that does nothing (gain 1) still fails.
  const double precision_ratio = static_cast<double>(std::numeric_limits<long double>::epsilon()) /
                                 std::numeric_limits<double>::epsilon();
  EXPECT_LE(error, std::max(error_plain * error_plain, 16.0 * precision_ratio * error_plain));
  EXPECT_LT(error, 1e-9);
  EXPECT_LT(report.relative_residual, 1e-15);
  EXPECT_GE(report.refinement_steps, 1);
  EXPECT_LE(report.refinement_steps, max_refinement_steps);
}

TEST(LinearSolver, UmfpackIsRefinedToo) {
  const int n = 1000;
  const SparseMatrix a = squared_second_difference(n);
  const Eigen::VectorXd exact = integer_solution(n);
  SolveReport report;
  const Eigen::VectorXd x = solve_linear_system(a, a * exact, SolverKind::umfpack, report);
  EXPECT_EQ(report.method, "umfpack");
  EXPECT_LT((x - exact).norm() / exact.norm(), 1e-9);
  EXPECT_GE(report.refinement_steps, 1);
}

TEST(LinearSolver, WellConditionedSystemStopsAtRoundOff) {
  // tridiag(−1, 6, −1): cond < 2, the first solve is already at round-off.
  const int n = 200;
  const SparseMatrix a = tridiagonal(n, 6.0);
  const Eigen::VectorXd exact = integer_solution(n);
  SolveReport report;
  const Eigen::VectorXd x = solve_linear_system(a, a * exact, SolverKind::cholmod, report);
  EXPECT_LE(report.refinement_steps, 2);
  EXPECT_LT((x - exact).norm() / exact.norm(), 1e-15);
}

}  // namespace
}  // namespace iga
