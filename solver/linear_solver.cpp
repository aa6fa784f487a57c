#include "solver/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <chrono>

#include "solver/errors.hpp"

namespace iga {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

template <class Solver>
bool try_solve(Solver& solver, const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
               SolveReport& report) {
  auto t0 = Clock::now();
  solver.compute(A);
  report.t_factorize = seconds_since(t0);
  if (solver.info() != Eigen::Success) return false;
  t0 = Clock::now();
  x = solver.solve(b);
  report.t_solve = seconds_since(t0);
  return solver.info() == Eigen::Success && x.allFinite();
}

}  // namespace

Eigen::VectorXd solve_linear_system(const SparseMatrix& A, const Eigen::VectorXd& b, SolverKind kind,
                                    SolveReport& report) {
  Eigen::VectorXd x;
  if (A.rows() == 0) {
    report.method = "none (no free unknowns)";
    return x;
  }
  bool ok = false;
  if (kind == SolverKind::cholmod) {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
    llt.cholmod().print = 0;  // its warnings would go to stdout; a failure is reported by the fallback
    ok = try_solve(llt, A, b, x, report);
    report.method = "cholmod";
  }
  if (!ok) {
    Eigen::UmfPackLU<SparseMatrix> lu;
    ok = try_solve(lu, A, b, x, report);
    report.method = kind == SolverKind::cholmod ? "umfpack (cholmod failed)" : "umfpack";
  }
  if (!ok) throw NumericalError("the system matrix is singular: " + report.method + " could not factorize it");
  const double bnorm = b.norm();
  report.relative_residual = bnorm > 0 ? (A * x - b).norm() / bnorm : (A * x).norm();
  if (!(report.relative_residual < 1e-6))
    throw NumericalError("linear solve inaccurate: relative residual " + std::to_string(report.relative_residual) +
                         " (matrix nearly singular)");
  return x;
}

}  // namespace iga
