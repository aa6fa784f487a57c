#pragma once
/// @file
/// The boundary term of a simply supported fourth-order problem on an open surface in 3D: with
/// u = g0 imposed and Δ_Γu = g natural on the boundary curve, integrating Δ_Γ²u v by parts twice
/// (v = 0 on the boundary) leaves ∫_∂Γ g ∂_ν v ds on the load side, ν the outward unit conormal.

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "spaces/space.hpp"

namespace iga {

/// b_i = ∫ g(x, n, H) ∂_ν N_i ds over `edges` (boundary edges of elements), with Gauss rules of
/// degree `quad_degree` on each edge; n and H are the surface's own at the point (g = Δ_Γu of an
/// ambient u depends on them), ν the conormal pointing out of the element.
Eigen::VectorXd surface_conormal_load(const Space& space, const std::vector<BoundaryEdge>& edges,
                                      const SurfaceSource& g, int quad_degree);

}  // namespace iga
