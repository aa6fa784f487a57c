#pragma once
/// @file
/// PETSc and MPI for the life of the program, and what the rest of the program needs to know about
/// the ranks (which one writes files, how an error on one rank reaches all). Free of PETSc types:
/// the work is the PETSc runtime's (petsc_runtime.hpp, in iga-run's plugin); until it runs — and
/// always without PETSc (IGA_WITH_PETSC off) — there is one rank and every function is trivial.

#include <functional>
#include <string>
#include <vector>

namespace iga {

/// Takes the PETSc options out of argv, leaving iga-run's own arguments for the command-line parser
/// (split_petsc_arguments), and initialises PETSc (and MPI) with them and PETSC_OPTIONS: at once
/// when launched by mpirun, else when the first PETSc solve asks (ensure_petsc_initialised), so a
/// serial run with another solver never starts MPI. PETSc reads the user's ~/.petscrc but never a
/// .petscrc or petscrc of the working directory (a folder of downloaded inputs). On destruction,
/// finalises PETSc, first
/// reporting (on rank 0) every option that nothing used: PETSc ignores a misspelt option silently.
class PetscSession {
 public:
  PetscSession(int& argc, char** argv);
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
};

/// argv split into iga-run's arguments (first, with argv[0]) and PETSc's (second, with argv[0]).
/// A PETSc option is a word "-name" with an underscore in the name (-ksp_monitor, -log_view,
/// -pc_gamg_threshold) or -info; the next word is its value unless it starts with '-' (and is not a
/// negative number) or, before the config file has been seen, names a .yaml/.yml file.
std::pair<std::vector<std::string>, std::vector<std::string>> split_petsc_arguments(
    const std::vector<std::string>& args);

/// The value for OMPI_MCA_pml that leaves out Open MPI's network transports (the `cm` layer: PSM,
/// PSM2, libfabric), from the launch environment: "^cm" when every rank is on this node (world
/// size = local size) and the user chose neither a PML nor an MTL, else empty. Open MPI probes them
/// in MPI_Init although shared memory carries every message on one node: 0.2 s of each run's start
/// (MPI_Init and MPI_Finalize alone 0.31 → 0.11 s on one or two ranks). An environment variable
/// beats Open MPI's parameter files, so a PML chosen only there is overridden on one node.
std::string messaging_layers_to_skip(const char* world_size, const char* local_size, const char* chosen_pml,
                                     const char* chosen_mtl);

/// This process's rank and the number of ranks (0 and 1 when PETSc is not running).
int mpi_rank();
int mpi_size();
/// The ranks that share this process's node (MPI's shared-memory communicator; 1 when PETSc is not
/// running). Collective.
int ranks_on_this_node();
/// Collective: the sum and the largest of `value` over the ranks, and the value of the lowest rank
/// whose value is not NaN (NaN when none has one). The value itself on one rank.
double sum_over_ranks(double value);
double max_over_ranks(double value);
double first_known_over_ranks(double value);
/// Collective: every rank's `mine`, one after the other in rank order, on every rank.
std::vector<double> gather_over_ranks(const std::vector<double>& mine);
/// Rank 0: the one that prints and writes files.
inline bool is_root_rank() { return mpi_rank() == 0; }

/// Collective (every rank must call it at the same point): run `work`; when it throws on any rank,
/// every rank throws the error of the lowest failing rank (InputError, NumericalError, else
/// std::runtime_error), so that no rank waits in a collective operation for one that has left.
void on_every_rank(const std::function<void()>& work);

/// Collective: rank 0's `text` on every rank (the others' arguments are ignored).
std::string broadcast_from_root(const std::string& text);

/// True once on_every_rank has thrown: every rank has the same error and leaves together.
bool failure_shared_by_all_ranks();

/// After a failure: returns `code` when it was shared by all ranks (or there is one rank);
/// otherwise the other ranks may be waiting for this one in a collective call, so every rank is
/// ended with `code` (MPI_Abort, mpirun's exit code).
int end_ranks_after_failure(int code);

/// Run `release` just before PETSc finalises MPI, last registered first: objects of other libraries
/// that hold MPI resources (VTK's controller and its duplicated communicator) must give them back
/// while MPI still runs. Without PETSc, MPI never runs and `release` is never called.
void before_mpi_finalize(std::function<void()> release);

/// Make sure PETSc is initialised: with the session's PETSc options, or without options in programs
/// that created no session (tests calling the library; finalised at exit then).
void ensure_petsc_initialised();

}  // namespace iga
