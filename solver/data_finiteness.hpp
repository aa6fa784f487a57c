#pragma once
/// @file
/// Finiteness of the problem data where quadrature alone would miss a bad value: at the vertices
/// and along the edges of every element. A pole on a mesh line (1/(x - 0.5) with a vertex at
/// x = 0.5) never meets an interior quadrature point, yet the data are not integrable there.

#include "solver/problem.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Throw InputError naming the config key when a datum is not finite at a vertex or an edge
/// midpoint of some element: the exact solution with its first and second derivatives (used by the
/// boundary data and the error norms) and the source term; without an exact solution, the boundary
/// data (u, ∂u/∂n, Δu) at the ends and three Gauss points of every boundary edge.
void check_data_finite(const Space& space, const ProblemSpec& problem);

}  // namespace iga
