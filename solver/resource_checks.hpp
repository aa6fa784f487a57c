#pragma once
/// @file
/// The limits: section applied to a study: the degree and element count the config asks for
/// before the coarsest space is built, every level's estimated size before the study starts (from
/// the coarsest space) and each level's actual size before it is assembled.

#include <optional>
#include <string>

#include "config/config_node.hpp"
#include "config/resource_limits.hpp"
#include "solver/petsc_settings.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Size of one level: what memory grows with.
struct SpaceSize {
  double elements = 0;
  double dofs = 0;
  double element_entries = 0;  ///< Σ over elements of (active functions)²: bounds the matrix nonzeros
  double build_bytes = 0;      ///< what the space itself takes, when estimated before it is built
};

/// Exact size of a built space (one pass over the elements' active functions).
SpaceSize measure(const Space& space);

/// Size of uniform level `level` estimated from level 0: elements, DOFs and entries grow at most
/// fourfold per level in 2D.
SpaceSize uniform_estimate(const SpaceSize& level0, int level);

/// What a solve keeps besides the space: a sparse factorization (CHOLMOD, UMFPACK, MUMPS, PETSc's
/// Cholesky) or, for Krylov methods with multigrid or ILU, the matrix and the preconditioner; and
/// over how many MPI ranks it is divided.
struct MemoryModel {
  bool factorization = true;
  int ranks = 1;
};

/// The model of a study's solver: PETSc with pc gamg, hypre or ilu is iterative, every other
/// solver factorizes; `ranks` is this run's number of MPI ranks.
MemoryModel memory_model(SolverKind kind, const PetscSettings& petsc);

/// Bytes a level of this size needs (per rank), an estimate, not a bound: size.build_bytes (the
/// space, on every rank) and the solve's.
/// With a factorization: 8.5 bytes per element entry times log2(dofs) (nested dissection's fill
/// grows like N log N), divided over the ranks. Calibrated on a B-spline study (264 196 DOFs,
/// quadratic: 2.4 GB measured, 3.2 GB estimated).
/// Iterative: 400 bytes per DOF on every rank (the space, its tables and the gathered solution are
/// replicated) and 7 bytes per element entry divided over the ranks (the matrix, about 12 bytes
/// per nonzero, and the AMG hierarchy and Krylov vectors). Calibrated on cubic B-splines with
/// CG + GAMG at 1 006 009 DOFs: 2.10 GB measured on one rank (2.19 estimated), 1.23 GB per rank on
/// two (1.30 estimated).
double estimated_memory_bytes(const SpaceSize& size, const MemoryModel& model = {});

/// Before the coarsest space is built: `space.degree` (a number or a list) against
/// limits.max_degree and the elements `space.elements` asks for (a count per direction, or one for
/// both) against limits.max_elements. InputError at the key otherwise.
void check_space_request(const ConfigNode& space, const ResourceLimits& limits);

/// Before anything is built: every uniform level of a space whose size follows from its request
/// (requested_space_sizes of the space factory: a B-spline space from its elements and degree, a
/// g1_4split surface from a file) against the limits, as check_size; InputError at the space (or the key the estimate
/// names, such as domain.file) for level 0 and at `blame` (the levels key) naming `levels_name`
/// ("--levels" or "refinement.levels") for the others. Nothing for other spaces: their levels are
/// estimated from the built level 0.
void check_requested_levels(const ConfigNode& domain, const ConfigNode& space, int levels, const ResourceLimits& limits,
                            const ConfigNode& blame, const std::string& levels_name, const MemoryModel& model);

/// InputError at `node` when `size` exceeds limits.max_elements, max_dofs or max_memory_gb (the
/// memory of `model`, per rank); `what` says which level ("level 3 (estimated from level 0)").
void check_size(const SpaceSize& size, const ResourceLimits& limits, const ConfigNode& node, const std::string& what,
                const MemoryModel& model = {});

}  // namespace iga
