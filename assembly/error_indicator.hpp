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
/// Plates, Δ²u = f with a C1 space (∫ΔuΔv), clamped or simply supported:
///   η_K² = h_K⁴ ‖f − Δ²u_h‖²_K + ½ Σ_{E ⊂ ∂K interior} (h_E ‖[Δu_h]‖²_E + h_E³ ‖[∂(Δu_h)/∂n]‖²_E)
///          + Σ_{E ⊂ ∂K simply supported} h_E ‖g_L − Δu_h‖²_E,
/// the terms left by integrating ∫_K Δu_h Δv by parts twice (Δu_h pairs with ∂v/∂n, ∂(Δu_h)/∂n
/// with v on each edge; on the boundary v = 0, and ∂v/∂n = 0 where clamped). Needs third and fourth
/// derivatives (Space::higher_derivatives()) and Space::interior_edges().

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "spaces/space.hpp"

namespace iga {

/// η_K of the Poisson residual for u_h = Σ c_i N_i, one per element (not squared).
/// `quadrature_degree` is passed to Space::quadrature (use Space::error_quadrature_degree).
std::vector<double> poisson_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                                const ScalarField& source, int quadrature_degree);

/// η_K of an eigenpair (λ_h, u_h) of −Δu = λu: the Poisson indicator with f = λ_h u_h, i.e.
/// η_K² = h_K² ‖λ_h u_h + Δu_h‖²_K (+ the jump terms of C0 spaces). For a simple eigenvalue it
/// bounds the eigenfunction's energy error up to higher-order terms (Durán, Padra, Rodríguez 2003),
/// whose square the eigenvalue error is.
std::vector<double> eigen_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients, double eigenvalue,
                                              int quadrature_degree);

/// η_K of the plate residual above, one per element (not squared); `simply_supported` are the
/// boundary edges where Δu = `laplacian` (g_L) is the natural condition (empty: all clamped). Throws
/// std::invalid_argument unless space.higher_derivatives() and the space lists its interior edges
/// (or has a single element).
std::vector<double> plate_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                              const ScalarField& source, int quadrature_degree,
                                              const std::vector<BoundaryEdge>& simply_supported = {},
                                              const BoundaryField& laplacian = nullptr);

/// (Σ_K η_K²)^{1/2}.
double total_indicator(const std::vector<double>& eta);

}  // namespace iga
