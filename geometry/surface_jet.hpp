#pragma once
/// @file
/// The differential geometry of a surface map x(ξ, η) into R³ at one point, computed in one place:
/// position, Jacobian J = (x_ξ, x_η), metric G = JᵀJ and its inverse, area element √det G, unit
/// normal n = x_ξ × x_η / |x_ξ × x_η|, the contravariant frame J G⁻¹ (surface gradient
/// ∇_Γφ = J G⁻¹ ∇̂φ) and, from the second derivatives x_ab, the second fundamental form
/// B_ab = x_ab · n, the shape operator G⁻¹B, the mean curvature H = −tr(G⁻¹B) = div_Γ n (2 on the
/// unit sphere with the outward normal) and the Gauss curvature K = det B / det G.
///
/// Every evaluator of a space on a surface and every computation of a surface normal goes through
/// surface_jet, so the sign of n, of H and the metric are the same everywhere.

#include <Eigen/Core>
#include <array>

namespace iga {

struct SurfaceJet {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, 2> jacobian = Eigen::Matrix<double, 3, 2>::Zero();  ///< columns x_ξ, x_η
  Eigen::Matrix2d metric = Eigen::Matrix2d::Identity();          ///< G = JᵀJ
  Eigen::Matrix2d metric_inverse = Eigen::Matrix2d::Identity();  ///< G⁻¹
  Eigen::Matrix<double, 3, 2> dual = Eigen::Matrix<double, 3, 2>::Zero();  ///< J G⁻¹: ∇_Γφ = dual ∇̂φ
  double area = 0.0;                                  ///< √det G = |x_ξ × x_η|
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();   ///< unit x_ξ × x_η

  // Second order: meaningful only when has_second (a jet refilled at first order keeps stale values).
  bool has_second = false;
  std::array<Eigen::Vector3d, 3> second{};           ///< x_ξξ, x_ξη, x_ηη
  Eigen::Matrix2d second_form = Eigen::Matrix2d::Zero();      ///< B_ab = x_ab · n
  Eigen::Matrix2d shape_operator = Eigen::Matrix2d::Zero();   ///< G⁻¹ B (Weingarten map in ξ, η)
  double mean_curvature = 0.0;   ///< H = −tr(G⁻¹B) = κ1 + κ2 = div_Γ n
  double gauss_curvature = 0.0;  ///< K = det B / det G = κ1 κ2
};

/// First-order jet: x, J and what follows from them.
SurfaceJet surface_jet(const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian);
/// Second-order jet: also x_ξξ, x_ξη, x_ηη and the curvatures.
SurfaceJet surface_jet(const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian,
                       const std::array<Eigen::Vector3d, 3>& second);

/// The same, written into an existing jet: evaluators refill one jet per quadrature point of every
/// element, and building a fresh ~50-double struct per point and copying it cost as much as the
/// geometry itself on low-degree surface elements. `second` null: first order (has_second false).
void fill_surface_jet(SurfaceJet& j, const Eigen::Vector3d& x, const Eigen::Matrix<double, 3, 2>& jacobian,
                      const std::array<Eigen::Vector3d, 3>* second = nullptr);

/// The unit normal x_ξ × x_η / |x_ξ × x_η| of tangent vectors (no metric inverse; for checks that
/// need only the normal).
Eigen::Vector3d unit_normal(const Eigen::Vector3d& x_xi, const Eigen::Vector3d& x_eta);
/// |x_ξ × x_η|: the area element.
double area_element(const Eigen::Vector3d& x_xi, const Eigen::Vector3d& x_eta);

}  // namespace iga
