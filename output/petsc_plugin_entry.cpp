// The entry points of the PETSc implementation (solver/petsc_runtime.hpp): the symbols iga-run looks
// up in the plugin, and that programs linking the implementation resolve at link time (they force
// this file in with -u iga_petsc_runtime, which brings the rest).
#include "output/parallel_vtk_pieces.hpp"
#include "solver/petsc_runtime.hpp"

extern "C" iga::PetscRuntime* iga_petsc_runtime() { return &iga::petsc_runtime_implementation(); }

extern "C" bool iga_petsc_write_solution_pvtu(const iga::Space& space, const Eigen::VectorXd& coefficients,
                                              const iga::VtkFieldOptions& options, const std::string& pvtu_filename) {
  return iga::write_solution_pvtu_mpi(space, coefficients, options, pvtu_filename);
}
