#pragma once
/// @file
/// The completion of PointValues on surfaces in 3D, shared by every space whose elements map into
/// R³: from the geometry jets of the element map (geometry/surface_jet.hpp) and the reference
/// derivatives of the functions to
///  - the tangential (surface) gradient ∇_Γφ = J G⁻¹ ∇̂φ in ambient coordinates, G = JᵀJ;
///  - the covariant (surface) Hessian ∇_Γ∇_Γφ = J G⁻¹ (∂²φ̂ − Γ^k ∂_kφ̂) G⁻¹ Jᵀ, a symmetric 3×3
///    tensor that annihilates the normal; Γ^k_ab = (G⁻¹Jᵀ x_ab)_k are the Christoffel symbols of
///    the map, so Γ^k_ab ∂_kφ̂ = x_ab · ∇_Γφ. Its trace is the Laplace–Beltrami Δ_Γφ, and it equals
///    the tangential part of the derivative of ∇_Γφ along the surface: H J = P ∂(∇_Γφ)/∂ξ.

#include <Eigen/Core>
#include <vector>

#include "geometry/surface_jet.hpp"
#include "spaces/point_values.hpp"

namespace iga {

/// √det(JᵀJ) = |J_ξ × J_η|: the area element of a map into R³.
double surface_measure(const Eigen::Matrix<double, 3, 2>& jacobian);

/// The unit normal x_ξ × x_η / |x_ξ × x_η| of a point of PointValues::jacobian3 (for the layers
/// above spaces/, which do not include geometry/ directly).
inline Eigen::Vector3d surface_normal(const Eigen::Matrix<double, 3, 2>& jacobian) {
  return unit_normal(jacobian.col(0), jacobian.col(1));
}

/// out.x3, out.x (its (x, y) rows), out.jacobian3 from the jets at the q points (out.jacobian
/// cleared), and with update_surface_curvature out.normal3 and out.mean_curvature.
void take_surface_geometry(const std::vector<SurfaceJet>& jets, unsigned flags, PointValues& out);

/// out.dx, out.dy, out.dz (n x q): the surface gradients from reference derivatives dxi, deta (n x q)
/// and the jets at the q points.
void complete_surface_gradients(const std::vector<SurfaceJet>& jets, const Eigen::MatrixXd& dxi,
                                const Eigen::MatrixXd& deta, PointValues& out);

/// Reference second derivatives of n functions at q points (n x q each).
struct ReferenceHessians {
  const Eigen::MatrixXd& dxixi;
  const Eigen::MatrixXd& dxieta;
  const Eigen::MatrixXd& detaeta;
};

/// The covariant Hessians (out.dxx, dxy, dyy, dxz, dyz, dzz; n x q) from the reference first and
/// second derivatives and the second-order jets (has_second) at the q points.
void complete_surface_hessians(const std::vector<SurfaceJet>& jets, const Eigen::MatrixXd& dxi,
                               const Eigen::MatrixXd& deta, const ReferenceHessians& second, PointValues& out);

}  // namespace iga
