#pragma once
/// @file
/// Which boundary condition holds on each boundary edge of a space: the parts of the problem in
/// config order, "all" first, later (named) parts overriding earlier ones.

#include <utility>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "solver/problem.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Every boundary edge once, ordered by (element, local edge), with its condition.
std::vector<std::pair<BoundaryEdge, BoundaryKind>> boundary_edge_kinds(const Space& space, const ProblemSpec& problem);

/// The boundary edges where `kind` holds, in the order above.
std::vector<BoundaryEdge> boundary_edges_of_kind(const Space& space, const ProblemSpec& problem, BoundaryKind kind);

/// The boundary edges sorted by what the problem does with them: essential data (u on dirichlet,
/// clamped and simply supported edges; ∂u/∂n on clamped ones), the Neumann flux, and the natural
/// term ∫ Δu ∂v/∂n of simply supported plates.
struct BoundarySplit {
  EssentialBoundary essential;
  std::vector<BoundaryEdge> neumann, simply_supported;
};

/// The split above; InputError for a pure Neumann problem (no unique solution).
BoundarySplit split_boundary(const Space& space, const ProblemSpec& problem);

}  // namespace iga
