#pragma once
/// @file
/// The eigenproblem K x = λ M x as a pipeline (pipeline.hpp): the same assemble step (checks,
/// essential conditions), K from Formulation::terms() and M from a mass term, both reduced to the
/// free functions (reduce_system: the basis change of dependent boundary traces too), and an
/// eigensolve instead of the linear solve. An EigenBackend is where it runs: serially here
/// (Spectra on a CHOLMOD factor); a SLEPc backend under MPI would reuse the PETSc layout and
/// matrix step (petsc_backend.cpp) and implement eigensolve() with EPS.

#include "solver/eigen_solver.hpp"
#include "solver/pipeline.hpp"

namespace iga {

/// A backend that assembles K and M under the constraints and returns eigenpairs.
class EigenBackend : public LinearBackend {
 public:
  /// The `count` smallest eigenpairs, eigenvectors as whole coefficient vectors (one column each,
  /// zero at the constrained functions), M-orthonormal.
  virtual EigenPairs eigensolve(int count, EigenReport& report, const ProgressSink& progress) = 0;
  /// Every eigenvalue (a dense solver), for problems of a few thousand unknowns at most.
  virtual Eigen::VectorXd spectrum(EigenReport& report) = 0;
  /// An eigen backend has no linear solve.
  Eigen::VectorXd solve(SolveReport&, const ProgressSink&) final;
};

/// One process: K and M assembled whole and reduced; Spectra + CHOLMOD.
class SerialEigenBackend final : public EigenBackend {
 public:
  void assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                const ProgressSink& progress) override;
  EigenPairs eigensolve(int count, EigenReport& report, const ProgressSink& progress) override;
  Eigen::VectorXd spectrum(EigenReport& report) override;

 private:
  Constraints constraints_;
  SparseMatrix K_free_, M_free_;
};

/// Assemble and solve for the problem's eigen.count smallest eigenpairs: eigenvalues, modes (whole
/// coefficient vectors), the first mode as coefficients, the result's h, dofs, free_dofs,
/// t_assemble, t_solve (errors: none), and the eigensolve's method, times and largest residual as
/// the solve report. With eigen.spectrum, at most max_spectrum_unknowns free unknowns: every
/// eigenvalue, ascending.
DiscreteSolution solve_eigen_pipeline(const Formulation& f, EigenBackend& backend, const ProgressSink& progress = {});

}  // namespace iga
