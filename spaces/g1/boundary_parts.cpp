#include "spaces/g1/boundary_parts.hpp"

#include <algorithm>
#include <cmath>

#include "config/errors.hpp"

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

std::vector<std::string> boundary_part_names(const PatchMesh& mesh) {
  if (!mesh.boundary_groups().empty()) {
    std::vector<std::string> names;
    for (const auto& [name, edges] : mesh.boundary_groups()) names.push_back(name);
    return names;
  }
  const auto g = group(mesh);
  std::vector<std::string> names;
  for (int s = 0; s < 4; ++s)
    if (!g[s].empty()) names.push_back(kSides[s]);
  return names;
}

std::vector<BoundaryEdge> boundary_part_edges(const PatchMesh& mesh, const std::string& name) {
  auto g = group(mesh);
  if (name == "all") return g[4];
  if (!mesh.boundary_groups().empty()) {
    const auto it = mesh.boundary_groups().find(name);
    if (it != mesh.boundary_groups().end()) {
      std::vector<BoundaryEdge> out;
      for (const auto& [a, b] : it->second) {
        const MeshEdge& e = mesh.edge(mesh.find_edge(a, b));
        out.push_back({e.first.face, e.first.local_edge});
      }
      return out;
    }
  } else {
    for (int s = 0; s < 4; ++s)
      if (name == kSides[s] && !g[s].empty()) return g[s];
  }
  std::string valid = "all";
  for (const std::string& n : boundary_part_names(mesh)) valid += ", " + n;
  throw InputError("unknown boundary '" + name + "' of multipatch domain '" + mesh.name() + "' (valid: " + valid + ")");
}

void set_boundary_parts(const PatchMesh& mesh, SpaceFacts& facts) {
  facts.all_boundary_edges = boundary_part_edges(mesh, "all");
  for (const std::string& name : boundary_part_names(mesh))
    facts.boundary_parts.emplace_back(name, boundary_part_edges(mesh, name));
}

}  // namespace iga
