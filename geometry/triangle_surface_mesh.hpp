#pragma once
/// @file
/// A validated manifold triangle mesh in 3D with one unit normal per vertex, and its edge table.
/// This is the input of the smooth-surface constructions (geometry/rsd/).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "mesh/read_surface_mesh.hpp"

namespace iga {

/// Triangles of a manifold, consistently oriented surface mesh, with unit vertex normals.
struct TriangleSurfaceMesh {
  std::string source;                         ///< file name or built-in name, for messages
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;  ///< counterclockwise seen from the normal side
  std::vector<Eigen::Vector3d> normals;       ///< unit, one per vertex
  std::vector<int> point_lines;               ///< file line per vertex (empty for built-ins)
  std::vector<int> triangle_lines;            ///< file line per triangle (empty for built-ins)
  std::vector<std::string> point_origins, triangle_origins;  ///< Gmsh tags as names (Gmsh meshes only)

  int num_points() const { return static_cast<int>(points.size()); }
  int num_triangles() const { return static_cast<int>(triangles.size()); }
  /// "vertex 7 (line 9)", "vertex 7 (Gmsh node 12)", or "vertex 7" for a built-in mesh: how messages name a vertex (the
  /// messages begin with `source`).
  std::string vertex_name(int v) const;
  /// "triangle 3 (line 21)": how messages name a triangle.
  std::string triangle_name(int n) const;
};

/// An edge {i, j} with i < j, its triangle(s) and their third vertices. A boundary (single) edge
/// has `nbar == -1`.
struct SurfaceEdge {
  int i = -1, j = -1;   ///< end vertices, i < j
  int n = -1, k = -1;   ///< first triangle (smaller index) and its vertex opposite the edge
  int nbar = -1, kbar = -1;  ///< second triangle and its opposite vertex; -1 on a boundary edge
  bool interior() const { return nbar >= 0; }
};

/// The edges of `mesh`, interior (double) edges first, each group sorted by (i, j).
/// InputError naming the edge for an edge in three or more triangles (non-manifold) and for two
/// triangles traversing a shared edge in the same direction (inconsistent orientation).
std::vector<SurfaceEdge> surface_edges(const TriangleSurfaceMesh& mesh);

/// Angle-weighted vertex normals (each incident triangle's unit normal times its corner angle),
/// normalised. Needs a consistently oriented mesh; InputError when the weights cancel at a vertex.
std::vector<Eigen::Vector3d> angle_weighted_normals(const TriangleSurfaceMesh& mesh);

/// Checks a mesh: indices in range, no repeated vertex in a triangle, no zero-area triangle
/// (relative to its longest edge), every vertex used, manifold and consistently oriented edges,
/// one unit normal per vertex. InputError naming the vertex, edge or triangle (and file line).
void validate_surface_mesh(const TriangleSurfaceMesh& mesh);

/// Throws InputError naming the mesh's source: `message` is what is wrong with it.
[[noreturn]] void reject_surface_mesh(const TriangleSurfaceMesh& mesh, const std::string& message);

/// A validated mesh from a file read by read_surface_mesh: the file's normals when it has them,
/// angle-weighted normals otherwise.
TriangleSurfaceMesh surface_mesh_from_file(const SurfaceMeshFile& file);

}  // namespace iga
