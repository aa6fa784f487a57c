#include "mesh/validate_quad_surface.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "mesh/coincident_points.hpp"
#include "mesh/validate_planar_mesh.hpp"

namespace iga {

namespace {

[[noreturn]] void reject(const QuadSurfaceFile& mesh, const std::string& message) {
  throw InputError(mesh.source + ": " + message);
}

/// "face 3 (line 12)", numbered from 1 as OBJ and OFF users count.
std::string face_name(const QuadSurfaceFile& mesh, std::size_t f) {
  std::string s = "face " + std::to_string(f + 1);
  if (f < mesh.quad_lines.size()) s += " (line " + std::to_string(mesh.quad_lines[f]) + ")";
  return s;
}

std::string point_text(const Eigen::Vector3d& x) {
  std::string s("(");  // appended, not "(" + string: GCC 12 warns wrongly (-Wrestrict) about that
  s += format_number(x.x()) + ", " + format_number(x.y()) + ", " + format_number(x.z()) + ")";
  return s;
}

void check_faces(const QuadSurfaceFile& mesh) {
  std::map<std::array<int, 4>, std::size_t> seen;
  for (std::size_t f = 0; f < mesh.quads.size(); ++f) {
    std::array<int, 4> key = mesh.quads[f];
    for (int v : key)
      if (v < 0 || v >= static_cast<int>(mesh.points.size()))
        reject(mesh, face_name(mesh, f) + " refers to vertex " + std::to_string(v + 1) + ", but the file has " +
                         std::to_string(mesh.points.size()) + " vertices");
    std::sort(key.begin(), key.end());
    if (std::adjacent_find(key.begin(), key.end()) != key.end())
      reject(mesh, face_name(mesh, f) + " uses a vertex twice");
    if (const auto [it, fresh] = seen.emplace(key, f); !fresh)
      reject(mesh, face_name(mesh, f) + " repeats " + face_name(mesh, it->second) + " (the same four vertices)");
  }
}

void check_shapes(const QuadSurfaceFile& mesh) {
  for (std::size_t f = 0; f < mesh.quads.size(); ++f) {
    const std::array<int, 4>& q = mesh.quads[f];
    const auto x = [&](int k) -> const Eigen::Vector3d& { return mesh.points[q[(k + 4) % 4]]; };
    double h = 0.0;
    for (int k = 0; k < 4; ++k) h = std::max(h, (x(k + 1) - x(k)).norm());
    // Vector area of a (possibly non-planar) quad: half the cross product of its diagonals.
    const Eigen::Vector3d area = 0.5 * (x(2) - x(0)).cross(x(3) - x(1));
    if (!(area.norm() > mesh_tolerance * h * h))
      reject(mesh, face_name(mesh, f) + " is degenerate (area " + format_number(area.norm()) + ", longest edge " +
                       format_number(h) + "): its corners are collinear or coincide");
    const Eigen::Vector3d normal = area.normalized();
    for (int k = 0; k < 4; ++k) {
      const double det = (x(k + 1) - x(k)).cross(x(k - 1) - x(k)).dot(normal);
      if (det <= mesh_tolerance * h * h)
        reject(mesh, face_name(mesh, f) + " is folded or not convex at corner " + point_text(x(k)) + " (vertex " +
                         std::to_string(q[k] + 1) + ")");
    }
  }
}

void check_coincident_vertices(const QuadSurfaceFile& mesh) {
  std::vector<int> used;
  for (const auto& q : mesh.quads) used.insert(used.end(), q.begin(), q.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (used.empty()) return;
  Eigen::Vector3d lo = mesh.points[used[0]], hi = lo;
  for (int v : used) lo = lo.cwiseMin(mesh.points[v]), hi = hi.cwiseMax(mesh.points[v]);
  const double eps = mesh_tolerance * (hi - lo).norm();
  if (const auto pair = find_coincident_points(mesh.points, used, eps, Closeness::distance))
    reject(mesh, "vertices " + std::to_string(pair->first + 1) + " and " + std::to_string(pair->second + 1) +
                     " coincide at " + point_text(mesh.points[pair->first]) +
                     "; merge them (faces meeting there are not connected)");
}

void check_edges(const QuadSurfaceFile& mesh) {
  // Orientation is not checked: the space glues faces listed either way round.
  std::map<std::pair<int, int>, std::vector<std::size_t>> uses;
  for (std::size_t f = 0; f < mesh.quads.size(); ++f)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.quads[f][k], b = mesh.quads[f][(k + 1) % 4];
      uses[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  for (const auto& [edge, faces] : uses)
    if (faces.size() > 2)
      reject(mesh, "the edge of vertices " + std::to_string(edge.first + 1) + " and " +
                       std::to_string(edge.second + 1) + " is shared by " + std::to_string(faces.size()) + " faces (" +
                       face_name(mesh, faces[0]) + ", " + face_name(mesh, faces[1]) + ", " + face_name(mesh, faces[2]) +
                       "): the surface is not a manifold");
}

}  // namespace

void validate_quad_surface(const QuadSurfaceFile& mesh) {
  check_faces(mesh);
  check_coincident_vertices(mesh);  // before the shapes: two corners at one place say more than a folded face
  check_shapes(mesh);
  check_edges(mesh);
}

}  // namespace iga
