#include "assembly/integrators.hpp"

namespace iga {

unsigned flags_for(BilinearForm form) {
  switch (form) {
    case BilinearForm::mass: return update_values;
    case BilinearForm::laplace: return update_gradients;
    case BilinearForm::bilaplace:
    case BilinearForm::hessian: return update_hessians;
  }
  return update_values;
}

std::string to_string(BilinearForm form) {
  switch (form) {
    case BilinearForm::mass: return "mass";
    case BilinearForm::laplace: return "laplace";
    case BilinearForm::bilaplace: return "bilaplace";
    case BilinearForm::hessian: return "hessian";
  }
  return "?";
}

namespace {
// local += A diag(w) B^T, written as one matrix product (the hot loop of assembly).
void add_weighted_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::VectorXd& w,
                          double factor, Eigen::MatrixXd& local) {
  local.noalias() += factor * (A * w.asDiagonal()) * B.transpose();
}
// local += factor A diag(w) Bᵀ in long double.
void add_weighted_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::VectorXd& w,
                          long double factor, MatrixXld& local) {
  thread_local MatrixXld aw, b;
  aw = A.cast<long double>() * w.cast<long double>().asDiagonal();
  b = B.cast<long double>();
  local.noalias() += factor * aw * b.transpose();
}

// The element matrix of `form`, accumulated in the scalar type of `local` (double, or long double
// for the extended-precision residuals).
template <class Local>
void form_matrix(BilinearForm form, const ElementValues& ev, Local& local) {
  using Scalar = typename Local::Scalar;
  const PointValues& v = ev.values();
  const Eigen::VectorXd& w = ev.jxw();
  const int n = ev.num_functions();
  local.setZero(n, n);
  switch (form) {
    case BilinearForm::mass:
      add_weighted_product(v.value, v.value, w, Scalar(1), local);
      break;
    case BilinearForm::laplace:
      add_weighted_product(v.dx, v.dx, w, Scalar(1), local);
      add_weighted_product(v.dy, v.dy, w, Scalar(1), local);
      if (v.dz.size() > 0) add_weighted_product(v.dz, v.dz, w, Scalar(1), local);  // surfaces in 3D
      break;
    case BilinearForm::bilaplace: {
      // Δφ rounded once per function and point: a perturbation of the functions, not of K.
      const Eigen::MatrixXd lap = v.dxx + v.dyy;
      add_weighted_product(lap, lap, w, Scalar(1), local);
      break;
    }
    case BilinearForm::hessian:
      add_weighted_product(v.dxx, v.dxx, w, Scalar(1), local);
      add_weighted_product(v.dxy, v.dxy, w, Scalar(2), local);
      add_weighted_product(v.dyy, v.dyy, w, Scalar(1), local);
      break;
  }
}
}  // namespace

void element_matrix_extended(BilinearForm form, const ElementValues& ev, MatrixXld& local) {
  form_matrix(form, ev, local);
}

void element_matrix(BilinearForm form, const ElementValues& ev, Eigen::MatrixXd& local) { form_matrix(form, ev, local); }

void element_load(const ScalarField& f, const ElementValues& ev, Eigen::VectorXd& local) {
  const PointValues& v = ev.values();
  const int q = ev.num_points();
  Eigen::VectorXd fw(q);
  for (int k = 0; k < q; ++k) fw(k) = f(v.x.col(k)) * ev.jxw()(k);
  local.noalias() = v.value * fw;
}

}  // namespace iga
