#pragma once
/// @file
/// The edge terms of the C0 interior penalty (C0-IP) form of the surface biharmonic, for C0
/// spaces on surfaces in 3D (Bernstein triangles on RSD surfaces), over Space::interior_edges():
///
///   a_h(u, v) = Σ_K ∫_K Δ_Γu Δ_Γv + c u v
///             − Σ_E ∫_E {Δ_Γu} [∂_ν v] + {Δ_Γv} [∂_ν u] ds + Σ_E (η / h_E) ∫_E [∂_ν u] [∂_ν v] ds,
///
/// [∂_ν v] = ∇_Γv_a · ν_a + ∇_Γv_b · ν_b with ν the outward unit conormal of each element (tangent
/// to its side of the surface, normal to the edge: on a G1 surface ν_b = −ν_a, so the smooth
/// functions have no jump), {Δ_Γv} = (Δ_Γv_a + Δ_Γv_b) / 2, h_E the edge's length. The element
/// part is the conforming form (the bilaplace and mass integrators); these are the rest.

#include <Eigen/Core>

#include "assembly/fields.hpp"
#include "assembly/sparsity.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Σ_E of the consistency, symmetry and penalty terms above, as a dimension × dimension matrix
/// (both triangles; its pattern couples the two elements of every edge). Gauss rule exact for
/// `quadrature_degree` along each edge.
SparseMatrix c0ip_edge_matrix(const Space& space, double eta, int quadrature_degree);

/// The edge part of the load a_h(u, ·) of a smooth u: −Σ_E ∫_E {Δ_Γu} [∂_ν v] ds, with Δ_Γu on
/// each side from `laplacian(x, n, H)` and that side's normal and mean curvature (Δ_Γu jumps where
/// the curvature of a G1 surface does). [∂_ν u] = 0, so the other two terms vanish.
Eigen::VectorXd c0ip_edge_load(const Space& space, const SurfaceSource& laplacian, int quadrature_degree);

}  // namespace iga
