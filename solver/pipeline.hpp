#pragma once
/// @file
/// The solve pipeline, written once for every problem and every solver: assemble → constrain →
/// solve → errors, with the level bookkeeping (LevelResult) and the checks that data are finite.
/// Two seams: the Formulation says what the problem is (planar, surface), the LinearBackend where
/// and how the linear algebra runs (one process with CHOLMOD/UMFPACK, or PETSc over MPI ranks).
///
/// The backend's two steps, assemble then solve, are where a generalized eigenproblem
/// K x = λ M x plugs in: a backend whose assemble step builds K from Formulation::terms() and M
/// from a mass term under the same constraints (Formulation::matrix and reduce_system serially,
/// PetscBackend::matrix on its layout under MPI) and whose solve step returns eigenpairs.

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>

#include "solver/formulation.hpp"
#include "solver/level_result.hpp"
#include "solver/linear_solver.hpp"

namespace iga {

/// Progress messages for long phases (the CLI prints them to stderr unless --quiet).
using ProgressSink = std::function<void(const std::string&)>;

/// Where the linear algebra of a solve runs.
class LinearBackend {
 public:
  virtual ~LinearBackend() = default;
  /// This process's share of the elements and of sums.
  virtual WorkShare share() const { return {}; }
  /// Run local work whose input errors must reach every process together (on every MPI rank).
  virtual void locally(const std::function<void()>& work) const { work(); }
  /// Assemble the matrix of `f` on this process's elements with the essential conditions `c`
  /// eliminated; `load` is this process's part of the load (Formulation::load).
  virtual void assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                        const ProgressSink& progress) = 0;
  /// Solve the assembled system; every process gets the whole coefficient vector.
  virtual Eigen::VectorXd solve(SolveReport& report, const ProgressSink& progress) = 0;
  /// a(u, u) with the assembled matrix, where this process holds it whole.
  virtual std::optional<double> energy(const Eigen::VectorXd& /*u*/) const { return std::nullopt; }
  /// After assemble: the whole problem's functions, elements and free unknowns into `r`, where
  /// this process holds a part of the space (the formulation counts only its part).
  virtual void count_whole(const Formulation& /*f*/, LevelResult& /*r*/) const {}
};

/// What a solve produced.
struct DiscreteSolution {
  Eigen::VectorXd coefficients;  ///< one per global basis function
  LevelResult result;            ///< h, dofs, errors, timings (level and t_space left to the caller)
  SolveReport solve;
  /// Adaptive studies: the residual indicator η_K per element and the elements marked for refinement.
  std::vector<double> indicators;
  std::vector<int> marked;
  /// Eigenproblems (solver/eigen_pipeline.hpp): the eigenvalues, ascending, and the M-normalised
  /// modes, one per column; `coefficients` is the first.
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd modes;
  Eigen::VectorXd spectrum;  ///< eigen.spectrum: every eigenvalue (small problems; else empty)
};

/// The assemble step of a level: load, essential conditions (checked finite, InputError naming the
/// datum) and the backend's assembly; fills `r`'s h, DOFs, elements, free unknowns and t_assemble
/// (the linear and the eigen pipelines start the same way). Returns the conditions.
Constraints assemble_level(const Formulation& f, LinearBackend& backend, LevelResult& r,
                           const ProgressSink& progress = {});

/// The whole pipeline: assemble, solve, finish, errors; `progress` is told when each phase starts.
DiscreteSolution solve_pipeline(const Formulation& f, LinearBackend& backend, const ProgressSink& progress = {});

}  // namespace iga
