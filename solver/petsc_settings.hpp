#pragma once
/// @file
/// The `solver:` section of a config: which linear solver, and for `type: petsc` the Krylov method,
/// preconditioner, tolerance and extra PETSc options. Plain data (no PETSc types), so the study and
/// every layer above can hold it whether or not PETSc was built in.

#include <optional>
#include <string>

#include "config/config_node.hpp"
#include "solver/linear_solver.hpp"
#include "solver/problem.hpp"

namespace iga {

/// What `solver.type: petsc` runs. Defaults depend on the PDE (solver_settings_for).
struct PetscSettings {
  std::string ksp = "cg";      ///< cg | gmres | preonly
  std::string pc = "gamg";     ///< gamg | hypre | mumps | cholesky | ilu
  double rtol = 1e-12;         ///< relative residual decrease, in the KSP's default norm (preconditioned for CG)
  int max_iterations = 10000;  ///< a KSP still unconverged after this many is a numerical failure
  std::string options;         ///< "-name value ..." added to the PETSc options (the command line wins);
                               ///< the allow-list of petsc_option_policy.hpp, checked when the config is
                               ///< parsed and again before PETSc gets them (also when set in code)
  std::string options_where;   ///< "FILE:LINE:COL: solver.options" for errors PETSc finds in them
};

/// The defaults for a PDE: CG preconditioned by algebraic multigrid (GAMG) for second-order
/// problems; a direct factorization (MUMPS) for the biharmonic ones, whose fourth-order matrices
/// AMG built for Laplacians preconditions poorly, and for shells (docs/shells.md: GAMG needs
/// hundreds of iterations on them).
PetscSettings default_petsc_settings(Pde pde);

/// Parse `solver:` ({type, ksp, pc, rtol, max_iterations, options}) into `kind` and `petsc`.
/// PETSc keys without `type: petsc`, `type: petsc` in a build without PETSc, and combinations that
/// cannot work (preonly with an iterative preconditioner) are InputErrors naming the key, and so is
/// an option in `options` that a config may not set or a value of the wrong type.
void parse_solver_settings(const ConfigNode& node, Pde pde, SolverKind& kind, PetscSettings& petsc);

/// True when this program was built with PETSc (IGA_WITH_PETSC).
bool petsc_available();
/// True when this program was built with SLEPc (IGA_WITH_SLEPC, which needs PETSc).
bool slepc_available();

}  // namespace iga
