// iga-run: the command-line program. Everything lives in the library; see app/cli.cpp.
#include "app/cli.hpp"
#include "solver/petsc_session.hpp"

int main(int argc, char** argv) {
  const iga::PetscSession petsc(argc, argv);  // MPI and PETSc (when built in); takes out the PETSc options
  return iga::run_cli(argc, argv);
}
