#pragma once
/// @file
/// Essential data on the boundary curve of an open surface in 3D for any surface space: u = g
/// (Dirichlet), and for fourth-order problems also the conormal derivative ∂_ν u = g_ν (clamped).
/// The method of impose_essential (boundary_conditions.hpp) with surface quantities: the functions
/// whose trace or conormal derivative is not identically zero on a boundary edge are constrained,
/// their coefficients minimise Σ ∫ (u_h − g)² ds + h_E² ∫ (∂_ν u_h − g_ν)² ds, and dependent traces
/// (G1 vertex functions seen by both boundary edges at a corner) stay free after a basis change.
/// ν is the outward unit conormal: tangent to the surface, normal to the boundary curve.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "assembly/fields.hpp"

namespace iga {

/// g_ν(x, ν): the conormal derivative of the data at boundary point x with outward conormal ν
/// (for an ambient exact solution: ∇u(x) · ν).
using SurfaceConormalField = std::function<double(const Eigen::Vector3d& x, const Eigen::Vector3d& conormal)>;

/// Constraints for u = g on `edges` and, when `g_conormal` is set, ∂_ν u = g_ν there too; edge
/// rules of degree `quad_degree`. InputError when the data are not finite.
Constraints surface_essential_constraints(const Space& space, const std::vector<BoundaryEdge>& edges,
                                          const SurfaceField& g, const SurfaceConormalField& g_conormal,
                                          int quad_degree);

/// The same with the data per edge: u = g on `boundary.value_edges`, ∂_ν u = g_ν on
/// `boundary.normal_edges` (clamped parts; each also a value edge), all in one least-squares system,
/// so a function seen by a clamped and a simply supported edge at a corner is fitted to both data.
Constraints surface_essential_constraints(const Space& space, const EssentialBoundary& boundary,
                                          const SurfaceField& g, const SurfaceConormalField& g_conormal,
                                          int quad_degree);

}  // namespace iga
