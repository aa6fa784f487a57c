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
/// Spaces on surfaces in 3D (Space::ambient_dimension() == 3) also fill x3 and jacobian3, and dz
/// with dx, dy: (dx, dy, dz) is then the tangential (surface) gradient J G⁻¹ ∇̂N in ambient
/// coordinates, G = JᵀJ (see complete_surface_values). Their x holds the (x, y) projection of x3
/// so that num_points() holds, and jacobian stays empty. Planar spaces leave the 3D members empty.
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
  Eigen::Matrix3Xd normal3;        ///< unit normal (3 x q, if update_surface_curvature)
  Eigen::VectorXd mean_curvature;  ///< H = div_Γ n = κ1 + κ2 (q, if update_surface_curvature)

  int num_functions() const { return static_cast<int>(dofs.size()); }
  int num_points() const { return static_cast<int>(x.cols()); }
};

/// One discrete function u_h = Σ_i c_i N_i and its physical derivatives at the q points of a rule
/// (vectors of length q). Filled by Space::Evaluator::evaluate_function; only the vectors asked for
/// by the flags are set (update_values: value, update_gradients: dx, dy, update_hessians: dxx, dxy, dyy).
struct FunctionValues {
  Eigen::VectorXd value;
  Eigen::VectorXd dx, dy;
  Eigen::VectorXd dz;  ///< surfaces in 3D: third component of the surface gradient
  Eigen::VectorXd dxx, dxy, dyy;
  Eigen::VectorXd laplacian_dx, laplacian_dy;  ///< ∂x Δu_h, ∂y Δu_h (update_laplacian_gradient)
  Eigen::VectorXd bilaplacian;                 ///< Δ²u_h (update_bilaplacian)
};

}  // namespace iga
