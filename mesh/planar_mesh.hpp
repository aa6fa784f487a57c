#pragma once
/// @file
/// PlanarMesh: a planar mesh of triangles and quadrilaterals as read from a file (Gmsh, OBJ, OFF),
/// before any space builds its own topology from it. Shared by every space that reads mesh files.

#include <Eigen/Core>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace iga {

struct PlanarMesh {
  /// Vertex coordinates (z dropped: readers check that the file is planar).
  std::vector<Eigen::Vector2d> vertices;
  /// Cells as vertex ids, 3 (triangle) or 4 (quadrilateral) each; the readers orient every cell
  /// counterclockwise (a clockwise cell is reversed, see read_mesh_file.hpp).
  std::vector<std::vector<int>> cells;
  /// Named boundary edges (vertex id pairs), e.g. Gmsh physical curves; may be empty.
  std::map<std::string, std::vector<std::array<int, 2>>> boundary_groups;
  /// Where the mesh came from (file name), for messages.
  std::string source;
  /// Optional, one per cell: where the cell was read ("line 12", "Gmsh element 57"), for messages.
  std::vector<std::string> cell_origins;
};

/// Twice the signed area of cell `c` (shoelace; > 0 for counterclockwise).
double twice_signed_area(const PlanarMesh& mesh, int c);

/// Reverses every cell with negative signed area, keeping its first vertex.
void orient_cells_counterclockwise(PlanarMesh& mesh);

/// For files that list cells one by one (OBJ, OFF): every cell must turn the same way as the
/// first non-degenerate one (an InputError names the first that does not — inconsistent
/// orientation is a broken export); a mesh listed clockwise throughout is then reversed.
void orient_consistently_counterclockwise(PlanarMesh& mesh);

/// The edges used by exactly one cell, each as that cell traverses it (domain on the left for
/// counterclockwise cells), in cell order.
std::vector<std::array<int, 2>> boundary_edges(const PlanarMesh& mesh);

/// "cell 7 (line 12: triangle (0, 0), (1, 0), (0.5, 0))": the cell, where it was read and its
/// corners, for messages.
std::string describe_cell(const PlanarMesh& mesh, int c);

/// "(0.5, 0.25)": a point for messages.
std::string describe_point(const Eigen::Vector2d& x);

}  // namespace iga
