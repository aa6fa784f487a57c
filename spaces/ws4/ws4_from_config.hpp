#pragma once
/// @file
/// Building a WS4 space from the `domain` and `space` config nodes:
///
///   domain: {type: unit_square}
///   domain: {type: rectangle, min: [x0, y0], max: [x1, y1]}
///   domain: {type: l_shape}                   # [-1,1]² minus [0,1]x[-1,0]
///   domain: {type: polygon, vertices: [[x, y], ...], holes: [[[x, y], ...], ...], mesh_size: h}
///   domain: {type: mesh_file, file: path.msh|.geo|.obj|.off, mesh_size: h}   # mesh_size: .geo only
///   any of them with jitter: 0.15, seed: 3    # perturbed interior vertices
///   space:  {type: ws4, elements: N}          # or [nx, ny]; default 2; grids only
///
/// unit_square / rectangle: the nx x ny grid of squares, each split by a diagonal alternating in a
/// checkerboard (WS4 notes §10); l_shape: N x N such squares per unit square (ws4::l_shape_mesh).
/// polygon: meshed by Gmsh (mesh_polygon.hpp), parts side1..sideN and hole1, hole2, ...
/// mesh_file: read by read_mesh_file.hpp, a relative path relative to the config file's folder;
/// parts are the Gmsh physical curves. Every input mesh is validated (validate_planar_mesh.hpp,
/// triangles only) with messages naming the config key and the triangle. Refinement level l splits
/// every triangle into 4, l times; boundary vertices stay on the straight edges of the level-0 mesh,
/// so a curved Gmsh boundary is not followed (the domain is the polygon of the read mesh). With
/// `jitter` (in [0, 0.2]), the interior vertices of each level are then moved at random by up to
/// jitter x the shortest edge at the vertex (ws4_jitter.hpp; seed + level seeds the generator,
/// default seed 1). Every error is an InputError naming the config place (exit code 2).

#include "config/config_node.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"

namespace iga {

/// With SpaceExtent::skeleton the space is built on no element (Ws4Space, BuildsOnElements).
SpacePtr make_ws4_space(const ConfigNode& domain, const ConfigNode& space, int level,
                        SpaceExtent extent = SpaceExtent::whole);

}  // namespace iga
