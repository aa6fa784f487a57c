#pragma once
/// @file
/// The triangle mesh in 3D of the current Gmsh model, for smooth surfaces (call inside with_gmsh).

#include <string>

#include "mesh/read_surface_mesh.hpp"

namespace iga {

/// Cells: every 3-node triangle (Gmsh type 2) of dimension 2; any other 2D element type is an
/// InputError naming it (the G1 construction needs triangles). Vertices: only the nodes the
/// triangles use, numbered by increasing node tag, named "Gmsh node <tag>"; triangles are named
/// "Gmsh element <tag>". Gmsh orients each surface entity by its own parametrisation, so the
/// entities of a model may disagree: each connected group of entities is oriented like its first
/// entity (an entity is reversed as a whole when it traverses a shared edge in the same direction
/// as an already oriented neighbour). Triangles of one entity are never reordered: a file whose
/// entity is inconsistent in itself stays so and the geometry layer names the edge.
SurfaceMeshFile surface_mesh_from_gmsh_model(const std::string& source);

}  // namespace iga
