#pragma once
/// @file
/// Closed-form element matrices of a Ws4Space: C_Kᵀ K_B C_K with K_B from the universal reference
/// matrices of the 51 simplex splines (ws4_reference_matrices.hpp) under the element's affine map
/// (affine_element_matrices.hpp).
/// The double-double matrices are computed once per shape class shared by several elements
/// (ws4_shape_classes.hpp): the documented fast path behind prepare and shared.

#include "spaces/closed_forms.hpp"
#include "spaces/ws4/ws4_shape_classes.hpp"

namespace iga::ws4 {

class Ws4Space;

class Ws4ClosedForms final : public ClosedForms {
 public:
  /// `space` must outlive this object.
  explicit Ws4ClosedForms(const Ws4Space& space);

 protected:
  /// K_B from the double tables, the product accumulated in long double, rounded once.
  bool rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const override;
  bool extended(int element, BilinearForm form, LongDoubleMatrix& local) const override;
  /// The cached matrix of the element's shape class, or computed.
  bool double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const override;
  /// The reference tables of `form` and the matrices of every shared shape class, with all threads.
  void prepare_double_double(BilinearForm form) const override;
  /// The cached matrix of the element's shape class (after prepare).
  const DoubleDoubleMatrix* shared_double_double(int element, BilinearForm form) const override;

 private:
  /// The element's own double-double matrix (no cache).
  void compute_double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const;

  const Ws4Space& space_;
  ElementMatrixCache cache_;
};

}  // namespace iga::ws4
