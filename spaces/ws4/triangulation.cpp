#include "spaces/ws4/triangulation.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace iga::ws4 {

Triangulation::Triangulation(std::vector<Point2> vertices, std::vector<std::array<int, 3>> triangles,
                             std::vector<std::string> part_names, const std::function<int(int, int)>& part_of)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), part_names_(std::move(part_names)) {
  std::map<std::pair<int, int>, int> edge_id;
  triangle_edges_.resize(triangles_.size());
  for (int t = 0; t < num_triangles(); ++t) {
    const auto& v = triangles_[t];
    const Point2 e1 = vertices_.at(v[1]) - vertices_.at(v[0]), e2 = vertices_.at(v[2]) - vertices_.at(v[0]);
    if (!(e1.x() * e2.y() - e1.y() * e2.x() > 0.0))
      throw std::invalid_argument("Triangulation: triangle " + std::to_string(t) + " is not counterclockwise");
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(v[k], v[(k + 1) % 3]), b = std::max(v[k], v[(k + 1) % 3]);
      auto [it, fresh] = edge_id.emplace(std::make_pair(a, b), num_edges());
      if (fresh) {
        edges_.push_back({a, b});
        edge_triangles_.push_back({t, -1});
      } else {
        if (edge_triangles_[it->second][1] >= 0)
          throw std::invalid_argument("Triangulation: edge with more than two triangles");
        edge_triangles_[it->second][1] = t;
      }
      triangle_edges_[t][k] = it->second;
    }
  }
  edge_part_.assign(edges_.size(), -1);
  for (int e = 0; e < num_edges(); ++e)
    if (is_boundary_edge(e)) edge_part_[e] = part_of(edges_[e][0], edges_[e][1]);
}

Triangulation Triangulation::rectangle(int nx, int ny, const Point2& lo, const Point2& hi) {
  std::vector<Point2> v;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      v.emplace_back(lo.x() + (hi.x() - lo.x()) * i / nx, lo.y() + (hi.y() - lo.y()) * j / ny);
  auto id = [&](int i, int j) { return i + j * (nx + 1); };
  std::vector<std::array<int, 3>> t;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        t.push_back({a, b, c});
        t.push_back({a, c, d});
      } else {
        t.push_back({a, b, d});
        t.push_back({b, c, d});
      }
    }
  // Side of a boundary edge from its grid coordinates (both endpoints on the same side).
  auto part = [nx, ny](int a, int b) {
    const int ia = a % (nx + 1), ja = a / (nx + 1), ib = b % (nx + 1), jb = b / (nx + 1);
    if (ja == 0 && jb == 0) return 0;
    if (ia == nx && ib == nx) return 1;
    if (ja == ny && jb == ny) return 2;
    return 3;
  };
  return Triangulation(std::move(v), std::move(t), {"bottom", "right", "top", "left"}, part);
}

Triangulation Triangulation::refined() const {
  std::vector<Point2> v = vertices_;
  const int nv = num_vertices();
  for (const auto& e : edges_) v.push_back(0.5 * (vertices_[e[0]] + vertices_[e[1]]));
  std::vector<std::array<int, 3>> t;
  for (int k = 0; k < num_triangles(); ++k) {
    const auto& p = triangles_[k];
    const int m0 = nv + triangle_edges_[k][0], m1 = nv + triangle_edges_[k][1], m2 = nv + triangle_edges_[k][2];
    t.push_back({p[0], m0, m2});
    t.push_back({m0, p[1], m1});
    t.push_back({m2, m1, p[2]});
    t.push_back({m0, m1, m2});
  }
  // A boundary child edge joins an old vertex and the midpoint of its parent edge.
  const std::vector<int> parent_part = edge_part_;
  auto part = [nv, &parent_part](int a, int b) { return parent_part[std::max(a, b) - nv]; };
  return Triangulation(std::move(v), std::move(t), part_names_, part);
}

}  // namespace iga::ws4
