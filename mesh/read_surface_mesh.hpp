#pragma once
/// @file
/// Readers of triangle meshes in 3D (surfaces): Wavefront OBJ with or without `vn` normals, and OFF.
/// They only parse; topology, orientation and normals are checked by the geometry layer, which
/// names the file lines kept here in its messages.

#include <Eigen/Core>
#include <array>
#include <istream>
#include <string>
#include <vector>

namespace iga {

/// A triangle mesh in 3D as read from a file, before any validation.
struct SurfaceMeshFile {
  std::string source;                          ///< file name, for messages
  std::vector<Eigen::Vector3d> points;         ///< vertex positions
  std::vector<int> point_lines;                ///< file line of each vertex
  std::vector<std::array<int, 3>> triangles;   ///< 0-based vertex indices, in file order
  std::vector<int> triangle_lines;             ///< file line of each triangle
  std::vector<Eigen::Vector3d> normals;        ///< one per vertex (from OBJ `vn`), or empty
};

/// Wavefront OBJ from `in`; `source` names the file in messages ("<source>:<line>: ...").
/// Faces must be triangles. Normals are taken when every face corner names one (`i//n`, `i/t/n`);
/// the corners of one vertex must then agree (a vertex has one tangent plane).
SurfaceMeshFile read_obj_surface(std::istream& in, const std::string& source);

/// Object File Format (OFF) from `in`; faces must be triangles. OFF carries no normals.
SurfaceMeshFile read_off_surface(std::istream& in, const std::string& source);

/// Reads `path` by its extension (.obj or .off, any case); InputError for anything else.
SurfaceMeshFile read_surface_mesh(const std::string& path);

}  // namespace iga
