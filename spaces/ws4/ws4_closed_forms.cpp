#include "spaces/ws4/ws4_closed_forms.hpp"

#include "spaces/ws4/ws4_reference_matrices.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {

Ws4ClosedForms::Ws4ClosedForms(const Ws4Space& space) : space_(space), cache_(space.shape_classes().count) {}

bool Ws4ClosedForms::rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const {
  local = symmetric_congruence_extended(space_.extraction(element), ws4_form_matrix(form, space_.jacobian(element)));
  return true;
}

bool Ws4ClosedForms::extended(int element, BilinearForm form, LongDoubleMatrix& local) const {
  ws4_element_matrix_extended(form, space_.jacobian(element), space_.extraction(element), local);
  return true;
}

bool Ws4ClosedForms::double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  // Every element of a class has the same J (its translated corners) and extraction.
  cache_.get(space_.shape_classes().of_element[element], form, local, [&](DoubleDoubleMatrix& out) {
    ws4_element_matrix_double_double(form, space_.jacobian(element), space_.extraction(element), out);
  });
  return true;
}

void Ws4ClosedForms::prepare_double_double(BilinearForm form) const {
  prepare_reference_matrices_double_double(form);
  cache_.build_all(form, [&](int cls, DoubleDoubleMatrix& out) {
    const int element = space_.shape_classes().representative[cls];
    ws4_element_matrix_double_double(form, space_.jacobian(element), space_.extraction(element), out);
  });
}

const DoubleDoubleMatrix* Ws4ClosedForms::shared_double_double(int element, BilinearForm form) const {
  return cache_.find(space_.shape_classes().of_element[element], form);
}

}  // namespace iga::ws4
