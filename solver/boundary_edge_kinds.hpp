#pragma once
/// @file
/// Which boundary condition holds on each boundary edge of a space: the parts of the problem in
/// config order, "all" first, later (named) parts overriding earlier ones.

#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "solver/problem.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The boundary edges sorted by what the problem does with them: essential data (u on dirichlet,
/// clamped and simply supported edges; ∂u/∂n on clamped ones), the Neumann flux, and the natural
/// term ∫ Δu ∂v/∂n of simply supported plates. Each list ordered by (element, local edge).
struct BoundarySplit {
  EssentialBoundary essential;
  std::vector<BoundaryEdge> neumann, simply_supported;
};

/// The split above; InputError for a pure Neumann problem (no unique solution).
BoundarySplit split_boundary(const Space& space, const ProblemSpec& problem);

}  // namespace iga
