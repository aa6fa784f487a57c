#pragma once
/// @file
/// The PETSc backend of the one pipeline (pipeline.hpp), distributed over the MPI ranks (one rank
/// without mpirun). The elements are partitioned (petsc_partition.hpp); each rank assembles its
/// elements' matrices (the serial assembler's double-double kernel) with the essential conditions
/// eliminated into a distributed (MPIAIJ) matrix preallocated from the element couplings, keeps
/// them in double-double for the right-hand side and the refinement residuals
/// (petsc_extended_residual.hpp), the KSP of `settings` solves, and loads, errors and the sums of
/// surface problems are summed over the ranks. Every rank ends with the whole coefficient vector.
/// Every rank builds the whole space and computes the boundary constraints (a boundary-sized
/// problem) itself. Written against the Space interface only.

#include <memory>

#include "solver/petsc_settings.hpp"
#include "solver/pipeline.hpp"

namespace iga {

/// Collective over the ranks; initialises PETSc when no session did. The backend's solve throws
/// NumericalError (with PETSc's reason and the last residual norms) on every rank when the KSP
/// does not converge; input errors found on any rank are thrown on every rank. Throws InputError
/// when the program was built without PETSc. `progress` is called on every rank (solve_problem
/// hands it a sink that speaks on rank 0 only).
std::unique_ptr<LinearBackend> make_petsc_backend(const Space& space, const PetscSettings& settings,
                                                  const ProgressSink& progress = {});

}  // namespace iga
