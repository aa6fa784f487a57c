#pragma once
/// @file
/// Closed-form element matrices of a TMeshSpace. The cell map is a diagonal scaling and the local
/// basis a tensor product, so every form is a sum of Kronecker products of 1D integrals
/// ∫ B_i^(a) B_k^(b) over the cell's sides (the tensor path of affine_element_matrices.hpp):
/// E_c K_c E_cᵀ with K_c from side integrals computed once per (section, side length) with the
/// Gauss rule of assembly (2n + 1, plus kFullExtraDegree for non-polynomial sections: the
/// coarse-cell rule, i.e. the tensor rule's sums, separated; finer than quadrature() on fine cells).

#include <cstdint>
#include <map>

#include "spaces/affine_element_matrices.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/tmesh/tmesh_space.hpp"

namespace iga {

class TMeshClosedForms final : public ClosedForms {
 public:
  /// The side integrals of every Bernstein basis of `space` (which must outlive this object).
  explicit TMeshClosedForms(const TMeshSpace& space);

 protected:
  /// The long double matrix, rounded once.
  bool rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const override;
  /// Accumulated in long double.
  bool extended(int element, BilinearForm form, LongDoubleMatrix& local) const override;
  /// For the solver's residuals (the long double sums would bring back the plates' round-off
  /// floor): side integrals summed from exact products, K_c per (form, sections, side lengths)
  /// computed once per thread; cells with the same K_c and E_c reuse the result.
  bool double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const override;

 private:
  const TMeshSpace& space_;
  /// Per (section, side length): moment[a][b](i, k) = ∫_0^1 ∂^a B_i ∂^b B_k in reference
  /// coordinates (a, b <= 2), in long double and in double-double.
  std::map<CellSideKey, DerivativeMoments<LongDoubleMatrix>> side_integrals_;
  std::map<CellSideKey, DerivativeMoments<DoubleDoubleMatrix>> side_integrals_dd_;
  /// Distinguishes spaces in the per-thread cache of double-double cell matrices.
  std::uint64_t instance_id_ = 0;
};

}  // namespace iga
