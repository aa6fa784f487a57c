#include "solver/boundary_edge_kinds.hpp"

#include <map>
#include <utility>

#include "config/errors.hpp"

namespace iga {

namespace {
/// Every boundary edge once, ordered by (element, local edge), with its condition.
std::vector<std::pair<BoundaryEdge, BoundaryKind>> boundary_edge_kinds(const Space& space, const ProblemSpec& problem) {
  std::map<std::pair<int, int>, BoundaryKind> kind_of_edge;
  for (const BoundaryPart& part : problem.boundary)
    for (const BoundaryEdge& e : space.boundary_edges(part.name)) kind_of_edge[{e.element, e.local_edge}] = part.kind;
  std::vector<std::pair<BoundaryEdge, BoundaryKind>> out;
  for (const auto& [key, kind] : kind_of_edge) out.push_back({BoundaryEdge{key.first, key.second}, kind});
  return out;
}
}  // namespace

BoundarySplit split_boundary(const Space& space, const ProblemSpec& problem) {
  BoundarySplit split;
  for (const auto& [e, kind] : boundary_edge_kinds(space, problem)) {
    if (kind != BoundaryKind::neumann) split.essential.value_edges.push_back(e);
    if (kind == BoundaryKind::clamped) split.essential.normal_edges.push_back(e);
    if (kind == BoundaryKind::neumann) split.neumann.push_back(e);
    if (kind == BoundaryKind::simply_supported) split.simply_supported.push_back(e);
  }
  if (split.essential.value_edges.empty())
    throw InputError("problem.boundary: a pure Neumann problem has no unique solution; make at least one part dirichlet");
  return split;
}

}  // namespace iga
