#pragma once
/// @file
/// Finiteness of the problem data where quadrature alone would miss a bad value: at the vertices
/// and along the edges of every element. A pole on a mesh line (1/(x - 0.5) with a vertex at
/// x = 0.5) never meets an interior quadrature point, yet the data are not integrable there.

#include "solver/problem.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Throw InputError naming the config key when a datum is not finite where quadrature does not
/// look: the exact solution at every element vertex, and at every edge midpoint also its first and
/// second derivatives (used by the boundary data and the error norms) and the source term; without
/// an exact solution, the source at edge midpoints and the boundary data (u at the ends, u, ∂u/∂n
/// and Δu at three Gauss points) of every boundary edge. Derivatives are not checked at vertices:
/// a re-entrant corner's r^(2/3) has an integrable singularity there.
void check_data_finite(const Space& space, const ProblemSpec& problem);

}  // namespace iga
