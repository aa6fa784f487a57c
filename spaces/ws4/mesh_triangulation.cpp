#include "spaces/ws4/mesh_triangulation.hpp"

#include <map>

#include "config/errors.hpp"
#include "mesh/validate_planar_mesh.hpp"

namespace iga::ws4 {

Triangulation triangulation_from_mesh(const PlanarMesh& mesh) {
  validate_planar_mesh(mesh, {true, false, "ws4"});
  std::vector<std::string> names;
  std::map<std::pair<int, int>, int> part_of_edge;  // (min, max) vertex ids -> part
  for (const auto& [name, edges] : mesh.boundary_groups) {
    if (name == "all")
      throw InputError(mesh.source + ": boundary group name 'all' is reserved (every boundary edge); rename it");
    const int part = static_cast<int>(names.size());
    names.push_back(name);
    for (const auto& e : edges) {
      const auto [it, fresh] = part_of_edge.emplace(std::make_pair(std::min(e[0], e[1]), std::max(e[0], e[1])), part);
      if (!fresh && it->second != part)
        throw InputError(mesh.source + ": boundary edge " + describe_point(mesh.vertices[e[0]]) + "-" +
                         describe_point(mesh.vertices[e[1]]) + " is in both groups '" + names[it->second] + "' and '" +
                         name + "'; a WS4 boundary edge belongs to one named part");
    }
  }
  std::vector<Point2> vertices(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<std::array<int, 3>> triangles;
  for (const auto& cell : mesh.cells) triangles.push_back({cell[0], cell[1], cell[2]});
  auto part = [&part_of_edge](int a, int b) {
    const auto it = part_of_edge.find({a, b});
    return it == part_of_edge.end() ? -1 : it->second;
  };
  return Triangulation(std::move(vertices), std::move(triangles), std::move(names), part);
}

PlanarMesh l_shape_mesh(int n) {
  // The checkerboard-split grid of [-1,1]² without the triangles of the removed quarter; the
  // vertices that only those used are dropped.
  const Triangulation square = Triangulation::rectangle(2 * n, 2 * n, Point2(-1, -1), Point2(1, 1));
  PlanarMesh mesh;
  mesh.source = "l_shape";
  std::vector<int> id(square.num_vertices(), -1);
  for (int t = 0; t < square.num_triangles(); ++t) {
    const auto& corners = square.triangle(t);
    Point2 centroid = Point2::Zero();
    for (int v : corners) centroid += square.vertices()[v] / 3.0;
    if (centroid.x() > 0.0 && centroid.y() < 0.0) continue;
    std::vector<int> cell;
    for (int v : corners) {
      if (id[v] < 0) {
        id[v] = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back(square.vertices()[v]);
      }
      cell.push_back(id[v]);
    }
    mesh.cells.push_back(std::move(cell));
  }
  for (const auto& e : boundary_edges(mesh)) {
    const Eigen::Vector2d &p = mesh.vertices[e[0]], &q = mesh.vertices[e[1]];
    const std::string side = p.x() == -1 && q.x() == -1   ? "left"
                             : p.x() == 1 && q.x() == 1   ? "right"
                             : p.y() == -1 && q.y() == -1 ? "bottom"
                             : p.y() == 1 && q.y() == 1   ? "top"
                                                          : "reentrant";
    mesh.boundary_groups[side].push_back(e);
  }
  return mesh;
}

}  // namespace iga::ws4
