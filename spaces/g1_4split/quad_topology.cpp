#include "spaces/g1_4split/quad_topology.hpp"

#include <algorithm>
#include <map>

#include "config/errors.hpp"

namespace iga {

QuadTopology::QuadTopology(int num_vertices, std::vector<std::array<int, 4>> faces, std::string name)
    : num_vertices_(num_vertices), faces_(std::move(faces)), name_(std::move(name)) {
  std::map<std::pair<int, int>, int> ids;
  face_edges_.resize(faces_.size());
  vertex_boundary_.assign(num_vertices_, false);
  vertex_corners_.resize(num_vertices_);
  vertex_edges_.resize(num_vertices_);
  for (int f = 0; f < num_faces(); ++f) {
    const auto& q = faces_[f];
    for (int c = 0; c < 4; ++c) {
      if (q[c] < 0 || q[c] >= num_vertices_)
        throw InputError(name_ + ": face " + std::to_string(f) + " refers to a missing vertex");
      for (int d = 0; d < c; ++d)
        if (q[c] == q[d]) throw InputError(name_ + ": face " + std::to_string(f) + " repeats a corner vertex");
      vertex_corners_[q[c]].push_back({f, c});
    }
    for (int j = 0; j < 4; ++j) {
      const int a = q[j], b = q[(j + 1) % 4];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = ids.find(key);
      if (it == ids.end()) {
        it = ids.emplace(key, num_edges()).first;
        edges_.push_back(QuadEdge{key.first, key.second, {}});
        vertex_edges_[key.first].push_back(it->second);
        vertex_edges_[key.second].push_back(it->second);
      }
      QuadEdge& e = edges_[it->second];
      if (e.sides.size() == 2)
        throw InputError(name_ + ": the edge between vertices " + std::to_string(a) + " and " + std::to_string(b) +
                         " has more than two faces (non-manifold)");
      e.sides.push_back({f, j});
      face_edges_[f][j] = it->second;
    }
  }
  for (const QuadEdge& e : edges_)
    if (e.boundary()) vertex_boundary_[e.g0] = vertex_boundary_[e.g1] = true;
}

QuadTopology QuadTopology::refined() const {
  const int mid0 = num_vertices_, centre0 = num_vertices_ + num_edges();
  std::vector<std::array<int, 4>> faces;
  for (int f = 0; f < num_faces(); ++f) {
    const auto& q = faces_[f];
    for (int c = 0; c < 4; ++c)
      faces.push_back({q[c], mid0 + face_edges_[f][c], centre0 + f, mid0 + face_edges_[f][(c + 3) % 4]});
  }
  return QuadTopology(centre0 + num_faces(), std::move(faces), name_);
}

QuadTopology cube_topology() {
  // Vertices (x,y,z) in {0,1}^3 with id x + 2y + 4z; faces oriented outwards.
  return QuadTopology(8, {{{0, 2, 3, 1}}, {{4, 5, 7, 6}}, {{0, 1, 5, 4}}, {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}},
                      "cube");
}

QuadTopology split_tetrahedron_topology() {
  // Corners 0..3, edge mids 4..9, face centres 10..13; each triangle (a,b,c) gives 3 quads.
  const int tri[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::map<std::pair<int, int>, int> mid;
  int next = 4;
  auto m = [&](int a, int b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mid.find(key);
    if (it == mid.end()) it = mid.emplace(key, next++).first;
    return it->second;
  };
  std::vector<std::array<int, 4>> faces;
  for (int t = 0; t < 4; ++t) {
    const int c = 10 + t;
    for (int i = 0; i < 3; ++i) {
      const int a = tri[t][i], b = tri[t][(i + 1) % 3], p = tri[t][(i + 2) % 3];
      faces.push_back({a, m(a, b), c, m(p, a)});
    }
  }
  return QuadTopology(14, std::move(faces), "split tetrahedron");
}

}  // namespace iga
