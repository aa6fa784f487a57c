#pragma once
/// @file
/// Readers of triangle meshes in 3D (surfaces): Wavefront OBJ with or without `vn` normals, OFF,
/// and through the Gmsh worker STL, Gmsh .msh and .geo (meshed in 2D, e.g. an OpenCASCADE torus).
/// They only parse; topology, orientation and normals are checked by the geometry layer, which
/// names the file lines (or Gmsh tags) kept here in its messages.

#include <Eigen/Core>
#include <array>
#include <istream>
#include <string>
#include <vector>

#include "mesh/mesh_limits.hpp"

namespace iga {

/// A triangle mesh in 3D as read from a file, before any validation.
struct SurfaceMeshFile {
  std::string source;                          ///< file name, for messages
  std::vector<Eigen::Vector3d> points;         ///< vertex positions
  std::vector<int> point_lines;                ///< file line of each vertex
  std::vector<std::array<int, 3>> triangles;   ///< 0-based vertex indices, in file order
  std::vector<int> triangle_lines;             ///< file line of each triangle
  std::vector<Eigen::Vector3d> normals;        ///< one per vertex (from OBJ `vn`), or empty
  /// Meshes made by Gmsh name their vertices and triangles by Gmsh's tags instead of file lines
  /// ("Gmsh node 17", "Gmsh element 40"); empty for OBJ and OFF.
  std::vector<std::string> point_origins, triangle_origins;
};

/// Wavefront OBJ from `in`; `source` names the file in messages ("<source>:<line>: ...").
/// Faces must be triangles. Normals are taken when every face corner names one (`i//n`, `i/t/n`);
/// the corners of one vertex must then agree (a vertex has one tangent plane).
SurfaceMeshFile read_obj_surface(std::istream& in, const std::string& source);

/// Object File Format (OFF) from `in`; faces must be triangles. OFF carries no normals.
SurfaceMeshFile read_off_surface(std::istream& in, const std::string& source);

/// Options of surface mesh files made by Gmsh.
struct SurfaceFileOptions {
  /// `.geo` only: largest element size (Gmsh Mesh.MeshSizeMax); 0 keeps the file's own sizes.
  double mesh_size = 0.0;
  /// `.geo` only: a second folder (besides the file's own) that Include statements may read from.
  std::string config_folder;
};

/// Reads `path` by its extension (any case): .obj and .off here; .stl, .msh and .geo through the
/// Gmsh worker after our own checks (check_stl_structure, check_msh_structure, check_geo_script;
/// gmsh_model_surface.hpp says how Gmsh's triangles become the mesh). InputError for anything else.
SurfaceMeshFile read_surface_mesh(const std::string& path, const SurfaceFileOptions& options = {},
                                  const MeshLimits& limits = {});

}  // namespace iga
