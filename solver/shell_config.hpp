#pragma once
/// @file
/// The `problem:` block of a linear Kirchhoff–Love shell (docs/shells.md):
///   pde: kirchhoff_love_shell
///   material: {youngs_modulus: E, poisson_ratio: ν, thickness: t}
///   load: [fx, fy, fz]            force per unit area, expressions in x, y, z
///   pressure: p                   force p n per unit area along the oriented normal (outward on a
///                                 closed surface), an expression in x, y, z
///   point_loads: [{point: [x, y, z], force: [fx, fy, fz]}, ...]   forces at points of the surface
///                                 (any of load, pressure, point_loads, at least one)
///   exact: [ux, uy, uz]           optional: the exact displacement (errors; values of fixed components)
///   boundary: {PART: {fixed: [x, y, z], rotation: held}, ...}   displacement components held (any
///                                 subset) and the rotation about the edge (Nitsche), per part;
///                                 without it, a free shell (loads balanced against its rigid motions)

#include "config/config_node.hpp"
#include "solver/problem.hpp"

namespace iga {

/// Parse and check the shell's `problem:` block (InputError at the key at fault, exit 2).
ProblemSpec parse_shell_problem(const ConfigNode& node);

}  // namespace iga
