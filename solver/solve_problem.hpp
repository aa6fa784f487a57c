#pragma once
/// @file
/// Solve one boundary value problem on one space: the pipeline (pipeline.hpp) with the problem's
/// formulation (planar or surface) and the backend the solver kind asks for (serial CHOLMOD/UMFPACK
/// here, PETSc in petsc_backend.cpp). Written against the Space interface only.

#include <Eigen/Core>
#include <memory>

#include "assembly/boundary_conditions.hpp"
#include "assembly/split_matrix.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/pipeline.hpp"
#include "solver/planar_formulation.hpp"
#include "solver/problem.hpp"

namespace iga {

/// The linear system of one problem on one space: the full matrix (extended precision) and load,
/// the essential boundary conditions, and the reduced system of the free functions.
struct LinearSystem {
  SplitMatrix A;
  Eigen::VectorXd b;
  Constraints constraints;
  SparseMatrix A_free;     ///< rows and columns: constraints.free, in that order
  Eigen::VectorXd b_free;
};

/// One process, every element: the matrix assembled whole (Formulation::matrix), reduced to the
/// free coefficients and solved by CHOLMOD or UMFPACK with refinement residuals of the whole
/// extended-precision system (solve_linear_system).
class SerialBackend final : public LinearBackend {
 public:
  explicit SerialBackend(SolverKind kind) : kind_(kind) {}
  void assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                const ProgressSink& progress) override;
  Eigen::VectorXd solve(SolveReport& report, const ProgressSink& progress) override;
  std::optional<double> energy(const Eigen::VectorXd& u) const override { return u.dot(system_.A.high * u); }
  const LinearSystem& system() const { return system_; }

 private:
  SolverKind kind_;
  LinearSystem system_;
};

/// The formulation of `problem` (planar, or Laplace–Beltrami on a surface).
std::unique_ptr<Formulation> make_formulation(const Space& space, const ProblemSpec& problem);

/// Assemble the matrix and load, impose the essential conditions and reduce (planar problems;
/// what solve_problem solves). Throws InputError for bad data (non-finite load or boundary values,
/// pure Neumann problems).
LinearSystem assemble_linear_system(const Space& space, const ProblemSpec& problem, const ProgressSink& progress = {});

/// `progress`, when given, is told when each phase starts (assemble, factorize and solve, errors).
/// With problem.eigen, the eigenproblem instead (eigen_pipeline.hpp): eigenvalues and modes, by
/// Spectra serially and by SLEPc with SolverKind::petsc (slepc_eigen_backend.cpp).
/// SolverKind::petsc solves with PETSc as `petsc` says (PetscRuntime::make_linear_backend; collective over the ranks).
DiscreteSolution solve_problem(const Space& space, const ProblemSpec& problem, SolverKind solver,
                               const ProgressSink& progress = {}, const PetscSettings& petsc = {});

}  // namespace iga
