#include "solver/solve_problem.hpp"

#include <optional>

#include "config/errors.hpp"
#include "config/progress.hpp"
#include "solver/eigen_pipeline.hpp"
#include "solver/petsc_runtime.hpp"
#include "solver/petsc_session.hpp"
#include "solver/shell_problem.hpp"
#include "solver/surface_problem.hpp"

namespace iga {

void SerialBackend::assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                             const ProgressSink&) {
  system_.A = f.matrix(f.terms());
  system_.b = load;
  system_.constraints = c;
  reduce_system(system_.A, system_.b, system_.constraints, system_.A_free, system_.b_free);
}

Eigen::VectorXd SerialBackend::solve(SolveReport& report, const ProgressSink& progress) {
  const LinearSystem& s = system_;
  if (progress) progress("factorizing and solving (" + std::to_string(s.constraints.free.size()) + " unknowns)");
  ProgressPhase phase("factorizing", 0);
  const Eigen::VectorXd u_free = solve_linear_system(
      s.A_free, s.b_free, kind_, report,
      [&](const Eigen::VectorXd& x) { return reduced_residual(s.A, s.b, s.constraints, x); });
  return expand_solution(u_free, s.constraints);
}

std::unique_ptr<Formulation> make_formulation(const Space& space, const ProblemSpec& problem) {
  if (problem.pde == Pde::laplace_beltrami) return std::make_unique<SurfaceFormulation>(space, problem);
  if (problem.pde == Pde::surface_biharmonic) return std::make_unique<SurfaceBiharmonicFormulation>(space, problem);
  if (problem.pde == Pde::kirchhoff_love_shell) return std::make_unique<ShellFormulation>(space, problem);
  return std::make_unique<PlanarFormulation>(space, problem);
}

LinearSystem assemble_linear_system(const Space& space, const ProblemSpec& problem, const ProgressSink& progress) {
  const PlanarFormulation f(space, problem);
  SerialBackend backend(SolverKind::cholmod);
  LevelResult unused;
  assemble_level(f, backend, unused, progress);
  return backend.system();
}

DiscreteSolution solve_problem(const Space& space, const ProblemSpec& problem, SolverKind solver,
                               const ProgressSink& progress, const PetscSettings& petsc) {
  const std::unique_ptr<Formulation> f = make_formulation(space, problem);
  // The eigen backends count one unknown per function (parse_study refuses the combination for
  // configs; this guards library callers). The linear backends, PETSc's too, take components.
  if (f->components() != 1 && problem.eigen)
    throw InputError(problem.source_where + ": " + to_string(problem.pde) + " has no eigenproblems (problem.eigen) yet");
  // Under PETSc every rank runs the pipeline; rank 0 reports its progress.
  const ProgressSink say = [&](const std::string& msg) {
    if (progress && is_root_rank()) progress(msg);
  };
  if (problem.eigen) {
    std::unique_ptr<EigenBackend> backend;
    if (solver == SolverKind::petsc) {
      if (!slepc_available())
        throw InputError("solver.type: petsc with problem.eigen: this iga-run was built without SLEPc");
      ensure_petsc_initialised();
      backend = petsc_runtime(true)->make_eigen_backend(space, say);
    } else {
      backend = std::make_unique<SerialEigenBackend>();
    }
    return solve_eigen_pipeline(*f, *backend, solver == SolverKind::petsc ? say : progress);
  }
  if (solver != SolverKind::petsc) {
    SerialBackend backend(solver);
    return solve_pipeline(*f, backend, progress);
  }
  ensure_petsc_initialised();  // without PETSc, petsc_runtime(true) throws the InputError that says so
  const std::unique_ptr<LinearBackend> backend = petsc_runtime(true)->make_linear_backend(space, petsc, say);
  return solve_pipeline(*f, *backend, say);
}

}  // namespace iga
