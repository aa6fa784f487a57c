#pragma once
/// @file
/// WS4 triangulations from the shared mesh input (mesh/): validated PlanarMeshes with
/// their named boundary groups, and the built-in L-shape.

#include "mesh/planar_mesh.hpp"
#include "spaces/ws4/triangulation.hpp"

namespace iga::ws4 {

/// Validates `mesh` for WS4 (triangles only, every check of validate_planar_mesh) and builds the
/// Triangulation. Boundary parts are the mesh's boundary groups (their names, in name order); a
/// boundary edge in no group belongs only to "all". InputError "<source>: ..." when a group is named
/// "all" (reserved) or an edge is in two groups.
Triangulation triangulation_from_mesh(const PlanarMesh& mesh);

/// The L-shape [-1,1]² minus [0,1]×[-1,0] (the lower right quarter): 3 unit squares, each split
/// into n × n squares of side 1/n cut by a diagonal alternating in a checkerboard (as in
/// Triangulation::rectangle). Boundary groups: `left` (x = -1), `right` (x = 1), `bottom` (y = -1),
/// `top` (y = 1), and `reentrant` (the two sides meeting at the re-entrant corner (0, 0)).
PlanarMesh l_shape_mesh(int n);

}  // namespace iga::ws4
