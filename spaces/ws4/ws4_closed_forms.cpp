#include "spaces/ws4/ws4_closed_forms.hpp"

#include "spaces/ws4/ws4_reference_matrices.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {

Ws4ClosedForms::Ws4ClosedForms(const Ws4Space& space) : space_(space), cache_(space.shape_classes().count) {}

bool Ws4ClosedForms::rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const {
  affine_element_matrix(form, space_.jacobian(element), ws4_reference_integrals(), space_.extraction(element), local);
  return true;
}

bool Ws4ClosedForms::extended(int element, BilinearForm form, LongDoubleMatrix& local) const {
  affine_element_matrix(form, space_.jacobian(element), ws4_reference_integrals_extended(), space_.extraction(element),
                        local);
  return true;
}

void Ws4ClosedForms::compute_double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  affine_element_matrix(form, space_.jacobian(element), ws4_reference_integrals_double_double(form),
                        space_.extraction(element), local);
}

bool Ws4ClosedForms::double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  // Every element of a class has the same J (its translated corners) and extraction.
  cache_.get(space_.class_of(element), form, local,
             [&](DoubleDoubleMatrix& out) { compute_double_double(element, form, out); });
  return true;
}

void Ws4ClosedForms::prepare_double_double(BilinearForm form) const {
  ws4_reference_integrals_double_double(form);
  cache_.build_all(form, [&](int cls, DoubleDoubleMatrix& out) {
    compute_double_double(space_.shape_classes().representative[cls], form, out);
  });
}

const DoubleDoubleMatrix* Ws4ClosedForms::shared_double_double(int element, BilinearForm form) const {
  return cache_.find(space_.class_of(element), form);
}

}  // namespace iga::ws4
