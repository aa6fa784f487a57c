#pragma once
/// @file
/// Which PETSc options a config may set (`solver.options`), and the checks of their values.
/// A config comes from other people and may touch nothing outside its folder, but many PETSc
/// options write or read files (`-log_view :FILE`, `-ksp_view ascii:FILE`, `-options_file`,
/// `-history`), start debuggers or change signal handling. So a config may set only the
/// solver-tuning options of an explicit allow-list, each with a typed value; monitors and views
/// print to standard output only. The command line and PETSC_OPTIONS are the user's own and are
/// not checked here. Plain C++ (no PETSc), so the parser and its fuzz target need no PETSc.

#include <optional>
#include <string>
#include <vector>

namespace iga {

/// The most Krylov iterations a config may ask for (`solver.max_iterations`, `-ksp_max_it`): a
/// solve that needs more does not converge in any useful sense, and a config must not make a run
/// that hangs for hours.
inline constexpr int kMaxIterations = 100000;

/// One option of `solver.options`: its name as written ("-ksp_rtol") and its value, if any.
struct PetscOption {
  std::string name;
  std::optional<std::string> value;
};

/// Splits `text` ("-name [value] ...", words separated by white space; a word that starts with '-'
/// and a letter is a name, any other word the value of the name before it) and checks every
/// option against the allow-list and its value against the option's type. Throws InputError
/// naming the offending option (no place: the caller adds it, ConfigNode::guard).
std::vector<PetscOption> parse_config_petsc_options(const std::string& text);

/// The allow-list as documented in docs/parallel.md: each entry is an option name ("-ksp_rtol"),
/// or a family written with a placeholder ("-mat_mumps_icntl_N"). Options of the KSP and PC
/// entries may also carry one of the prefixes of config_petsc_option_prefixes().
std::vector<std::string> config_petsc_option_names();

/// "sub_", "mg_levels_", "mg_coarse_": the inner solvers (block Jacobi / ASM blocks, multigrid
/// smoothers and coarse solve) that the KSP and PC options may also address.
std::vector<std::string> config_petsc_option_prefixes();

}  // namespace iga
