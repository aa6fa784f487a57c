#pragma once
/// @file
/// Sparse direct solvers from SuiteSparse: CHOLMOD (supernodal Cholesky) for the SPD systems of
/// Poisson and biharmonic problems, UMFPACK (LU) as the fallback when Cholesky fails.

#include <Eigen/Core>
#include <string>

#include "assembly/sparsity.hpp"

namespace iga {

enum class SolverKind { cholmod, umfpack };

struct SolveReport {
  std::string method;           ///< what actually solved the system ("cholmod", "umfpack")
  double t_factorize = 0;       ///< seconds
  double t_solve = 0;           ///< seconds
  double relative_residual = 0; ///< ||A x - b|| / ||b||
};

/// Solve A x = b. With cholmod, a failed factorization (matrix not positive definite) falls back
/// to UMFPACK. Throws NumericalError when every method fails or the residual is not small.
Eigen::VectorXd solve_linear_system(const SparseMatrix& A, const Eigen::VectorXd& b, SolverKind kind,
                                    SolveReport& report);

}  // namespace iga
