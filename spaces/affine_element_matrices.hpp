#pragma once
/// @file
/// Closed-form element matrices of a space with an affine-invariant local basis, written once for
/// every such space and for the scalars it sums in. On an element x = x0 + J ξ the standard forms
/// are constant combinations of reference integrals
///   K = Σ_t w_t(J) R(α_t, β_t),   R(α, β)_ij = ∫_ref ∂^α φ_i ∂^β φ_j,
/// and the element matrix in the global functions is Cᵀ K C with the extraction C (local × active).
/// A space describes its local basis by its reference integrals (ReferenceIntegrals, or 1D
/// DerivativeMoments for a tensor basis on a rectangle) and its map by J; this file gives the
/// weights w_t of each form (affine_form_terms), K (combine, or tensor_form_matrix, the sum-
/// factorised fast path of tensor bases) and Cᵀ K C (symmetric_congruence), in long double and in
/// double-double. The double-double path exists for the solver's residuals: WS4's and the T-mesh's
/// plates reach round-off only with element matrices beyond long double (docs/known-limits.md).

#include <Eigen/Core>

#include "config/double_double.hpp"
#include "spaces/bilinear_form.hpp"

namespace iga {

using LongDoubleMatrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

/// Derivatives in reference coordinates (ξ, η), the indices α, β of R(α, β): the value, ∂ξ, ∂η,
/// ∂ξξ, ∂ξη, ∂ηη.
enum ReferenceDerivative : int { kValue = 0, kDxi, kDeta, kDxixi, kDxieta, kDetaeta };
/// Orders in ξ and in η of each ReferenceDerivative (for tensor-product bases).
inline constexpr int kOrderXi[6] = {0, 1, 0, 2, 1, 0};
inline constexpr int kOrderEta[6] = {0, 0, 1, 0, 1, 2};

/// The reference integrals of a local basis that the standard forms use: values with values,
/// first with first and second with second derivatives.
template <class Matrix>
struct ReferenceIntegrals {
  Matrix mass;        ///< R(value, value)
  Matrix grad[2][2];  ///< R(∂_a, ∂_b), a, b ∈ {ξ, η}
  Matrix hess[3][3];  ///< R(∂_p, ∂_q), p, q ∈ {ξξ, ξη, ηη}
  const Matrix& operator()(int alpha, int beta) const {
    if (alpha == kValue) return mass;
    if (alpha < kDxixi) return grad[alpha - kDxi][beta - kDxi];
    return hess[alpha - kDxixi][beta - kDxixi];
  }
};

/// 1D integrals of a tensor factor: moment[k][l](a, c) = ∫_0^1 N_a^(k) N_c^(l) (derivatives in the
/// reference coordinate, k, l <= 2); R(α, β) = X(ξ orders) ⊗ Y(η orders).
template <class Matrix>
struct DerivativeMoments {
  Matrix moment[3][3];
};

/// One term w ∫_ref ∂^α φ ∂^β ψ of a form.
template <class Scalar>
struct ReferenceTerm {
  int alpha, beta;
  Scalar weight;
};
/// The terms of one form (at most 16: the Hessian form in long double keeps its sixteen products
/// G_ac G_bd apart, the order WS4's tables were always summed in).
template <class Scalar>
struct AffineTerms {
  ReferenceTerm<Scalar> term[16];
  int size = 0;
  const ReferenceTerm<Scalar>* begin() const { return term; }
  const ReferenceTerm<Scalar>* end() const { return term + size; }
};

/// The weights of `form` on the element x = x0 + J ξ, |det J| included (J(i, k) = ∂x_i/∂ξ_k).
/// double or long double: G = J⁻¹J⁻ᵀ in that scalar. Double-double: det J and M = adj(J) adj(J)ᵀ from exact
/// products of J's entries, each weight divided once by a power of |det J|, so the weights carry
/// ≈ 1e-32 of their size. Terms whose weight is exactly zero (axis-aligned elements) are left out.
template <class Scalar>
AffineTerms<Scalar> affine_form_terms(BilinearForm form, const Eigen::Matrix2d& jacobian);

/// K = Σ_t w_t R(α_t, β_t), n x n, in the scalar of the tables (double, long double). The
/// double-double K is computed on one triangle and mirrored (every form is symmetric).
template <class Scalar>
void combine(const AffineTerms<Scalar>& terms, const ReferenceIntegrals<Eigen::Matrix<Scalar, -1, -1>>& r,
             Eigen::Matrix<Scalar, -1, -1>& k);
void combine(const AffineTerms<DoubleDouble>& terms, const ReferenceIntegrals<DoubleDoubleMatrix>& r,
             DoubleDoubleMatrix& k);

/// K of a tensor basis N_a(ξ) M_b(η), local index a + b n_x, without forming the R(α, β): each entry
/// is one product per term (sum factorisation, the fast path of B-spline and T-mesh cells). The
/// double-double K is computed on one triangle and mirrored, and drops terms whose weight is
/// round-off of J (an axis-aligned element's off-diagonal, ≈ 1e-21 of the largest): each term maps
/// constants and linears to zero on its own, so the kernel is kept, and its share of K is far
/// below double precision.
void tensor_form_matrix(const DerivativeMoments<LongDoubleMatrix>& x, const DerivativeMoments<LongDoubleMatrix>& y,
                        const AffineTerms<long double>& terms, LongDoubleMatrix& k);
void tensor_form_matrix(const DerivativeMoments<DoubleDoubleMatrix>& x, const DerivativeMoments<DoubleDoubleMatrix>& y,
                        const AffineTerms<DoubleDouble>& terms, DoubleDoubleMatrix& k);

/// Cᵀ K C (active × active) for a symmetric K (local × local) and the extraction C (local ×
/// active), over the nonzeros of C (a WS4 extraction has ≈ 800 of 2601 entries; skipping exact
/// zeros changes no term). Extractions mix coefficients of very different sizes: a double product
/// loses digits to cancellation that the biharmonic system (conditioned like h⁻⁴) amplifies into
/// an error floor, hence long double sums, and for the residuals double-double ones (products
/// C_im K_ij exact, sums compensated: ≈ 1e-32 of Σ|C||K||C| instead of long double's 5e-20).
template <class MatrixK>  // Eigen::MatrixXd or LongDoubleMatrix
void symmetric_congruence(const Eigen::MatrixXd& c, const MatrixK& k, LongDoubleMatrix& out);
void symmetric_congruence(const Eigen::MatrixXd& c, const DoubleDoubleMatrix& k, DoubleDoubleMatrix& out);

/// Cᵀ K C for `form` on the element of `jacobian`, K from the reference integrals `r` (all in one
/// call): in double (K from the double tables, the product summed in long double and rounded
/// once), long double or double-double.
void affine_element_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian, const ReferenceIntegrals<Eigen::MatrixXd>& r,
                           const Eigen::MatrixXd& c, Eigen::MatrixXd& out);
void affine_element_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian, const ReferenceIntegrals<LongDoubleMatrix>& r,
                           const Eigen::MatrixXd& c, LongDoubleMatrix& out);
void affine_element_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian,
                           const ReferenceIntegrals<DoubleDoubleMatrix>& r, const Eigen::MatrixXd& c,
                           DoubleDoubleMatrix& out);

}  // namespace iga
