#pragma once
/// @file
/// The config side of G1 surfaces (a proposal for `domain: {type: surface, ...}`):
///
///   domain:
///     type: surface
///     mesh: icosphere        # built-in: icosphere, octahedron, tetrahedron, perturbed_octahedron,
///     level: 2               #   height_field (level: icosphere only, 0..8) ...
///     file: bunny.obj        # ... or a .obj/.off/.stl/.msh/.geo file (relative to the config file),
///                            #   not both; .stl/.msh/.geo go through the Gmsh worker
///     mesh_size: 0.2         # .geo only: Gmsh's largest element size (default: the file's own)
///     normals: estimated     # file (default when the file has `vn`), estimated (angle-weighted,
///                            #   default otherwise), fan (area-weighted), exact (built-ins' own, default)
///     tuple: pi0             # pi0 (default, patch degree 8) or pi1 (degree 9)
///     method: hermite        # hermite (default), paper (reproduction only), none (C0, not G1)
///
/// Every failure (unknown key, bad value, unreadable file, mesh or data errors) is an InputError
/// at the offending key or at `domain`.

#include <string>
#include <utility>
#include <vector>

#include "config/config_node.hpp"
#include "geometry/rsd/rsd_surface.hpp"

namespace iga {

/// The mesh (with normals) that `domain` describes. `study_level` >= 0: the icosphere level of a
/// geometry study (domain.mesh must be icosphere, without its own `level`).
TriangleSurfaceMesh surface_mesh_from_config(const ConfigNode& domain, int study_level = -1);

/// tuple and method of `domain`.
rsd::RsdOptions rsd_options_from_config(const ConfigNode& domain);

/// The G1 surface that `domain` describes (`study_level` as for surface_mesh_from_config).
rsd::RsdSurface surface_from_config(const ConfigNode& domain, int study_level = -1);

}  // namespace iga
