#pragma once
/// @file
/// The 2D mesh of the current Gmsh model as a PlanarMesh (call inside with_gmsh).

#include <string>

#include "mesh/planar_mesh.hpp"

namespace iga {

/// Cells: every 3-node triangle (Gmsh type 2) and 4-node quadrilateral (type 3) of dimension 2;
/// other 2D element types are an InputError naming the type. Vertices: only the nodes these cells
/// use, numbered by increasing node tag (Gmsh keeps geometry-only nodes, e.g. circle centres).
/// Boundary groups: every physical group of dimension 1, by its name (its tag as a string when
/// unnamed), with its 2-node line elements as edges. Cells are oriented counterclockwise; every
/// cell's origin is "Gmsh element <tag>".
PlanarMesh planar_mesh_from_gmsh_model(const std::string& source);

}  // namespace iga
