#pragma once
/// @file
/// Residual-type a-posteriori error indicators, written once against the Space interface.
///
/// Poisson, −Δu = f:  η_K = h_K ‖f + Δu_h‖_{L2(K)}  with h_K = |K|^{1/2}.
/// The full residual estimator also has the edge terms h_E^{1/2} ‖[∂u_h/∂n]‖_E on interior edges.
/// The Space interface cannot locate the element on the other side of an edge, so they are not
/// computed: for C1 spaces (continuity() >= 1) they vanish identically and η is the complete
/// estimator; for C0 spaces η is only the element part (it misses the dominant jump term, so it is
/// not a reliable estimator there — use C1 spaces for adaptivity).
///
/// Biharmonic, Δ²u = f: the analogous term is h_K² ‖f − Δ²u_h‖_K (plus jump terms of Δu_h and
/// ∂Δu_h/∂n, which a C1 space does not make vanish). It needs fourth derivatives, which
/// Space::Evaluator does not provide (update_hessians is the highest), so it is not implemented;
/// adaptive biharmonic studies are rejected by the config parser.

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "spaces/space.hpp"

namespace iga {

/// η_K of the Poisson residual for u_h = Σ c_i N_i, one per element (not squared).
/// `quadrature_degree` is passed to Space::quadrature (use error_quadrature_degree).
std::vector<double> poisson_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                                const ScalarField& source, int quadrature_degree);

/// (Σ_K η_K²)^{1/2}.
double total_indicator(const std::vector<double>& eta);

}  // namespace iga
