#pragma once
/// @file
/// Building the 4-split G1 space from config:
///   domain: {type: multipatch, name: NAME}   (g14_domain_names() and the quad-only g1 built-ins)
///   domain: {type: mesh_file, file: PATH, mesh_size: h, recombine: true}   (quads only)
///   space:  {type: g1_4split, degree: k, regularity: r (1), blending: q1 | c1 | q0 (q1),
///            refinement: nested | rebuild (nested)}
/// q0 (the paper's example blending) is refused for analysis: every geometry built from it is
/// singular at the edge midpoints. Errors are InputErrors naming the config place (exit code 2).

#include "config/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The space on the domain refined `level` times (nested: gluing and geometry inherited).
SpacePtr make_g1_4split_space(const ConfigNode& domain, const ConfigNode& space, int level);

}  // namespace iga
