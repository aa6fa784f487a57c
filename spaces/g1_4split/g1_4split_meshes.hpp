#pragma once
/// @file
/// Quad meshes for the 4-split G1 space: the built-in planar test domains of the notes, and the
/// conversion of a PatchMesh (built-ins of the g1 space, mesh files) into a QuadTopology.

#include <string>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"
#include "spaces/g1_4split/quad_topology.hpp"

namespace iga {

/// Names of the planar built-ins of this space: fan3 (the paper's "round corner", 3 quads around a
/// valence-3 vertex), fan5, fan6 (regular n-gon, spokes to the side midpoints), grid2x2 (unit square
/// in 4), halffan3 (3 quads at a straight-boundary vertex), fan3s, fan5s, fan6s (the fans split
/// once: crossing vertices next to the centre), fan3+ and fan5+ (the fan with one more
/// quad outside the spoke end s0, which becomes an interior valence-3 vertex next to the centre:
/// the topology of fan_topology(n, true)).
std::vector<std::string> g14_domain_names();

/// The built-in named `name` (g14_domain_names); std::invalid_argument otherwise.
PatchMesh g14_domain(const std::string& name);

/// Topology of a mesh of quads. Throws InputError naming the first triangle (the g1 space takes them).
QuadTopology quad_topology(const PatchMesh& mesh);

/// Interior angle of the domain at every vertex (2π at interior vertices): the sum of the face
/// angles at its corners.
std::vector<double> vertex_angles(const PatchMesh& mesh);

/// Topology of "fan n" (centre 0, spoke ends 1..n, corners n+1..2n; face i = [0, s_{i-1}, c_i, s_i]);
/// `plus` adds the quad [s_0, c_0, 2n+1, c_1], which makes s_0 an interior valence-3 vertex next to
/// the centre (fan3+, fan5+ of the notes).
QuadTopology fan_topology(int n, bool plus);

}  // namespace iga
