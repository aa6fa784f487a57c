#include "geometry/triangle_surface_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "config/errors.hpp"

namespace iga {

[[noreturn]] void reject_surface_mesh(const TriangleSurfaceMesh& mesh, const std::string& message) {
  throw InputError(mesh.source + ": " + message);
}

namespace {

/// " (line 12)" when the file line is known, "" for built-in meshes (messages start with the source).
std::string located(const std::vector<int>& lines, int index) {
  if (index >= 0 && index < static_cast<int>(lines.size())) return " (line " + std::to_string(lines[index]) + ")";
  return "";
}


std::string edge_name(const TriangleSurfaceMesh& mesh, int a, int b) {
  return "edge (" + std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + ") between " +
         mesh.vertex_name(std::min(a, b)) + " and " + mesh.vertex_name(std::max(a, b));
}

}  // namespace

std::string TriangleSurfaceMesh::vertex_name(int v) const {
  if (v >= 0 && v < static_cast<int>(point_origins.size())) return "vertex " + std::to_string(v) + " (" + point_origins[v] + ")";
  return "vertex " + std::to_string(v) + located(point_lines, v);
}

std::string TriangleSurfaceMesh::triangle_name(int n) const {
  if (n >= 0 && n < static_cast<int>(triangle_origins.size()))
    return "triangle " + std::to_string(n) + " (" + triangle_origins[n] + ")";
  return "triangle " + std::to_string(n) + located(triangle_lines, n);
}

std::vector<SurfaceEdge> surface_edges(const TriangleSurfaceMesh& mesh) {
  // Directed half-edges a→b of each triangle; an edge is shared by at most two triangles that
  // traverse it in opposite directions.
  struct Use {
    int triangle, opposite;
    bool forward;  // traversed from the smaller to the larger vertex
  };
  std::map<std::pair<int, int>, std::vector<Use>> uses;
  for (int n = 0; n < mesh.num_triangles(); ++n) {
    const auto& t = mesh.triangles[n];
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3], o = t[(c + 2) % 3];
      uses[{std::min(a, b), std::max(a, b)}].push_back({n, o, a < b});
    }
  }
  std::vector<SurfaceEdge> interior, boundary;
  for (const auto& [key, list] : uses) {
    SurfaceEdge e;
    e.i = key.first;
    e.j = key.second;
    if (list.size() > 2)
      reject_surface_mesh(mesh, edge_name(mesh, e.i, e.j) + " is shared by " + std::to_string(list.size()) + " triangles (" +
                     mesh.triangle_name(list[0].triangle) + ", " + mesh.triangle_name(list[1].triangle) + ", " +
                     mesh.triangle_name(list[2].triangle) + "); a surface mesh must be manifold");
    e.n = list[0].triangle;
    e.k = list[0].opposite;
    if (list.size() == 2) {
      if (list[0].forward == list[1].forward)
        reject_surface_mesh(mesh, edge_name(mesh, e.i, e.j) + ": " + mesh.triangle_name(list[0].triangle) + " and " +
                       mesh.triangle_name(list[1].triangle) +
                       " traverse it in the same direction (inconsistent orientation)");
      e.nbar = list[1].triangle;
      e.kbar = list[1].opposite;
      if (e.kbar == e.k)
        reject_surface_mesh(mesh, edge_name(mesh, e.i, e.j) + ": " + mesh.triangle_name(e.n) + " and " + mesh.triangle_name(e.nbar) +
                       " are the same triangle twice");
      interior.push_back(e);
    } else {
      boundary.push_back(e);
    }
  }
  interior.insert(interior.end(), boundary.begin(), boundary.end());
  return interior;
}

std::vector<Eigen::Vector3d> angle_weighted_normals(const TriangleSurfaceMesh& mesh) {
  std::vector<Eigen::Vector3d> sum(mesh.points.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d face =
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).normalized();
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d a = mesh.points[t[(c + 1) % 3]] - mesh.points[t[c]];
      const Eigen::Vector3d b = mesh.points[t[(c + 2) % 3]] - mesh.points[t[c]];
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      sum[t[c]] += angle * face;
    }
  }
  std::vector<Eigen::Vector3d> normals(sum.size());
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const double length = sum[v].norm();
    if (!(length > 1e-12))
      reject_surface_mesh(mesh, mesh.vertex_name(static_cast<int>(v)) +
                     ": the triangle normals around it cancel; give normals in the file");
    normals[v] = sum[v] / length;
  }
  return normals;
}

void validate_surface_mesh(const TriangleSurfaceMesh& mesh) {
  if (mesh.triangles.empty()) reject_surface_mesh(mesh, "the surface mesh has no triangles");
  std::vector<int> used(mesh.points.size(), 0);
  for (int n = 0; n < mesh.num_triangles(); ++n) {
    const auto& t = mesh.triangles[n];
    for (int c = 0; c < 3; ++c)
      if (t[c] < 0 || t[c] >= mesh.num_points())
        reject_surface_mesh(mesh, mesh.triangle_name(n) + " names vertex " + std::to_string(t[c]) + ", which does not exist");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      reject_surface_mesh(mesh, mesh.triangle_name(n) + " repeats a vertex");
    const Eigen::Vector3d a = mesh.points[t[1]] - mesh.points[t[0]];
    const Eigen::Vector3d b = mesh.points[t[2]] - mesh.points[t[0]];
    const Eigen::Vector3d c = mesh.points[t[2]] - mesh.points[t[1]];
    const double longest = std::max({a.squaredNorm(), b.squaredNorm(), c.squaredNorm()});
    // Twice the area against the squared longest edge: zero for collinear vertices.
    if (!(a.cross(b).norm() > 1e-12 * longest))
      reject_surface_mesh(mesh, mesh.triangle_name(n) + " with vertices " + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                     ", " + std::to_string(t[2]) + " has zero area");
    for (int v : t) ++used[v];
  }
  for (int v = 0; v < mesh.num_points(); ++v)
    if (!used[v]) reject_surface_mesh(mesh, mesh.vertex_name(v) + " belongs to no triangle");
  if (mesh.normals.size() != mesh.points.size()) reject_surface_mesh(mesh, "one normal per vertex is required");
  for (int v = 0; v < mesh.num_points(); ++v)
    if (std::abs(mesh.normals[v].norm() - 1.0) > 1e-12)
      reject_surface_mesh(mesh, mesh.vertex_name(v) + " has no unit normal");
  surface_edges(mesh);  // manifold and orientation checks
}

TriangleSurfaceMesh surface_mesh_from_file(const SurfaceMeshFile& file) {
  TriangleSurfaceMesh mesh;
  mesh.source = file.source;
  mesh.points = file.points;
  mesh.triangles = file.triangles;
  mesh.point_lines = file.point_lines;
  mesh.triangle_lines = file.triangle_lines;
  mesh.point_origins = file.point_origins;
  mesh.triangle_origins = file.triangle_origins;
  // Normals are checked last: estimating them needs the topology checks first.
  mesh.normals.assign(mesh.points.size(), Eigen::Vector3d::UnitZ());
  validate_surface_mesh(mesh);
  if (file.normals.empty()) {
    mesh.normals = angle_weighted_normals(mesh);
  } else {
    mesh.normals = file.normals;
    for (auto& n : mesh.normals) n.normalize();
  }
  validate_surface_mesh(mesh);
  return mesh;
}

}  // namespace iga
