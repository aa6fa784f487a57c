#include "geometry/rsd/first_order_data.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "config/errors.hpp"

namespace iga::rsd {

namespace {

std::string edge_text(int i, int j) { return "edge (" + std::to_string(i) + ", " + std::to_string(j) + ")"; }

/// Signed angle from a to b about the axis n.
double signed_angle(const Eigen::Vector3d& n, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(n.dot(a.cross(b)), a.dot(b));
}

/// Orientation of g_ij → g_ik about n_i: +1, −1, or 0 when (nearly) parallel.
int side(const Eigen::Vector3d& n, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double s = n.dot(a.cross(b)) / (a.norm() * b.norm());
  return s > data_tolerance ? 1 : (s < -data_tolerance ? -1 : 0);
}

}  // namespace

FirstOrderData projected_chord_data(const TriangleSurfaceMesh& mesh, const std::vector<SurfaceEdge>& edges) {
  FirstOrderData data;
  data.f = mesh.points;
  data.n = mesh.normals;
  for (const auto& e : edges)
    for (const auto& [a, b] : {std::pair{e.i, e.j}, std::pair{e.j, e.i}}) {
      const Eigen::Vector3d chord = mesh.points[b] - mesh.points[a];
      const Eigen::Vector3d& n = mesh.normals[a];
      data.g_of(a, b) = chord - chord.dot(n) * n;
    }
  return data;
}

void check_data_conditions(const TriangleSurfaceMesh& mesh, const std::vector<SurfaceEdge>& edges,
                           const FirstOrderData& data) {
  for (const auto& e : edges)
    for (const auto& [a, b] : {std::pair{e.i, e.j}, std::pair{e.j, e.i}}) {
      const Eigen::Vector3d& g = data.g_of(a, b);
      if (!(g.norm() > 0))
        reject_surface_mesh(mesh, "the tangent g at " + mesh.vertex_name(a) + " towards vertex " + std::to_string(b) + " is zero");
      if (std::abs(g.dot(data.n[a])) > data_tolerance * g.norm())
        reject_surface_mesh(mesh, "condition (28) violated at " + mesh.vertex_name(a) + ": the tangent towards vertex " +
                       std::to_string(b) + " (" + edge_text(e.i, e.j) +
                       ") leaves the vertex tangent plane; no G1 surface interpolates such data");
    }
  for (int n = 0; n < mesh.num_triangles(); ++n) {
    const auto& t = mesh.triangles[n];
    for (int c = 0; c < 3; ++c) {
      const int i = t[c], j = t[(c + 1) % 3], k = t[(c + 2) % 3];
      if (side(data.n[i], data.g_of(i, j), data.g_of(i, k)) == 0)
        reject_surface_mesh(mesh, "condition (11) violated at " + mesh.vertex_name(i) + " in " + mesh.triangle_name(n) +
                       ": the tangents towards vertices " + std::to_string(j) + " and " + std::to_string(k) +
                       " are parallel (singular vertex)");
    }
  }
  // Fan winding: the corner angles of the tangent triangles around a vertex, measured in the
  // triangles' orientation, add up to ±2π at an interior vertex (less at a boundary vertex).
  std::vector<double> turning(mesh.points.size(), 0.0);
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) {
      const int i = t[c];
      turning[i] += signed_angle(data.n[i], data.g_of(i, t[(c + 1) % 3]), data.g_of(i, t[(c + 2) % 3]));
    }
  for (int v = 0; v < mesh.num_points(); ++v) {
    const double windings = std::abs(turning[v]) / (2 * M_PI);
    if (windings > 1.5)
      reject_surface_mesh(mesh, "the tangents at " + mesh.vertex_name(v) + " wind " + std::to_string(std::lround(windings)) +
                     " times around the normal (a branch point; the surface would not be embedded)");
  }
  for (const auto& e : edges) {
    if (!e.interior()) continue;
    for (const auto& [a, b] : {std::pair{e.i, e.j}, std::pair{e.j, e.i}}) {
      const Eigen::Vector3d& n = data.n[a];
      const int s1 = side(n, data.g_of(a, b), data.g_of(a, e.k));
      const int s2 = side(n, data.g_of(a, b), data.g_of(a, e.kbar));
      if (s1 == 0 || s2 == 0 || s1 == s2)
        reject_surface_mesh(mesh, "condition (12) violated at " + mesh.vertex_name(a) + " on " + edge_text(e.i, e.j) +
                       ": the tangents towards vertices " + std::to_string(e.k) + " and " + std::to_string(e.kbar) +
                       " are not on opposite sides of the edge tangent (the surface would fold)");
    }
  }
}

}  // namespace iga::rsd
