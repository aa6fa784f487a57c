#pragma once
/// @file
/// Element matrices without quadrature: a property of (local basis, affine map, form) that some
/// spaces have (a combination of exact reference integrals of an affine-invariant basis, written
/// once in affine_element_matrices.hpp). A space that has them returns a ClosedForms from
/// Space::closed_forms(); the assembler asks it for the element matrix in the scalar it sums in
/// (double, long double or double-double), and falls back to quadrature where it answers false.

#include <type_traits>

#include "spaces/affine_element_matrices.hpp"

namespace iga {

class ClosedForms {
 public:
  virtual ~ClosedForms() = default;

  /// The element matrix of `form` on `element`, rows and columns in element_dofs order, in the
  /// scalar of `Matrix` (Eigen::MatrixXd, LongDoubleMatrix or DoubleDoubleMatrix), not rounded
  /// through a narrower one. False: no closed form here (the caller integrates). Thread-safe.
  template <class Matrix>
  bool element_matrix(int element, BilinearForm form, Matrix& local) const {
    if constexpr (std::is_same_v<Matrix, DoubleDoubleMatrix>) return double_double(element, form, local);
    else if constexpr (std::is_same_v<Matrix, LongDoubleMatrix>) return extended(element, form, local);
    else return rounded(element, form, local);
  }

  /// Before an element loop in the scalar of `Matrix`, outside any parallel region: a space whose
  /// matrices share tables (reference matrices, matrices of shape classes) builds them here with
  /// every thread, rather than inside the loop, where the first element to need them builds them
  /// on one thread while the others wait. Only double-double loops share (the others are cheap).
  template <class Matrix>
  void prepare(BilinearForm form) const {
    if constexpr (std::is_same_v<Matrix, DoubleDoubleMatrix>) prepare_double_double(form);
  }

  /// The matrix of `element` when several elements share it (valid while the space lives, after
  /// prepare): read it in place instead of computing a copy. Null when it is not shared.
  template <class Matrix>
  const Matrix* shared(int element, BilinearForm form) const {
    if constexpr (std::is_same_v<Matrix, DoubleDoubleMatrix>) return shared_double_double(element, form);
    else return nullptr;
  }

 protected:
  // What a space provides. Spaces compute in the widest scalar they have and round once; the
  // defaults widen the narrower answer (exactly: long double holds a double, a double-double a
  // long double), so a space overrides at least the narrowest scalar it has.
  virtual bool rounded(int /*element*/, BilinearForm /*form*/, Eigen::MatrixXd& /*local*/) const { return false; }
  virtual bool extended(int element, BilinearForm form, LongDoubleMatrix& local) const {
    Eigen::MatrixXd narrow;
    if (!rounded(element, form, narrow)) return false;
    local = narrow.cast<long double>();
    return true;
  }
  virtual bool double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
    LongDoubleMatrix narrow;
    if (!extended(element, form, narrow)) return false;
    local = DoubleDoubleMatrix::from_long_double(narrow);
    return true;
  }
  /// Fast path of WS4 (one matrix per shape class, ws4_shape_classes.hpp); nothing by default.
  virtual void prepare_double_double(BilinearForm /*form*/) const {}
  virtual const DoubleDoubleMatrix* shared_double_double(int /*element*/, BilinearForm /*form*/) const {
    return nullptr;
  }
};

}  // namespace iga
