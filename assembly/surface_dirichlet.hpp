#pragma once
/// @file
/// Dirichlet data on the boundary curve of an open surface in 3D, through the Space interface:
/// the functions whose trace on a boundary edge is not identically zero are constrained, and their
/// coefficients minimise ∫_∂Γ (u_h − g)² ds (a boundary L2 projection, optimal order for any C0
/// space). Planar spaces use impose_essential (boundary_conditions.hpp), whose data are functions
/// of (x, y); on a surface the data depend on z as well.

#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "assembly/fields.hpp"

namespace iga {

/// Constraints (constrained, free, values) for u = g on `edges` of a space with
/// ambient_dimension() == 3; edge rules of degree `quad_degree`. When the boundary mass matrix of
/// the constrained functions is singular (dependent traces, as the G1 vertex functions of a
/// 4-split surface at a boundary corner), the general projection of surface_essential.hpp.
Constraints surface_dirichlet_constraints(const Space& space, const std::vector<BoundaryEdge>& edges,
                                          const SurfaceField& g, int quad_degree);

}  // namespace iga
