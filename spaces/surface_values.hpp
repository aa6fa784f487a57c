#pragma once
/// @file
/// The completion of PointValues on surfaces in 3D: from reference gradients and the 3×2 Jacobian
/// J of the element map to tangential gradients in ambient coordinates, J G⁻¹ ∇̂φ with G = JᵀJ,
/// and the area element √det G. Shared by every space whose elements map into R³.

#include <Eigen/Core>

#include "spaces/space.hpp"

namespace iga {

/// √det(JᵀJ) = |J_ξ × J_η|: the area element of a map into R³.
double surface_measure(const Eigen::Matrix<double, 3, 2>& jacobian);

/// H = −tr(G⁻¹ B), G = JᵀJ, from the second fundamental form B (entries x_ab · n) at a point: the
/// mean curvature with the sign convention of PointValues::mean_curvature.
double mean_curvature(const Eigen::Matrix<double, 3, 2>& jacobian, const Eigen::Matrix2d& second_form);

/// out.dx, out.dy, out.dz (n x q) from reference derivatives dxi, deta (n x q) and out.jacobian3.
void complete_surface_gradients(const Eigen::MatrixXd& dxi, const Eigen::MatrixXd& deta, PointValues& out);

}  // namespace iga
