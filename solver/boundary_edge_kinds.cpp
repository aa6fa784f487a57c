#include "solver/boundary_edge_kinds.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "config/errors.hpp"

namespace iga {

void check_boundary_part(const Space& space, const std::string& name, const std::string& where,
                         const std::string& of) {
  const std::vector<std::string> names = space.boundary_names();
  if (name == "all" || std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string list = "all";
  for (const std::string& n : names) list += ", " + n;
  const std::string near = nearest_word(name, names);
  throw InputError(where + ": unknown boundary part '" + name + "' of " + of + " (parts: " + list + ")" +
                   (near.empty() ? "" : " (did you mean '" + near + "'?)"));
}

BoundarySplit split_boundary(const Space& space, const ProblemSpec& problem) {
  // Every boundary edge once, ordered by (element, local edge), with the kind of the last part naming it.
  std::map<std::pair<int, int>, BoundaryKind> kind_of_edge;
  for (const BoundaryPart& part : problem.boundary)
    for (const BoundaryEdge& e : space.boundary_edges(part.name)) kind_of_edge[{e.element, e.local_edge}] = part.kind;
  BoundarySplit split;
  for (const auto& [key, kind] : kind_of_edge) {
    const BoundaryEdge e{key.first, key.second};
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
