#pragma once
/// @file
/// Errors of a discrete function against an exact solution: the L2 norm and the standard H1 and
/// H2 *seminorms* (|e|_1 = ||∇e||, |e|_2 = ||D²e|| with the Frobenius norm), not G+Smo's sums.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "assembly/fields.hpp"
#include "spaces/space.hpp"

namespace iga {

struct ErrorNorms {
  double l2 = 0;
  std::optional<double> h1;  ///< present when the exact gradient is known
  std::optional<double> h2;  ///< present when the exact Hessian is known
};

/// Integrate element by element with rules of degree `quad_degree` (use more than for assembly:
/// an oscillating exact solution is under-resolved by the assembly rule on coarse meshes).
/// `elements`, when given, restricts the integrals to those elements (a rank's share).
ErrorNorms error_norms(const Space& space, const Eigen::VectorXd& coefficients, const ExactSolution& exact,
                       int quad_degree, const std::vector<int>* elements = nullptr);

/// The same for a space on a surface in 3D (ambient_dimension() == 3): L2 error, the H1
/// seminorm of the error's surface gradient, ∇_Γu = ∇u − (∇u·n) n, and, when the exact Hessian is
/// given, the surface H2 seminorm ‖∇_Γ∇_Γ(u − u_h)‖ (covariant Hessians, Frobenius norm; the
/// exact one from assembly/surface_calculus.hpp).
ErrorNorms surface_error_norms(const Space& space, const Eigen::VectorXd& coefficients,
                               const SurfaceExactSolution& exact, int quad_degree,
                               const std::vector<int>* elements = nullptr);


}  // namespace iga
