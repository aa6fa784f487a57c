#pragma once
/// @file
/// Solve one boundary value problem on one space: assemble, impose boundary conditions, solve,
/// measure errors. Written against the Space interface only.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "assembly/error_norms.hpp"
#include "assembly/split_matrix.hpp"
#include "solver/level_result.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/problem.hpp"

namespace iga {

/// Progress messages for long phases (the CLI prints them to stderr unless --quiet).
using ProgressSink = std::function<void(const std::string&)>;

struct DiscreteSolution {
  Eigen::VectorXd coefficients;  ///< one per global basis function
  LevelResult result;            ///< h, dofs, errors, timings (level and t_space left to the caller)
  SolveReport solve;
  int boundary_constrained = 0;  ///< coefficients fixed by essential data
  /// Adaptive studies: the residual indicator η_K per element and the elements marked for refinement.
  std::vector<double> indicators;
  std::vector<int> marked;
};

/// Quadrature degree used for assembly with a space of local degree p (documented in docs/problems.md;
/// error norms use Space::error_quadrature_degree).
int assembly_quadrature_degree(const Space& space);

/// Validate the problem's boundary part names against the space; throws InputError.
void check_boundary_parts(const Space& space, const ProblemSpec& problem);


/// The linear system of one problem on one space: the full matrix (extended precision) and load,
/// the essential boundary conditions, and the reduced system of the free functions.
struct LinearSystem {
  SplitMatrix A;
  Eigen::VectorXd b;
  Constraints constraints;
  SparseMatrix A_free;     ///< rows and columns: constraints.free, in that order
  Eigen::VectorXd b_free;
};

/// Assemble the matrix and load, impose the essential conditions and reduce (planar problems;
/// what solve_problem solves). Throws InputError for bad data (non-finite load or boundary values,
/// pure Neumann problems).
LinearSystem assemble_linear_system(const Space& space, const ProblemSpec& problem, const ProgressSink& progress = {});

/// `progress`, when given, is told when each phase starts (assemble, factorize and solve, errors).
/// SolverKind::petsc solves with PETSc as `petsc` says (solve_problem_petsc).
DiscreteSolution solve_problem(const Space& space, const ProblemSpec& problem, SolverKind solver,
                               const ProgressSink& progress = {}, const PetscSettings& petsc = {});

}  // namespace iga
