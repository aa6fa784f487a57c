#pragma once
/// @file
/// `domain: {type: surface_patch, ...}` with `space: {type: bspline, degree, regularity, elements}`:
/// B-splines on one exact NURBS patch in 3D (surface_patch_space.hpp).
///
///   domain: {type: surface_patch, shape: cylinder, radius: R, length: L, half_angle: 40}  # ≥ 180: closed
///   domain: {type: surface_patch, shape: torus, major_radius: R, minor_radius: r}
///   domain: {type: surface_patch, shape: sphere, radius: R, hole: 18, sweep: 360}
///   domain: {type: surface_patch, file: shell.xml, periodic: none | u | v | both}   # G+Smo, geoDim 3
///
/// `elements: [nu, nv]` counts elements over the whole patch (default: the map's spans), a multiple
/// of the map's spans per direction; level l multiplies both by 2^l. Every error is an InputError
/// naming the config place (file, line, key), or the XML file and line.

#include "config/config_node.hpp"
#include "spaces/space.hpp"
#include "spaces/space_catalogue.hpp"

namespace iga {

SpacePtr make_surface_patch_bspline_space(const ConfigNode& domain, const ConfigNode& space, int level);

/// The `surface_patch` family of the bspline catalogue entry.
DomainFamily surface_patch_domain_family();

}  // namespace iga
