#pragma once
/// @file
/// Readers of quad meshes in 3D (closed or open quad surfaces for the 4-split G1 space): Wavefront OBJ and
/// OFF whose faces are all quadrilaterals. They only parse; the geometry is checked by
/// validate_quad_surface (validate_quad_surface.hpp), the topology (at most two faces per edge) by the space,
/// which names the file in its messages.

#include <Eigen/Core>
#include <array>
#include <istream>
#include <string>
#include <vector>

namespace iga {

/// A quad mesh in 3D as read from a file, before any validation.
struct QuadSurfaceFile {
  std::string source;                       ///< file name, for messages
  std::vector<Eigen::Vector3d> points;      ///< vertex positions
  std::vector<std::array<int, 4>> quads;    ///< 0-based vertex indices, in file order
  std::vector<int> quad_lines;              ///< file line of each quad
};

/// Wavefront OBJ (`v x y z`, `f a b c d` with optional `/t/n` parts, which are ignored).
/// A face that is not a quad is an InputError naming its line.
QuadSurfaceFile read_obj_quad_surface(std::istream& in, const std::string& source);

/// Object File Format (OFF) with faces `4 a b c d`; other face sizes are refused.
QuadSurfaceFile read_off_quad_surface(std::istream& in, const std::string& source);

/// Reads `path` by its extension (.obj or .off, any case); InputError for anything else.
QuadSurfaceFile read_quad_surface_mesh(const std::string& path);

}  // namespace iga
