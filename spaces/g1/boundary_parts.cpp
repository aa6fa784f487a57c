#include "spaces/g1/boundary_parts.hpp"

#include <algorithm>
#include <cmath>

namespace iga {

namespace {

const char* const kSides[4] = {"left", "right", "bottom", "top"};

/// Side index 0..3 of a boundary edge (as in kSides), or -1 when it lies on no side of the box.
int side_of(const PatchMesh& mesh, const MeshEdge& e, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  const double tol = 1e-10 * std::max((hi - lo).maxCoeff(), 1e-300);
  const Point2& a = mesh.vertex(e.x);
  const Point2& b = mesh.vertex(e.y);
  const double box[4] = {lo.x(), hi.x(), lo.y(), hi.y()};
  for (int s = 0; s < 4; ++s) {
    const int c = s < 2 ? 0 : 1;
    if (std::abs(a[c] - box[s]) <= tol && std::abs(b[c] - box[s]) <= tol) return s;
  }
  return -1;
}

/// Boundary edges of the mesh grouped by side; index 4 holds every boundary edge.
std::vector<std::vector<BoundaryEdge>> group(const PatchMesh& mesh) {
  Eigen::Vector2d lo = mesh.vertex(0), hi = mesh.vertex(0);
  for (int v = 1; v < mesh.num_vertices(); ++v) {
    lo = lo.cwiseMin(mesh.vertex(v));
    hi = hi.cwiseMax(mesh.vertex(v));
  }
  std::vector<std::vector<BoundaryEdge>> out(5);
  for (int i = 0; i < mesh.num_edges(); ++i) {
    const MeshEdge& e = mesh.edge(i);
    if (!e.boundary()) continue;
    const BoundaryEdge be{e.first.face, e.first.local_edge};
    out[4].push_back(be);
    const int s = side_of(mesh, e, lo, hi);
    if (s >= 0) out[s].push_back(be);
  }
  return out;
}

}  // namespace

void set_boundary_parts(const PatchMesh& mesh, SpaceFacts& facts) {
  auto g = group(mesh);
  facts.all_boundary_edges = g[4];
  if (!mesh.boundary_groups().empty()) {
    for (const auto& [name, ends] : mesh.boundary_groups()) {
      std::vector<BoundaryEdge> edges;
      for (const auto& [a, b] : ends) {
        const MeshEdge& e = mesh.edge(mesh.find_edge(a, b));
        edges.push_back({e.first.face, e.first.local_edge});
      }
      facts.boundary_parts.emplace_back(name, std::move(edges));
    }
  } else {
    for (int s = 0; s < 4; ++s)
      if (!g[s].empty()) facts.boundary_parts.emplace_back(kSides[s], std::move(g[s]));
  }
}

}  // namespace iga
