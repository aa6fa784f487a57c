#pragma once
/// @file
/// Building G1 multipatch spaces from config:
///   domain: {type: multipatch, name: NAME}   (multipatch_domain_names())
///   domain: {type: mesh_file, file: PATH, mesh_size: h, recombine: true|false}   (.geo keys only)
///   space:  {type: g1, degree: k}
/// Errors are InputErrors naming the config place (exit code 2).

#include "config/config_node.hpp"
#include "spaces/g1/patch_mesh.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The G1 space of degree k on the named multipatch domain or the mesh file's mesh, every patch
/// split uniformly into 4^level sub-patches (the geometry unchanged).
/// With SpaceExtent::skeleton the space keeps no extraction (G1Space, BuildsOnElements).
SpacePtr make_g1_space(const ConfigNode& domain, const ConfigNode& space, int level,
                       SpaceExtent extent = SpaceExtent::whole);

/// `domain: {type: mesh_file, file, mesh_size, recombine}`: a relative path is relative to the
/// config file's folder; mesh_size and recombine apply to .geo files (meshed by Gmsh) only.
PatchMesh patch_mesh_from_config(const ConfigNode& domain);

}  // namespace iga
