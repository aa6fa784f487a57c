#include "solver/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <cmath>
#include <limits>
#include <vector>

#include "config/errors.hpp"
#include "solver/blas_threads.hpp"

namespace iga {

namespace {

/// b − A x with products and sums in long double, rounded once (A with both triangles stored).
Eigen::VectorXd residual_extended(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  std::vector<long double> r(b.data(), b.data() + b.size());
  for (int k = 0; k < A.outerSize(); ++k) {
    const long double xk = x(k);
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) r[it.index()] -= it.value() * xk;
  }
  Eigen::VectorXd out(b.size());
  for (int i = 0; i < b.size(); ++i) out(i) = static_cast<double>(r[i]);
  return out;
}

/// Iterative refinement with the factor in `solver` (refine_iteratively).
template <class Solver>
void refine(const Solver& solver, const ResidualFunction& residual, Eigen::VectorXd& x, SolveReport& report) {
  Eigen::VectorXd d;
  const auto correct = [&] {
    d = solver.solve(residual(x));
    return d.allFinite() ? d.norm() : std::numeric_limits<double>::quiet_NaN();
  };
  report.refinement_steps += refine_iteratively(x.norm(), correct, [&] { return (x += d).norm(); });
}

template <class Solver>
bool try_solve(Solver& solver, const SparseMatrix& A, const Eigen::VectorXd& b, const ResidualFunction& residual,
               Eigen::VectorXd& x, SolveReport& report) {
  Stopwatch clock;
  solver.compute(A);
  report.t_factorize = clock.seconds();
  if (solver.info() != Eigen::Success) return false;
  clock.restart();
  x = solver.solve(b);
  const bool ok = solver.info() == Eigen::Success && x.allFinite();
  if (ok) refine(solver, residual, x, report);
  report.t_solve = clock.seconds();
  return ok;
}

}  // namespace

int refine_iteratively(double x_norm, const std::function<double()>& correct, const std::function<double()>& apply) {
  int steps = 0;
  double previous = x_norm;
  for (int step = 0; step < max_refinement_steps; ++step) {
    const double size = correct();
    if (!std::isfinite(size) || !(size < previous)) break;
    const double norm = apply();
    ++steps;
    if (size > 0.25 * previous || size <= 1e-16 * norm) break;
    previous = size;
  }
  return steps;
}

Eigen::VectorXd solve_linear_system(const SparseMatrix& A, const Eigen::VectorXd& b, SolverKind kind,
                                    SolveReport& report, const ResidualFunction& given_residual) {
  const ResidualFunction residual =
      given_residual ? given_residual : [&](const Eigen::VectorXd& x) { return residual_extended(A, x, b); };
  Eigen::VectorXd x;
  if (A.rows() == 0) {
    report.method = "none (no free unknowns)";
    return x;
  }
  bool ok = false;
  if (kind == SolverKind::cholmod) {
    set_blas_threads_for(static_cast<int>(A.rows()));
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
    llt.cholmod().print = 0;  // its warnings would go to stdout; a failure is reported by the fallback
    ok = try_solve(llt, A, b, residual, x, report);
    report.method = "cholmod";
  }
  if (!ok) {
    Eigen::UmfPackLU<SparseMatrix> lu;
    ok = try_solve(lu, A, b, residual, x, report);
    report.method = kind == SolverKind::cholmod ? "umfpack (cholmod failed)" : "umfpack";
  }
  if (!ok) throw NumericalError("the system matrix is singular: " + report.method + " could not factorize it");
  const double bnorm = b.norm();
  const double rnorm = residual(x).norm();
  report.relative_residual = bnorm > 0 ? rnorm / bnorm : rnorm;
  if (!(report.relative_residual < 1e-6))
    throw NumericalError("linear solve inaccurate: relative residual " + std::to_string(report.relative_residual) +
                         " (matrix nearly singular)");
  return x;
}

}  // namespace iga
