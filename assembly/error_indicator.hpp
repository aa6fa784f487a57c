#pragma once
/// @file
/// Residual-type a-posteriori error indicators, written once against the Space interface.
///
/// Poisson, −Δu = f:  η_K² = h_K² ‖f + Δu_h‖²_K + ½ Σ_{E ⊂ ∂K interior} h_E ‖[∂u_h/∂n]‖²_E,
/// h_K = |K|^{1/2}, h_E the length of the edge piece. The jump terms vanish identically for C1
/// spaces (continuity() >= 1) and are skipped there; for C0 spaces they come from
/// Space::interior_edges() (edge_jumps.hpp). A C0 space without interior_edges() gets
/// only the element part, which is not a reliable estimator (adaptive studies reject that case).
///
/// Clamped plates, Δ²u = f with a C1 space (∫ΔuΔv):
///   η_K² = h_K⁴ ‖f − Δ²u_h‖²_K + ½ Σ_{E ⊂ ∂K interior} (h_E ‖[Δu_h]‖²_E + h_E³ ‖[∂(Δu_h)/∂n]‖²_E),
/// the terms left by integrating ∫_K Δu_h Δv by parts twice (Δu_h pairs with ∂v/∂n, ∂(Δu_h)/∂n
/// with v on each edge). Needs third and fourth derivatives (Space::higher_derivatives()) and
/// Space::interior_edges(); clamped boundaries add no boundary terms (u and ∂u/∂n are essential).

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "spaces/space.hpp"

namespace iga {

/// η_K of the Poisson residual for u_h = Σ c_i N_i, one per element (not squared).
/// `quadrature_degree` is passed to Space::quadrature (use error_quadrature_degree).
std::vector<double> poisson_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                                const ScalarField& source, int quadrature_degree);

/// η_K of the clamped-plate residual above, one per element (not squared). Throws
/// std::invalid_argument unless space.higher_derivatives() and the space lists its interior edges
/// (or has a single element).
std::vector<double> plate_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                              const ScalarField& source, int quadrature_degree);

/// (Σ_K η_K²)^{1/2}.
double total_indicator(const std::vector<double>& eta);

}  // namespace iga
