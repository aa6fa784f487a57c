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
// Every form below is symmetric, a sum of A diag(w) Aᵀ: only the upper triangle is accumulated
// (half the products; the long double ones dominate assembly at high degree), then mirrored.

// upper(local) += factor A diag(w) Aᵀ (the hot loop of assembly).
void add_weighted_square(const Eigen::MatrixXd& A, const Eigen::VectorXd& w, double factor, Eigen::MatrixXd& local) {
  thread_local Eigen::MatrixXd aw;
  aw.noalias() = factor * (A * w.asDiagonal());
  local.triangularView<Eigen::Upper>() += aw * A.transpose();
}
// The same in long double.
void add_weighted_square(const Eigen::MatrixXd& A, const Eigen::VectorXd& w, long double factor, MatrixXld& local) {
  thread_local MatrixXld aw, a;
  a = A.cast<long double>();
  aw.noalias() = factor * (a * w.cast<long double>().asDiagonal());
  local.triangularView<Eigen::Upper>() += aw * a.transpose();
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
      add_weighted_square(v.value, w, Scalar(1), local);
      break;
    case BilinearForm::laplace:
      add_weighted_square(v.dx, w, Scalar(1), local);
      add_weighted_square(v.dy, w, Scalar(1), local);
      if (v.dz.size() > 0) add_weighted_square(v.dz, w, Scalar(1), local);  // surfaces in 3D
      break;
    case BilinearForm::bilaplace: {
      // Δφ rounded once per function and point: a perturbation of the functions, not of K.
      const Eigen::MatrixXd lap = v.dxx + v.dyy;
      add_weighted_square(lap, w, Scalar(1), local);
      break;
    }
    case BilinearForm::hessian:
      add_weighted_square(v.dxx, w, Scalar(1), local);
      add_weighted_square(v.dxy, w, Scalar(2), local);
      add_weighted_square(v.dyy, w, Scalar(1), local);
      break;
  }
  for (int j = 0; j < n; ++j)
    for (int i = j + 1; i < n; ++i) local(i, j) = local(j, i);
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
