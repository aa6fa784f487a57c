#pragma once
/// @file
/// Resource limits for meshing and mesh files: what one mesh may cost before it is refused. The
/// defaults fit a workstation; a config may raise them (passed down to read_mesh_file and
/// mesh_polygon).

#include <cstddef>
#include <string>

namespace iga {

struct MeshLimits {
  /// Largest number of 2D elements a mesh may have: a .msh file's element count, or the estimate
  /// area / (sqrt(3)/4 h²) for a .geo meshed with `mesh_size` h or a polygon, checked before meshing
  /// (a .geo's own sizes are refused above 8 times this: gmsh_job.cpp says why).
  double max_elements = 2e6;
  /// Wall-clock and CPU time of one Gmsh run (open and mesh), in seconds.
  double seconds = 120.0;
  /// Address space of the Gmsh worker process, in bytes.
  std::size_t memory_bytes = std::size_t{8} << 30;
  /// Largest iteration count of one For loop or {a:b:step} range in a .geo script (when its bounds
  /// can be evaluated before Gmsh runs).
  double max_loop_iterations = 1e6;
};

/// Triangles of side h covering `area` (equilateral: area / (sqrt(3)/4 h²)), the element
/// estimate compared with MeshLimits::max_elements before meshing.
double estimated_triangles(double area, double h);

/// InputError "<source>: mesh size h on an area of A gives about N triangles, more than the limit
/// of M elements ..." when estimated_triangles(area, h) exceeds limits.max_elements (or is NaN).
void check_element_estimate(double area, double h, const MeshLimits& limits, const std::string& source);

}  // namespace iga
