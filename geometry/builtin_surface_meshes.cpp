#include "geometry/builtin_surface_meshes.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <map>

#include "config/errors.hpp"

namespace iga {

namespace {

/// Orients every triangle of a mesh star-shaped about the origin so that it faces outward.
void orient_outward(TriangleSurfaceMesh& mesh) {
  for (auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.points[t[0]];
    const Eigen::Vector3d normal = (mesh.points[t[1]] - a).cross(mesh.points[t[2]] - a);
    if (normal.dot(a + mesh.points[t[1]] + mesh.points[t[2]]) < 0) std::swap(t[1], t[2]);
  }
}

std::vector<Eigen::Vector3d> unit_points(const std::vector<Eigen::Vector3d>& p) {
  std::vector<Eigen::Vector3d> n;
  for (const auto& x : p) n.push_back(x.normalized());
  return n;
}

}  // namespace

std::vector<Eigen::Vector3d> fan_normals(const TriangleSurfaceMesh& mesh) {
  std::vector<Eigen::Vector3d> sum(mesh.points.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d& p = mesh.points[t[c]];
      sum[t[c]] += (mesh.points[t[(c + 1) % 3]] - p).cross(mesh.points[t[(c + 2) % 3]] - p);
    }
  for (std::size_t v = 0; v < sum.size(); ++v) {
    if (!(sum[v].norm() > 0))
      throw InputError(mesh.source + ": " + mesh.vertex_name(static_cast<int>(v)) + ": the fan normal vanishes");
    sum[v].normalize();
  }
  return sum;
}

TriangleSurfaceMesh icosphere(int level) {
  if (level < 0 || level > 8) throw InputError("icosphere: level must be in 0..8, got " + std::to_string(level));
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSurfaceMesh mesh;
  mesh.source = "icosphere level " + std::to_string(level);
  for (const auto& p : std::vector<Eigen::Vector3d>{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t},
                                                    {0, 1, t}, {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1},
                                                    {-t, 0, -1}, {-t, 0, 1}})
    mesh.points.push_back(p.normalized());
  mesh.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
      const auto found = midpoint.find(key);
      if (found != midpoint.end()) return found->second;
      mesh.points.push_back((mesh.points[a] + mesh.points[b]).normalized());
      return midpoint[key] = static_cast<int>(mesh.points.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : mesh.triangles) {
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
  orient_outward(mesh);
  mesh.normals = unit_points(mesh.points);
  return mesh;
}

TriangleSurfaceMesh regular_octahedron() {
  TriangleSurfaceMesh mesh;
  mesh.source = "regular octahedron";
  mesh.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int a : {0, 1})
    for (int b : {2, 3})
      for (int c : {4, 5}) mesh.triangles.push_back({a, b, c});
  orient_outward(mesh);
  mesh.normals = unit_points(mesh.points);
  return mesh;
}

TriangleSurfaceMesh regular_tetrahedron() {
  TriangleSurfaceMesh mesh;
  mesh.source = "regular tetrahedron";
  mesh.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  mesh.normals = fan_normals(mesh);
  return mesh;
}

TriangleSurfaceMesh perturbed_octahedron() {
  TriangleSurfaceMesh mesh;
  mesh.source = "perturbed octahedron";
  mesh.points = {{1.1, -0.1, 0.2}, {-1.1, 0.3, 0.2}, {0.3, 1.2, 0.2},
                 {0.1, -1.3, 0.3}, {0.0, 0.3, 0.8},  {0.2, -0.3, -1.2}};
  mesh.triangles = {{0, 2, 4}, {0, 5, 2}, {0, 4, 3}, {0, 3, 5}, {1, 4, 2}, {1, 2, 5}, {1, 3, 4}, {1, 5, 3}};
  mesh.normals = fan_normals(mesh);
  return mesh;
}

TriangleSurfaceMesh height_field() {
  TriangleSurfaceMesh mesh;
  mesh.source = "height field";
  const double xs[4] = {-0.75, -0.25, 0.25, 0.75};
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const double x = xs[a], y = xs[b];
      mesh.points.emplace_back(x, y, x * x / 2 - y * y / 3 + x * y / 5);
      mesh.normals.push_back(Eigen::Vector3d(-(x + y / 5), -(-2 * y / 3 + x / 5), 1).normalized());
    }
  auto id = [](int a, int b) { return a + 4 * b; };
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < 3; ++a) {
      const int p00 = id(a, b), p10 = id(a + 1, b), p01 = id(a, b + 1), p11 = id(a + 1, b + 1);
      if ((a + b) % 2 == 0) {  // diagonal from (a, b) to (a+1, b+1)
        mesh.triangles.push_back({p00, p10, p11});
        mesh.triangles.push_back({p00, p11, p01});
      } else {  // diagonal from (a+1, b) to (a, b+1)
        mesh.triangles.push_back({p00, p10, p01});
        mesh.triangles.push_back({p10, p11, p01});
      }
    }
  return mesh;
}

}  // namespace iga
