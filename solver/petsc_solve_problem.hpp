#pragma once
/// @file
/// Solve one boundary value problem with PETSc, distributed over the MPI ranks (one rank without
/// mpirun): the elements are partitioned (petsc_partition.hpp), each rank assembles its elements'
/// systems with the essential boundary conditions eliminated into a distributed (MPIAIJ) matrix
/// preallocated from the element couplings, the KSP of `settings` solves it, and the error
/// integrals of each rank's elements are summed over the ranks. Every rank ends with the whole
/// coefficient vector. Written against the Space interface only.
///
/// Every rank builds the whole space and computes the boundary constraints (a boundary-sized
/// problem) itself; only assembly, solve and errors are divided.

#include "solver/petsc_settings.hpp"
#include "solver/solve_problem.hpp"

namespace iga {

/// Collective over the ranks. A KSP that does not converge throws NumericalError (with PETSc's
/// reason and the last residual norms) on every rank; input errors found on any rank are thrown
/// on every rank. Throws InputError when the program was built without PETSc.
DiscreteSolution solve_problem_petsc(const Space& space, const ProblemSpec& problem, const PetscSettings& settings,
                                     const ProgressSink& progress = {});

}  // namespace iga
