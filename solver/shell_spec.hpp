#pragma once
/// @file
/// The data of a linear Kirchhoff–Love shell problem (`pde: kirchhoff_love_shell`,
/// solver/shell_problem.hpp): material, load per area, supports per boundary part, and an optional
/// exact displacement to measure errors against. Parsed by parse_shell_problem (shell_config.hpp).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/shell_integrators.hpp"
#include "config/expression.hpp"

namespace iga {

/// Displacement components fixed on a boundary part (x, y, z: any subset), the rest free.
struct ShellSupport {
  std::string part;
  std::array<bool, 3> fixed{false, false, false};
  /// The rotation about the edge, n·∂_ν u, held at zero (clamped edges, symmetry planes; by
  /// Nitsche's method, assembly/shell_rotation.hpp).
  bool rotation_held = false;
  std::string where;  ///< config location, for messages about the part name
};

/// A force at a point of the surface (located on each level's surface; admissible for the
/// Kirchhoff–Love model since H² ⊂ C⁰ in two dimensions).
struct ShellPointLoad {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  /// Applied at the surface's nearest point (within 1 % of its size) instead of exactly at `point`:
  /// for fitted surfaces that do not pass through the mesh vertex the load was meant for.
  bool snap = false;
  std::string where;  ///< config location of the point, for messages about it
};

struct ShellSpec {
  ShellMaterial material;
  /// Force per unit area (x, y, z components), functions of x, y, z.
  std::vector<SymbolicFunction> load;
  /// Pressure (problem.pressure): a force p(x) n per unit area along the surface's oriented normal
  /// (spaces/surface_orientation.hpp: outward on a closed surface, towards the convex side of a
  /// curved open one), added to `load`. A negative p pushes the other way.
  std::optional<SymbolicFunction> pressure;
  std::string pressure_where;  ///< config location of the pressure, for messages about its direction
  /// Point forces (problem.point_loads), added to the load per area.
  std::vector<ShellPointLoad> point_loads;
  /// Config location of the loads as a whole (messages about their resultant).
  std::string loads_where = "problem.load";
  /// The exact displacement (three functions of x, y, z) when known: errors, and the values of
  /// fixed components on the boundary (zero without it).
  std::optional<std::vector<SymbolicFunction>> exact;
  std::vector<ShellSupport> supports;
};

}  // namespace iga
