#pragma once
/// @file
/// The constants in the kernel of an operator without reaction on a closed surface (−Δ_Γ, Δ_Γ²):
/// the solution is unique up to a constant. With k the constant's coefficients
/// (assembly/constant_coefficients.hpp: not all ones for every basis), the load is made orthogonal
/// to k (b·k = ∫f, which is 0 for exact data only up to quadrature), the coefficient where |k_i|
/// is largest is pinned (an essential condition like any other: the consistent singular system
/// then has the free problem's solution plus a multiple of k), and after the solve the constant is
/// chosen: zero mean, or the exact solution's mean when one is given. Shared by SurfaceFormulation
/// and SurfaceBiharmonicFormulation.

#include <optional>

#include <Eigen/Core>

#include "config/expression.hpp"
#include "solver/formulation.hpp"

namespace iga {

class ConstantKernel {
 public:
  /// Subtracts from b (this share's load) its mean times ∫ N_i, so that b·k = 0 over all shares,
  /// and keeps ∫ N_i and the area for finish.
  void make_load_orthogonal(Eigen::VectorXd& b, const Space& space, int quadrature_degree, const WorkShare& share);
  /// The pinned coefficient (to 0); every other coefficient is free.
  Constraints pinned(const Space& space);
  /// Shifts the solution by a multiple of k to zero mean, or to the mean of `exact` when given
  /// (after make_load_orthogonal of the same share).
  void finish(Eigen::VectorXd& coefficients, const Space& space, const std::optional<SymbolicFunction>& exact,
              const WorkShare& share);

 private:
  const Eigen::VectorXd& constant(const Space& space);  ///< k, computed once
  Eigen::VectorXd k_;
  Eigen::VectorXd mass_of_one_;  ///< ∫ N_i over this share's elements
  double area_ = 0;              ///< of the whole surface
};

}  // namespace iga
