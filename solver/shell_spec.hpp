#pragma once
/// @file
/// The data of a linear Kirchhoff–Love shell problem (`pde: kirchhoff_love_shell`,
/// solver/shell_problem.hpp): material, load per area, supports per boundary part, and an optional
/// exact displacement to measure errors against. Parsed by parse_shell_problem (shell_config.hpp).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "assembly/shell_integrators.hpp"
#include "config/expression.hpp"

namespace iga {

/// Displacement components fixed on a boundary part (x, y, z: any subset), the rest free.
struct ShellSupport {
  std::string part;
  std::array<bool, 3> fixed{false, false, false};
  std::string where;  ///< config location, for messages about the part name
};

struct ShellSpec {
  ShellMaterial material;
  /// Force per unit area (x, y, z components), functions of x, y, z.
  std::vector<SymbolicFunction> load;
  /// The exact displacement (three functions of x, y, z) when known: errors, and the values of
  /// fixed components on the boundary (zero without it).
  std::optional<std::vector<SymbolicFunction>> exact;
  std::vector<ShellSupport> supports;
};

}  // namespace iga
