#pragma once
/// @file
/// Sparse direct solvers from SuiteSparse: CHOLMOD (supernodal Cholesky) for the SPD systems of
/// Poisson and biharmonic problems, UMFPACK (LU) as the fallback when Cholesky fails, followed by
/// iterative refinement with the residual in long double (reusing the factor): the factorization's
/// round-off, amplified by the condition number (h⁻⁴ for biharmonic problems), otherwise sets an
/// error floor well above what the assembled system determines.

#include <Eigen/Core>
#include <chrono>
#include <functional>
#include <string>

#include "assembly/sparsity.hpp"

namespace iga {

/// petsc: the distributed PETSc path (solver/petsc_backend.cpp), chosen before this function.
enum class SolverKind { cholmod, umfpack, petsc };

struct SolveReport {
  std::string method;           ///< what actually solved the system ("cholmod", "umfpack")
  double t_factorize = 0;       ///< seconds
  double t_solve = 0;           ///< seconds
  double relative_residual = 0; ///< ||A x - b|| / ||b|| (computed in long double)
  int refinement_steps = 0;     ///< iterative-refinement corrections applied
};

/// Wall-clock seconds since construction or restart(): the phase times of SolveReport and LevelResult.
class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  void restart() { start_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// r(x) = b − A x evaluated more accurately than the double A allows, e.g. on the whole system
/// before elimination with the matrix kept in extended precision (reduced_residual).
using ResidualFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd& x)>;

/// Solve A x = b (A stored with both triangles). With cholmod, a failed factorization (matrix not
/// positive definite) falls back to UMFPACK. Then x ← x + A⁻¹ r with r = b − A x in long double
/// (or r = residual(x) when given) while the corrections keep shrinking (at most
/// max_refinement_steps, refine_iteratively). Throws NumericalError when every method fails or the
/// residual is not small.
Eigen::VectorXd solve_linear_system(const SparseMatrix& A, const Eigen::VectorXd& b, SolverKind kind,
                                    SolveReport& report, const ResidualFunction& residual = {});

/// Iterative refinement with a factor, the rule of the serial and the PETSc solver alike: apply
/// corrections while each is smaller than the last; stop once one shrinks by less than 4x
/// (round-off reached) or drops below ε ‖x‖. `correct()` computes the next correction from the
/// current x and returns its norm (NaN when it failed); `apply()` adds it to x and returns ‖x‖.
/// Returns the number of corrections applied.
constexpr int max_refinement_steps = 8;
int refine_iteratively(double x_norm, const std::function<double()>& correct, const std::function<double()>& apply);

}  // namespace iga
