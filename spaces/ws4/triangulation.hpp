#pragma once
/// @file
/// Triangulation: a conforming planar triangle mesh with its edges (globally oriented from the
/// lower to the higher vertex id) and named boundary parts. The mesh of a WS4 space.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "quadrature/quadrature_rule.hpp"

namespace iga::ws4 {

class Triangulation {
 public:
  /// Triangles are vertex index triples, counterclockwise (std::invalid_argument otherwise, or when
  /// an edge has more than two triangles). `part_of` gives the index in `part_names` of a boundary
  /// edge from its endpoint ids (a < b); it is called once per boundary edge.
  Triangulation(std::vector<Point2> vertices, std::vector<std::array<int, 3>> triangles,
                std::vector<std::string> part_names, const std::function<int(int a, int b)>& part_of);

  /// N_x x N_y rectangle [lo, hi] of squares, square (i, j) split by the diagonal (i,j)-(i+1,j+1)
  /// when i + j is even and by (i+1,j)-(i,j+1) otherwise (WS4 notes §10). Boundary parts bottom,
  /// right, top, left.
  static Triangulation rectangle(int nx, int ny, const Point2& lo, const Point2& hi);

  /// Uniform refinement: every triangle split into 4 by its edge midpoints; boundary parts kept.
  Triangulation refined() const;

  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  int num_triangles() const { return static_cast<int>(triangles_.size()); }
  int num_edges() const { return static_cast<int>(edges_.size()); }
  const std::vector<Point2>& vertices() const { return vertices_; }
  /// Move vertex v (e.g. to perturb a mesh in tests); edges and parts are unchanged.
  void move_vertex(int v, const Point2& x) { vertices_.at(v) = x; }
  const std::array<int, 3>& triangle(int t) const { return triangles_[t]; }
  /// Global edge of local edge k of triangle t (local edge k joins local vertices k and k+1).
  int triangle_edge(int t, int k) const { return triangle_edges_[t][k]; }
  /// Endpoints (a, b) of edge e with a < b: the global orientation of the edge.
  const std::array<int, 2>& edge(int e) const { return edges_[e]; }
  /// The triangles on each side of edge e (second = -1 on the boundary), with their local edge.
  const std::array<int, 2>& edge_triangles(int e) const { return edge_triangles_[e]; }
  bool is_boundary_edge(int e) const { return edge_triangles_[e][1] < 0; }

  const std::vector<std::string>& part_names() const { return part_names_; }
  /// Part index of each edge (-1 for interior edges).
  int edge_part(int e) const { return edge_part_[e]; }

 private:
  std::vector<Point2> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 3>> triangle_edges_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<std::array<int, 2>> edge_triangles_;
  std::vector<std::string> part_names_;
  std::vector<int> edge_part_;
};

}  // namespace iga::ws4
