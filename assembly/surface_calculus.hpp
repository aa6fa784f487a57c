#pragma once
/// @file
/// Tangential calculus of a function u given in ambient coordinates (x, y, z), restricted to a
/// surface Γ with unit normal n, P = I − n nᵀ, mean curvature H = div_Γ n and Weingarten map
/// W = ∇_Γ n (symmetric, tangential, tr W = H; W = P on the unit sphere with the outward normal).
/// With g = ∇u and D = ∇²u the ambient gradient and Hessian at a point of Γ:
///   ∇_Γu = P g,
///   ∇_Γ∇_Γu = P ∂_τ(P g) = P D P − (g·n) W   (the covariant Hessian, as the evaluators return it
///             for discrete functions: spaces/surface_values.hpp),
///   Δ_Γu = tr(∇_Γ∇_Γu) = tr D − nᵀ D n − H (g·n)   (the Laplace–Beltrami source's formula).
/// Derivation: ∂_τ(P g) = P D τ − ∂_τ(g·n) n − (g·n) ∂_τ n, and ∂_τ n = W τ; the middle term is
/// normal and drops under P. Unit sphere, u = z: D = 0, g·n = z, W = P: ∇_Γ∇_Γ z = −z P, Δ_Γ z = −2z.

#include <Eigen/Core>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// Δ_Γu = tr D − nᵀ D n − H (g·n).
double surface_laplacian_of_ambient(const Eigen::Matrix3d& D, const Eigen::Vector3d& g, const Eigen::Vector3d& n,
                                    double H);

/// ∇_Γ∇_Γu = P D P − (g·n) W.
Eigen::Matrix3d covariant_hessian_of_ambient(const Eigen::Matrix3d& D, const Eigen::Vector3d& g,
                                             const Eigen::Vector3d& n, const Eigen::Matrix3d& W);

/// The Weingarten map W = ∇_Γ n at the points of `rule` on `element`, in ambient form (3 × 3,
/// symmetric, W n = 0), from the unit normals of Evaluator::evaluate_geometry at points shifted
/// by ±δ, ±2δ, ±3δ (δ = 2.5e-4, less within 1e-3 of the reference cell's edge) along each reference direction: ∂_a n by the sixth-order central
/// difference, W = [∂_ξ n, ∂_η n] G⁻¹ Jᵀ. With L the reference length over which n turns (≈ 0.03
/// at the rounded corners of the 4-split cube, level 0) the truncation is ≈ (δ/L)⁶ ≈ 1e-12 and the
/// rounding ≈ 1e-15 L/δ relative to |W|: far below the errors it measures (the fourth-order
/// difference with δ = 1e-3 left 3e-8 relative there, and an H2 floor of 1e-5). Why differences: PointValues
/// carries n and H but not W, and adding W there rebuilds every layer above spaces/; the map's
/// second derivatives (exact W) stay inside the spaces' cores.
///
/// The shifted points must lie in the polynomial piece of their quadrature point (true for Gauss
/// points of the pieces of every space here: the nearest lies ≥ 4e-3 inside its piece, 3δ = 7.5e-4).
class ShapeOperatorByDifferences {
 public:
  /// W at every point of `rule` on a reference triangle or square; `jacobian3` are the Jacobians
  /// at those points (PointValues).
  void compute(Space::Evaluator& evaluator, int element, const QuadratureRule& rule, bool triangle,
               const std::vector<Eigen::Matrix<double, 3, 2>>& jacobian3, std::vector<Eigen::Matrix3d>& W);

 private:
  QuadratureRule shifted_;         ///< 12 points per point of the last rule
  std::vector<Point2> base_;       ///< the points shifted_ was built from
  bool triangle_ = false;
  std::vector<double> delta_;      ///< the step at each point: 2.5e-4, or a quarter of its distance to the cell's edge
  PointValues geometry_;
};

}  // namespace iga
