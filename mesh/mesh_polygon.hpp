#pragma once
/// @file
/// Meshing a polygonal domain (with optional polygonal holes) by Gmsh's 2D mesher.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "mesh/mesh_limits.hpp"
#include "mesh/planar_mesh.hpp"

namespace iga {

struct PolygonDomain {
  std::vector<Eigen::Vector2d> outer;               ///< boundary vertices, either orientation
  std::vector<std::vector<Eigen::Vector2d>> holes;  ///< each strictly inside `outer`
};

/// Checks that every vertex is finite, every loop has >= 3 distinct vertices, that no two sides intersect (except
/// neighbours at their common vertex, in any loop), and that the holes lie inside the outer loop
/// and outside each other. Throws InputError "<source>: ..." naming the loop and sides
/// ("outer side 2 ((1, 0)-(1, 1)) crosses hole 1 side 3 (...)").
void check_polygon_domain(const PolygonDomain& domain, const std::string& source);

/// Checks the domain and triangulates it with element size at most `mesh_size` (Gmsh
/// Mesh.MeshSizeMax; quadrilaterals when `recombine`). Boundary groups: "side1" .. "sideN" for the
/// outer sides (side k joins outer vertices k and k+1, counted from 1, the last one closes the loop)
/// and "hole1", "hole2", ... for the whole boundary of each hole. `source` names the domain in
/// messages. The element estimate (area / (sqrt(3)/4 h²)) must be within limits.max_elements; Gmsh
/// runs in the Gmsh worker (gmsh_worker.hpp) under `limits`.
PlanarMesh mesh_polygon(const PolygonDomain& domain, double mesh_size, bool recombine, const std::string& source,
                        const MeshLimits& limits = {});

}  // namespace iga
