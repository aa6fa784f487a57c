#pragma once
/// @file
/// The standard integrators, planar and on surfaces, and the element load. Each is a symmetric
/// form Σ_t f_t ∫ (L_t u)(L_t v): a list of operands L_t φ (one row per function, one column per
/// point) and exact factors f_t, summed as A diag(w) Aᵀ by one kernel per scalar (double, long
/// double, double-double). On a surface (ambient dimension 3) the derivatives are the surface
/// gradient and the covariant Hessian of PointValues, so the same objects give the surface forms:
///   mass       ∫ u v
///   stiffness  ∫ ∇u·∇v                  (surface: ∇_Γ; Laplace–Beltrami)
///   bilaplace  ∫ Δu Δv                  (surface: Δ_Γ = trace of the covariant Hessian)
///   hessian    ∫ D²u : D²v              (surface: covariant Hessians, all nine entries)

#include <Eigen/Core>
#include <memory>

#include "assembly/fields.hpp"
#include "assembly/integrator.hpp"

namespace iga {

/// An integrator of the form Σ_t f_t ∫ (L_t u)(L_t v), written once for the three scalars.
class SymmetricSquaresIntegrator : public Integrator {
 public:
  using Integrator::Integrator;

  /// L_t φ at the points: `hi` (+ `lo` where one rounding of a sum of derivatives would be too
  /// much for double-double sums; null when hi is exact), times the exact factor f_t (1 or 2).
  struct Operand {
    const Eigen::MatrixXd* hi;
    const Eigen::MatrixXd* lo;
    double factor;
  };
  static constexpr int kMaxOperands = 6;
  /// Scratch for operands the integrator computes (Δφ); one per thread.
  struct Scratch {
    Eigen::MatrixXd hi, lo;
  };
  /// The operands on `v`; returns how many.
  virtual int operands(const PointValues& v, Scratch& scratch, Operand (&out)[kMaxOperands]) const = 0;

 protected:
  void unit_matrix(const ElementValues& ev, Eigen::MatrixXd& local) const override;
  void unit_matrix(const ElementValues& ev, MatrixXld& local) const override;
  void unit_matrix(const ElementValues& ev, DoubleDoubleMatrix& local) const override;
};

/// The standard integrators (tags: BilinearForm::mass, laplace, bilaplace, hessian).
std::shared_ptr<const Integrator> mass_integrator(double coefficient = 1.0);
std::shared_ptr<const Integrator> stiffness_integrator(double coefficient = 1.0);
std::shared_ptr<const Integrator> bilaplace_integrator(double coefficient = 1.0);
std::shared_ptr<const Integrator> hessian_integrator(double coefficient = 1.0);

}  // namespace iga
