/// @file
/// CHOLMOD's BLAS runs on one thread for small systems and on OpenMP's threads for large ones.
/// Checked through OpenBLAS's own getter after real factorizations (the project installs OpenBLAS;
/// with another BLAS the setting is a documented no-op and the test is skipped).

#include <gtest/gtest.h>

#include <dlfcn.h>
#include <omp.h>

#include <cstdlib>

#include "solver/blas_threads.hpp"
#include "solver/linear_solver.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(BlasThreads, FactorizationsOfSmallSystemsUseOneBlasThreadAndLargeOnesOpenMPs) {
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS"))
    GTEST_SKIP() << "OPENBLAS_NUM_THREADS is set: the user's choice is kept";
  omp_set_num_threads(2);
  for (const int n : {kParallelBlasUnknowns - 1, kParallelBlasUnknowns, 500}) {
    const SparseMatrix a = test::tridiagonal(n, 2.0);  // the 1D Laplacian, h = 1
    SolveReport report;
    const Eigen::VectorXd x = solve_linear_system(a, Eigen::VectorXd::Ones(n), SolverKind::cholmod, report);
    ASSERT_EQ(report.method, "cholmod");
    using GetThreads = int (*)();
    const auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    if (!get) GTEST_SKIP() << "CHOLMOD's BLAS is not OpenBLAS";
    EXPECT_EQ(get(), n < kParallelBlasUnknowns ? 1 : 2) << n;
    // The solution of -u'' = 1 with u(0) = u(n+1) = 0 at the midpoint: (n+1)²/8 (h = 1).
    EXPECT_NEAR(x(n / 2), 0.5 * (n / 2 + 1) * (n - n / 2), 1e-9 * n * n);
  }
}

}  // namespace
}  // namespace iga
