#include "solver/eigen_pipeline.hpp"

#include <cstdio>
#include <stdexcept>

#include "assembly/integrators.hpp"
#include "config/progress.hpp"

namespace iga {

Eigen::VectorXd EigenBackend::solve(SolveReport&, const ProgressSink&) {
  throw std::logic_error("an eigen backend has no linear solve (use eigensolve)");
}

void SerialEigenBackend::assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                                  const ProgressSink&) {
  constraints_ = c;
  Eigen::VectorXd unused;
  reduce_system(f.matrix(f.terms()), load, c, K_free_, unused);
  reduce_system(f.matrix({mass_integrator()}), load, c, M_free_, unused);
}

EigenPairs SerialEigenBackend::eigensolve(int count, EigenReport& report, const ProgressSink& progress) {
  if (progress)
    progress("eigensolve: " + std::to_string(count) + " eigenpairs of " + std::to_string(K_free_.rows()) + " unknowns");
  ProgressPhase phase("eigensolve", 0);
  // Nothing constrained: our operators without a reaction term then have the constants in their kernel.
  const bool may_be_singular = constraints_.constrained.empty();
  EigenPairs free = smallest_eigenpairs(K_free_, M_free_, count, report, may_be_singular);
  if (progress) {
    char line[160];
    std::snprintf(line, sizeof line, "eigensolve: %d solves with the factor (factorize %.3f s, Lanczos %.3f s), "
                  "largest residual %.1e", report.operations, report.t_factorize, report.t_solve, report.max_residual);
    progress(line);
  }
  EigenPairs out{free.values, Eigen::MatrixXd(constraints_.values.size(), free.vectors.cols())};
  Constraints homogeneous = constraints_;
  homogeneous.values.setZero();
  for (int i = 0; i < free.vectors.cols(); ++i) out.vectors.col(i) = expand_solution(free.vectors.col(i), homogeneous);
  return out;
}

Eigen::VectorXd SerialEigenBackend::spectrum(EigenReport& report) {
  return all_eigenpairs(K_free_, M_free_, report).values;
}

DiscreteSolution solve_eigen_pipeline(const Formulation& f, EigenBackend& backend, const ProgressSink& progress) {
  if (!f.problem().eigen) throw std::logic_error("solve_eigen_pipeline: the problem has no eigen block");
  DiscreteSolution out;
  LevelResult& r = out.result;
  assemble_level(f, backend, r, progress);
  Stopwatch clock;
  EigenReport report;
  EigenPairs modes = backend.eigensolve(f.problem().eigen->count, report, progress);
  r.t_solve = clock.seconds();
  out.solve = {report.method, report.t_factorize, report.t_solve, report.max_residual, 0};
  out.eigenvalues = modes.values;
  out.modes = std::move(modes.vectors);
  out.coefficients = out.modes.col(0);
  if (f.problem().eigen->spectrum && r.free_dofs <= max_spectrum_unknowns) {
    if (progress) progress("the whole spectrum (dense, " + std::to_string(r.free_dofs) + " unknowns)");
    EigenReport dense;
    out.spectrum = backend.spectrum(dense);
  }
  return out;
}

}  // namespace iga
