#pragma once
/// @file
/// Universal reference matrices of the 51 WS4 simplex splines on the unit triangle, and the element
/// matrices of the bilinear forms on any affine triangle built from them without quadrature
/// (the B_i are affine-invariant; WS4 notes §9).

#include <Eigen/Core>

#include "config/double_double.hpp"
#include "spaces/bilinear_form.hpp"

namespace iga::ws4 {

/// All matrices 51 x 51, integrals over the reference triangle, exact sub-region by sub-region.
struct Ws4ReferenceMatrices {
  Eigen::MatrixXd mass;        ///< ∫ B_i B_j
  Eigen::MatrixXd grad[2][2];  ///< ∫ ∂_a B_i ∂_b B_j, a, b ∈ {ξ, η}
  Eigen::MatrixXd hess[3][3];  ///< ∫ ∂_p B_i ∂_q B_j, p, q ∈ {ξξ, ξη, ηη}

  /// Built on first use (quadrature of degree 8 per sub-triangle), then shared; thread-safe.
  static const Ws4ReferenceMatrices& get();
};

using MatrixL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

/// The same integrals before rounding to double, for element matrices kept in long double.
struct Ws4ReferenceMatricesExtended {
  MatrixL mass;
  MatrixL grad[2][2];
  MatrixL hess[3][3];
  static const Ws4ReferenceMatricesExtended& get();
};

/// The same integrals in double-double, from pieces built in double-double (built on first use, a
/// fraction of a second). The residuals of clamped and simply supported plates need them: the
/// long double ones carry ≈ 1e-18 of their size, which the h⁻⁴ conditioning turns into an L2 error
/// of 1e-12 at 9 226 DOFs, growing ×16 per refinement.
struct Ws4ReferenceMatricesDoubleDouble {
  DoubleDoubleMatrix mass;
  DoubleDoubleMatrix grad[2][2];
  DoubleDoubleMatrix hess[3][3];
  /// All three groups (for tests; element matrices build only the group of their form, see
  /// prepare_reference_matrices_double_double).
  static const Ws4ReferenceMatricesDoubleDouble& get();
};

/// Build the double-double reference tables `form` needs (with the threads of the calling
/// context: call it outside parallel regions), so that later element matrices find them ready.
void prepare_reference_matrices_double_double(BilinearForm form);

/// Element matrix of `form` in the basis B_i of the triangle x = P0 + J ξ (51 x 51).
Eigen::MatrixXd ws4_form_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian);

/// Cᵀ K C for a symmetric K (n x n) and C (n x n), accumulated in long double and rounded once.
/// The element matrices of the Hermite basis need it: the extraction mixes B-coefficients of very
/// different sizes, and a double product loses digits to cancellation that the biharmonic system
/// (conditioned like h⁻⁴) then amplifies into an L2 error floor.
Eigen::MatrixXd symmetric_congruence_extended(const Eigen::MatrixXd& c, const Eigen::MatrixXd& k);

/// Cᵀ K C with K the element matrix of `form` on the triangle of `jacobian`, everything in long
/// double and not rounded: the residuals of iterative refinement need the element matrices beyond
/// double, or their rounding (which does not annihilate polynomials) returns as an error floor
/// growing like h⁻⁴.
void ws4_element_matrix_extended(BilinearForm form, const Eigen::Matrix2d& jacobian, const Eigen::MatrixXd& c,
                                 MatrixL& local);
/// Cᵀ K C in double-double: K's metric factors from the Jacobian and the combination of reference
/// matrices in double-double, the products C_im K_ij exact (two-product) and their sums
/// compensated, so the entries carry ≈ 1e-32 of Σ|C||K||C| instead of long double's 5e-20.
void ws4_element_matrix_double_double(BilinearForm form, const Eigen::Matrix2d& jacobian, const Eigen::MatrixXd& c,
                                      DoubleDoubleMatrix& local);

}  // namespace iga::ws4
