#pragma once
/// @file
/// What iga-run's PETSc plugin provides (solver/petsc_plugin.cpp loads it): MPI and PETSc's session,
/// the collectives of petsc_session.hpp, and the distributed backends. The program links none of
/// PETSc, SLEPc or MPI: a serial run never loads their ~100 shared libraries (start-up), and the
/// plugin (iga-run-petsc.so) is opened only under mpirun or when a config asks for `solver.type:
/// petsc`. Programs linking the library (tests, the Python module) have the implementation
/// built in instead. Internal to the solver layer and the plugin.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "solver/eigen_pipeline.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/pipeline.hpp"

namespace iga {

class PetscRuntime {
 public:
  virtual ~PetscRuntime() = default;
  /// The PETSc words of the command line (split_petsc_arguments; the first is the program name)
  /// and whether a PetscSession will finalise PETSc (else it is finalised at exit).
  virtual void set_arguments(std::vector<std::string> words, bool session) = 0;
  /// Initialise MPI and PETSc with those words unless they run already.
  virtual void ensure_initialised() = 0;
  /// PETSc runs (then MPI does).
  virtual bool up() const = 0;
  /// End of a PetscSession: reports unused options and finalises PETSc if it runs.
  virtual void end_session() = 0;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual int ranks_on_this_node() const = 0;
  virtual double sum(double value) const = 0;
  virtual double max(double value) const = 0;
  virtual double first_known(double value) const = 0;
  virtual std::vector<double> gather(const std::vector<double>& mine) const = 0;
  virtual void on_every_rank(const std::function<void()>& work) const = 0;
  virtual std::string broadcast_from_root(const std::string& text) const = 0;
  virtual bool failure_shared_by_all_ranks() const = 0;
  virtual int end_ranks_after_failure(int code) const = 0;
  virtual void before_mpi_finalize(std::function<void()> release) = 0;
  virtual std::unique_ptr<LinearBackend> make_linear_backend(const Space& space, const PetscSettings& settings,
                                                             const ProgressSink& progress) = 0;
  virtual std::unique_ptr<EigenBackend> make_eigen_backend(const Space& space, const ProgressSink& progress) = 0;
};

/// The implementation's parts (solver/petsc_runtime_impl.cpp, petsc_backend.cpp, slepc_eigen_backend.cpp).
PetscRuntime& petsc_runtime_implementation();
std::unique_ptr<LinearBackend> make_distributed_backend(const Space& space, const PetscSettings& settings,
                                                        const ProgressSink& progress);
/// Collective over the ranks, PETSc running; initialises SLEPc when nothing did. The solver keys of `solver:` are not
/// used (the factorization is CHOLMOD's or MUMPS's Cholesky); PETSc options of the command line
/// (-eps_*, -st_*) are. `progress` is called on every rank.
std::unique_ptr<EigenBackend> make_slepc_backend(const Space& space, const ProgressSink& progress);

/// The runtime when it is built in or was loaded; nullptr otherwise. With `load`, opens the plugin
/// if needed (throws std::runtime_error naming the file when it cannot).
PetscRuntime* petsc_runtime(bool load);

/// A symbol of the loaded plugin (the output layer's entry), nullptr when nothing was loaded.
void* petsc_plugin_symbol(const char* name);

}  // namespace iga

/// The entry of the implementation, defined in output/petsc_plugin_entry.cpp: in the plugin, and in
/// programs that link the implementation (they see it through a weak reference).
extern "C" iga::PetscRuntime* iga_petsc_runtime();
