#pragma once
/// @file
/// Building the 4-split G1 space from config:
///   domain: {type: multipatch, name: NAME}   (g14_domain_names() and the quad-only g1 built-ins)
///   domain: {type: mesh_file, file: PATH, mesh_size: h, recombine: true}   (quads only)
///   space:  {type: g1_4split, degree: k, regularity: r (1), blending: lines | q1 | c1 | linear | q0 (lines),
///            refinement: nested | rebuild (nested)}
/// q0 (the paper's example blending) is refused for analysis: every geometry built from it is
/// singular at the edge midpoints. Errors are InputErrors naming the config place (exit code 2).

#include "config/config_node.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"
#include "spaces/space_request_size.hpp"

namespace iga {

/// The space on the domain refined `level` times (nested: gluing and geometry inherited).
/// With SpaceExtent::skeleton a planar space keeps no extraction (G14Space, BuildsOnElements);
/// surfaces are built whole.
SpacePtr make_g1_4split_space(const ConfigNode& domain, const ConfigNode& space, int level,
                              SpaceExtent extent = SpaceExtent::whole);

/// Levels 0 .. levels - 1 of a surface from a quad file (domain: {type: surface, file: F}),
/// estimated from the file's counts of faces F, edges E and vertices V, each level splitting every
/// face in four: DOFs about F ((2k-r-3)² + 4) + E (4k-2r-6) + 4V (the dimension formula of the
/// note with every edge counted as a boundary edge, which has the most functions); per face about
/// (2k-r-3)² + 4 + 4 (4k-2r-6) + 16 active functions; and building level 0 takes about 64 N² bytes
/// per face, N = (2k-r+1)² its coefficients (measured on flat grids: 0.31, 0.52, 1.24 MB per face at
/// k = 4, 5, 6), a nested level that plus about 8 N² per face of its own (the refined basis; the fit
/// is level 0's). Empty for other domains and for requests the builder refuses (it says why).
std::vector<SpaceRequestSize> g1_4split_requested_sizes(const ConfigNode& domain, const ConfigNode& space, int levels);

}  // namespace iga
