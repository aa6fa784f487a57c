#pragma once
/// @file
/// The eigen backend of a `solver.type: petsc` study: K and M assembled on the PETSc backend's
/// distributed layout (petsc_distribution.hpp) and the smallest eigenpairs of K x = λ M x by
/// SLEPc's EPS (generalized Hermitian, Krylov–Schur with shift-and-invert, one Cholesky factor of
/// K − σM — CHOLMOD's on one rank, MUMPS's across ranks — σ and the number of pairs as in the serial path: eigen_solver.hpp). Every rank
/// ends with the whole eigenvectors. Free of PETSc types.

#include <memory>

#include "solver/eigen_pipeline.hpp"

namespace iga {

/// True when this program was built with SLEPc (IGA_WITH_SLEPC, which needs PETSc).
bool slepc_available();

/// Collective over the ranks; initialises PETSc and SLEPc when no session did. The solver keys of
/// `solver:` are not used (the factorization is CHOLMOD's or MUMPS's Cholesky); PETSc options of the command
/// line (-eps_*, -st_*) are. Throws InputError when the program was built without SLEPc.
/// `progress` is called on every rank.
std::unique_ptr<EigenBackend> make_slepc_eigen_backend(const Space& space, const ProgressSink& progress = {});

}  // namespace iga
