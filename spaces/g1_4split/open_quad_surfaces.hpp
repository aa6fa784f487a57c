#pragma once
/// @file
/// Built-in open quad surfaces in 3D for the 4-split G1 surface space (surfaces with a boundary
/// curve, where fourth-order problems need clamped data): each a topology and one position per
/// vertex, fitted by the space as the closed ones are.
///  - open_cube: the unit cube without its top face (5 faces; 4 interior valence-3 vertices, a
///    boundary square whose corners have 2 faces);
///  - cylinder_band: 8 × 2 quads on the cylinder x² + y² = 1, 0 ≤ z ≤ 1 (every interior vertex of
///    valence 4, two boundary circles);
///  - cap_fan5 / cap_fan5+: the planar built-ins fan5 / fan5+ (g1_4split_meshes.hpp: a valence-5
///    centre; fan5+ adds an interior valence-3 vertex next to it) lifted onto a sphere of radius
///    1.25 × the mesh's largest |(x, y)|: caps with extraordinary vertices inside.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "spaces/g1_4split/quad_topology.hpp"

namespace iga {

std::vector<std::string> open_quad_surface_names();

/// The built-in named `name` (open_quad_surface_names); std::invalid_argument otherwise.
std::pair<QuadTopology, std::vector<Eigen::Vector3d>> open_quad_surface(const std::string& name);

}  // namespace iga
