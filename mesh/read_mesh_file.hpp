#pragma once
/// @file
/// Reading a planar mesh file into a PlanarMesh (not yet validated: see validate_planar_mesh.hpp).
///
/// By extension (case-insensitive):
///  - `.msh`: an ASCII Gmsh mesh, MSH 2.2 or 4.1, checked by check_msh_structure, then read by the
///    Gmsh SDK in the Gmsh worker process (gmsh_worker.hpp);
///  - `.geo`: a Gmsh script, checked by check_geo_script (geometry and mesh statements only;
///    Includes from the file's folder or the config's), then meshed in 2D in the Gmsh worker;
///  - `.obj`: Wavefront OBJ, `v x y [z]` and `f` lines of 3 or 4 vertices (`i`, `i/t`, `i//n`,
///    `i/t/n`; 1-based, negative = relative to the end); `vt vn vp o g s l usemtl mtllib` ignored;
///  - `.off`: Object File Format: `OFF`, `nV nF nE`, nV lines `x y z`, nF lines `n i0 .. i(n-1)`
///    (0-based, n = 3 or 4; trailing colour values ignored).
/// All z must be equal (the mesh is planar). Cells are oriented counterclockwise on reading. Gmsh
/// surfaces may be oriented either way, so a clockwise Gmsh cell is reversed; an OBJ or OFF file
/// must list all its cells in one sense (either; a clockwise file is reversed) and a cell listed
/// the other way round is an InputError (inconsistent orientation). A mesh that folds over itself
/// is caught by validation, as two cells on the same side of an edge.
/// Gmsh meshes keep only the nodes their 2D cells use and name boundary edges by physical curve;
/// OBJ and OFF meshes have no boundary groups. Every failure (unreadable file, unknown extension,
/// syntax, a refused script statement, a malformed .msh, non-finite coordinates, Gmsh error or
/// crash, a time, memory or element limit reached, unsupported element, options given for a file
/// that is not `.geo`) is an InputError naming the file (and line).

#include <string>

#include "mesh/mesh_limits.hpp"
#include "mesh/planar_mesh.hpp"

namespace iga {

struct MeshFileOptions {
  /// `.geo` only: largest element size (Gmsh Mesh.MeshSizeMax); 0 keeps the file's own sizes.
  double mesh_size = 0.0;
  /// `.geo` only: recombine triangles into quadrilaterals (Gmsh Mesh.RecombineAll = 1).
  bool recombine = false;
  /// `.geo` only: a second folder (besides the file's own) that Include statements may read from,
  /// the config file's folder; empty for none.
  std::string config_folder;
  /// What reading or meshing may cost (element count or estimate, Gmsh time and memory).
  MeshLimits limits;
};

PlanarMesh read_mesh_file(const std::string& path, const MeshFileOptions& options = {});

}  // namespace iga
