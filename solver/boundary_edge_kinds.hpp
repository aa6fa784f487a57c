#pragma once
/// @file
/// Which boundary condition holds on each boundary edge of a space: the parts of the problem in
/// config order, "all" first, later (named) parts overriding earlier ones.

#include <string>
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

/// An InputError at `where` unless `name` is one of the space's boundary parts ("all" always is),
/// naming the parts there are and the nearest one; `of` ends "unknown boundary part 'x' of …"
/// ("this g1 domain").
void check_boundary_part(const Space& space, const std::string& name, const std::string& where,
                         const std::string& of);

/// The split above; InputError for a pure Neumann problem (no unique solution).
BoundarySplit split_boundary(const Space& space, const ProblemSpec& problem);

}  // namespace iga
