#pragma once
/// @file
/// A PatchMesh from a mesh file (Gmsh .msh / .geo, OBJ, OFF; mesh/): the file's
/// triangles and quadrilaterals become the G1 space's affine and bilinear patches.

#include <string>

#include "spaces/g1/patch_mesh.hpp"
#include "mesh/read_mesh_file.hpp"

namespace iga {

/// Read `path` (see read_mesh_file.hpp; `.geo` files are meshed with `options`), validate it
/// (validate_planar_mesh: degenerate, folded or non-convex cells, non-manifold edges, overlapping
/// cells, ...) and build the PatchMesh, named after the file. Every failure is an InputError naming
/// the file and the offending cell.
PatchMesh patch_mesh_from_file(const std::string& path, const MeshFileOptions& options);

/// The same for a mesh already read.
PatchMesh patch_mesh_from_planar(const PlanarMesh& mesh);

}  // namespace iga
