#pragma once
/// @file
/// What an evaluation computes (UpdateFlags) and what it returns: PointValues (the active
/// functions of one element at a set of points) and FunctionValues (one discrete function there).

#include <Eigen/Core>
#include <vector>

namespace iga {

/// What an evaluation must compute. Combine with |.
enum UpdateFlags : unsigned {
  update_values = 1u,
  update_gradients = 2u,
  update_hessians = 4u,
  /// Third and fourth derivatives of a discrete function, as the biharmonic residual needs them:
  /// ∇(Δu_h) and Δ²u_h. Only Evaluator::evaluate_function fills them, and only for spaces whose
  /// higher_derivatives() is true (the default evaluate_function throws std::logic_error).
  update_laplacian_gradient = 8u,
  update_bilaplacian = 16u,
  /// Surfaces in 3D only: PointValues::normal3 and mean_curvature (the load of Laplace–Beltrami
  /// problems evaluates the source through the surface's own normal and curvature).
  update_surface_curvature = 32u,
};

/// Values of the active global functions of one element at a set of points, in physical
/// coordinates. Filled by Space::Evaluator::evaluate and completed by ElementValues.
/// Shapes: n = dofs.size() active functions, q = number of points; arrays are n x q.
///
/// Derivatives are tensors in ambient coordinates, stored one array per component: the gradient
/// (dx, dy[, dz]) and the symmetric Hessian (dxx, dxy, dyy[, dxz, dyz, dzz]); gradient(i, k) and
/// hessian(i, k) assemble them (zero rows and columns for z in the plane). A vector field built on
/// a scalar basis (N_i e_c, as shell displacements will be) reads the derivatives of each
/// component from these same arrays.
///
/// Spaces on surfaces in 3D (Space::ambient_dimension() == 3) also fill x3 and jacobian3, and dz
/// with dx, dy: (dx, dy, dz) is then the tangential (surface) gradient J G⁻¹ ∇̂N in ambient
/// coordinates, G = JᵀJ; with update_hessians the six Hessian arrays hold the covariant
/// (surface) Hessian ∇_Γ∇_Γ N, a symmetric tangential 3×3 tensor whose trace is the
/// Laplace–Beltrami Δ_Γ N (see spaces/surface_values.hpp). Their x holds the (x, y) projection of
/// x3 so that num_points() holds, and jacobian stays empty. Planar spaces leave the 3D members empty.
struct PointValues {
  std::vector<int> dofs;                 ///< global indices of the active functions (n)
  Eigen::Matrix2Xd x;                    ///< physical points (2 x q)
  std::vector<Eigen::Matrix2d> jacobian; ///< d(x,y)/d(xi,eta) at each point (q)
  Eigen::MatrixXd value;                 ///< N_i(x_q)                    (if update_values)
  Eigen::MatrixXd dx, dy;                ///< first derivatives           (if update_gradients)
  Eigen::MatrixXd dxx, dxy, dyy;         ///< second derivatives          (if update_hessians)
  // Surfaces in 3D only (empty otherwise):
  Eigen::Matrix3Xd x3;                                ///< points on the surface (3 x q)
  std::vector<Eigen::Matrix<double, 3, 2>> jacobian3; ///< d(x,y,z)/d(xi,eta) (q)
  Eigen::MatrixXd dz;                                 ///< third component of the surface gradient
  Eigen::MatrixXd dxz, dyz, dzz;   ///< the z row of the covariant Hessian (if update_hessians)
  Eigen::Matrix3Xd normal3;        ///< unit normal (3 x q, if update_surface_curvature)
  Eigen::VectorXd mean_curvature;  ///< H = div_Γ n = κ1 + κ2 (q, if update_surface_curvature)

  int num_functions() const { return static_cast<int>(dofs.size()); }
  int num_points() const { return static_cast<int>(x.cols()); }
  /// The gradient of function i at point k in ambient coordinates (z = 0 in the plane).
  Eigen::Vector3d gradient(int i, int k) const {
    return {dx(i, k), dy(i, k), dz.size() > 0 ? dz(i, k) : 0.0};
  }
  /// The Hessian of function i at point k (planar: the 2×2 block, z row and column zero; surface:
  /// the covariant Hessian).
  Eigen::Matrix3d hessian(int i, int k) const {
    const bool s = dzz.size() > 0;
    const double xz = s ? dxz(i, k) : 0.0, yz = s ? dyz(i, k) : 0.0, zz = s ? dzz(i, k) : 0.0;
    Eigen::Matrix3d h;
    h << dxx(i, k), dxy(i, k), xz, dxy(i, k), dyy(i, k), yz, xz, yz, zz;
    return h;
  }
};

/// One discrete function u_h = Σ_i c_i N_i and its physical derivatives at the q points of a rule
/// (vectors of length q). Filled by Space::Evaluator::evaluate_function; only the vectors asked for
/// by the flags are set (update_values: value, update_gradients: dx, dy (dz), update_hessians:
/// dxx, dxy, dyy (dxz, dyz, dzz on surfaces: the covariant Hessian, as in PointValues)).
struct FunctionValues {
  Eigen::VectorXd value;
  Eigen::VectorXd dx, dy;
  Eigen::VectorXd dz;  ///< surfaces in 3D: third component of the surface gradient
  Eigen::VectorXd dxx, dxy, dyy;
  Eigen::VectorXd dxz, dyz, dzz;  ///< surfaces in 3D: the z row of the covariant Hessian
  Eigen::VectorXd laplacian_dx, laplacian_dy;  ///< ∂x Δu_h, ∂y Δu_h (update_laplacian_gradient)
  Eigen::VectorXd bilaplacian;                 ///< Δ²u_h (update_bilaplacian)

  /// Δu_h at point k (on a surface the Laplace–Beltrami Δ_Γ u_h, the trace of the covariant Hessian).
  double laplacian(int k) const { return dxx(k) + dyy(k) + (dzz.size() > 0 ? dzz(k) : 0.0); }
};

}  // namespace iga
