#pragma once
/// @file
/// Jumps of derivatives of a discrete function across interior element edges: the edge parts of
/// the residual estimators, written once against Space::interior_edges().

#include <Eigen/Core>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// Poisson: per element K (num_elements() entries), ½ Σ_{E ⊂ ∂K interior} h_E ‖[∂u_h/∂n]‖²_E for
/// u_h = Σ c_i N_i, over the pieces of Space::interior_edges() (h_E: the piece's physical length;
/// each piece gives half to each side). Squared, not rooted. Gauss rule exact for
/// `quadrature_degree` on each piece. All zeros when the space lists no interior edges.
std::vector<double> normal_derivative_jump_terms(const Space& space, const Eigen::VectorXd& coefficients,
                                                 int quadrature_degree);

/// Plates (Δ²u = f): ½ Σ_E (h_E ‖[Δu_h]‖²_E + h_E³ ‖[∂(Δu_h)/∂n]‖²_E) per element, as above.
/// Needs space.higher_derivatives() (throws std::invalid_argument otherwise).
std::vector<double> laplacian_jump_terms(const Space& space, const Eigen::VectorXd& coefficients,
                                         int quadrature_degree);

}  // namespace iga
