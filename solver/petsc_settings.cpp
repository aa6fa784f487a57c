#include "solver/petsc_settings.hpp"

#include "solver/petsc_option_policy.hpp"

namespace iga {

bool petsc_available() {
#ifdef IGA_WITH_PETSC
  return true;
#else
  return false;
#endif
}

PetscSettings default_petsc_settings(Pde pde) {
  PetscSettings s;
  // Fourth-order problems and shells (membrane and bending stiffness t² apart: ill-conditioned): a
  // direct factorization.
  if (pde == Pde::biharmonic || pde == Pde::surface_biharmonic || pde == Pde::kirchhoff_love_shell) {
    s.ksp = "preonly";
    s.pc = "mumps";
  }
  return s;
}

void parse_solver_settings(const ConfigNode& node, Pde pde, SolverKind& kind, PetscSettings& petsc) {
  node.check_keys({"type", "ksp", "pc", "rtol", "max_iterations", "options"});
  if (auto type = node.find("type")) {
    const std::string t = type->as_choice({"cholmod", "umfpack", "petsc"});
    kind = t == "cholmod" ? SolverKind::cholmod : t == "umfpack" ? SolverKind::umfpack : SolverKind::petsc;
    if (kind == SolverKind::petsc && !petsc_available())
      type->fail("this iga-run was built without PETSc (install petsc-dev and rebuild with -DIGA_WITH_PETSC=ON)");
  }
  if (kind != SolverKind::petsc) {
    for (const char* key : {"ksp", "pc", "rtol", "max_iterations", "options"})
      if (auto k = node.find(key)) k->fail(std::string(key) + " is only used with solver.type: petsc");
    return;
  }
  petsc = default_petsc_settings(pde);
  if (auto ksp = node.find("ksp")) petsc.ksp = ksp->as_choice({"cg", "gmres", "preonly"});
  if (auto pc = node.find("pc")) petsc.pc = pc->as_choice({"gamg", "hypre", "mumps", "cholesky", "ilu"});
  const bool direct = petsc.pc == "mumps" || petsc.pc == "cholesky";
  if (petsc.ksp == "preonly" && !direct)
    (node.find("ksp") ? node["ksp"] : node["pc"])
        .fail("ksp: preonly applies the preconditioner once; it needs a direct one (pc: mumps or cholesky), not " +
              petsc.pc);
  if (auto rtol = node.find("rtol")) {
    petsc.rtol = rtol->as_double();
    if (!(petsc.rtol > 0.0 && petsc.rtol < 1.0)) rtol->fail("rtol must be in (0, 1) (got " + format_number(petsc.rtol) + ")");
  }
  if (auto it = node.find("max_iterations")) {
    petsc.max_iterations = it->as_int();
    if (petsc.max_iterations < 1 || petsc.max_iterations > kMaxIterations)
      it->fail("max_iterations must be between 1 and " + std::to_string(kMaxIterations));
  }
  if (auto options = node.find("options")) {
    petsc.options = options->as_string();
    petsc.options_where = options->where();
    // Only the allow-list of solver-tuning options, with typed values (petsc_option_policy.hpp).
    options->guard([&] { return parse_config_petsc_options(petsc.options); });
  }
}

}  // namespace iga
