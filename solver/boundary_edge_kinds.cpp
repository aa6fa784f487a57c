#include "solver/boundary_edge_kinds.hpp"

#include <map>

namespace iga {

std::vector<std::pair<BoundaryEdge, BoundaryKind>> boundary_edge_kinds(const Space& space, const ProblemSpec& problem) {
  std::map<std::pair<int, int>, BoundaryKind> kind_of_edge;
  for (const BoundaryPart& part : problem.boundary)
    for (const BoundaryEdge& e : space.boundary_edges(part.name)) kind_of_edge[{e.element, e.local_edge}] = part.kind;
  std::vector<std::pair<BoundaryEdge, BoundaryKind>> out;
  for (const auto& [key, kind] : kind_of_edge) out.push_back({BoundaryEdge{key.first, key.second}, kind});
  return out;
}

std::vector<BoundaryEdge> boundary_edges_of_kind(const Space& space, const ProblemSpec& problem, BoundaryKind kind) {
  std::vector<BoundaryEdge> out;
  for (const auto& [edge, k] : boundary_edge_kinds(space, problem))
    if (k == kind) out.push_back(edge);
  return out;
}

}  // namespace iga
