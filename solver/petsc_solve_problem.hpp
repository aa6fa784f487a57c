#pragma once
/// @file
/// Solve one problem with PETSc, distributed over the MPI ranks (one rank without mpirun): the one
/// pipeline (pipeline.hpp) with the PETSc backend. The elements are partitioned
/// (petsc_partition.hpp); each rank assembles its elements' matrices (the serial assembler's
/// double-double kernel) with the essential conditions eliminated into a distributed (MPIAIJ)
/// matrix preallocated from the element couplings, keeps them in double-double for the right-hand
/// side and the refinement residuals (petsc_extended_residual.hpp), the KSP of `settings` solves,
/// and loads, errors and the sums of surface problems are summed over the ranks. Every rank ends
/// with the whole coefficient vector. Every rank builds the whole space and computes the boundary
/// constraints (a boundary-sized problem) itself. Written against the Space interface only.

#include "solver/petsc_settings.hpp"
#include "solver/solve_problem.hpp"

namespace iga {

/// Collective over the ranks. A KSP that does not converge throws NumericalError (with PETSc's
/// reason and the last residual norms) on every rank; input errors found on any rank are thrown
/// on every rank. Throws InputError when the program was built without PETSc.
DiscreteSolution solve_problem_petsc(const Space& space, const ProblemSpec& problem, const PetscSettings& settings,
                                     const ProgressSink& progress = {});

}  // namespace iga
