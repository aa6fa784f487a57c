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
}  // namespace

void element_matrix(BilinearForm form, const ElementValues& ev, Eigen::MatrixXd& local) {
  const PointValues& v = ev.values();
  const Eigen::VectorXd& w = ev.jxw();
  const int n = ev.num_functions();
  local.setZero(n, n);
  switch (form) {
    case BilinearForm::mass:
      add_weighted_product(v.value, v.value, w, 1.0, local);
      break;
    case BilinearForm::laplace:
      add_weighted_product(v.dx, v.dx, w, 1.0, local);
      add_weighted_product(v.dy, v.dy, w, 1.0, local);
      if (v.dz.size() > 0) add_weighted_product(v.dz, v.dz, w, 1.0, local);  // surfaces in 3D
      break;
    case BilinearForm::bilaplace: {
      const Eigen::MatrixXd lap = v.dxx + v.dyy;
      add_weighted_product(lap, lap, w, 1.0, local);
      break;
    }
    case BilinearForm::hessian:
      add_weighted_product(v.dxx, v.dxx, w, 1.0, local);
      add_weighted_product(v.dxy, v.dxy, w, 2.0, local);
      add_weighted_product(v.dyy, v.dyy, w, 1.0, local);
      break;
  }
}

void element_load(const ScalarField& f, const ElementValues& ev, Eigen::VectorXd& local) {
  const PointValues& v = ev.values();
  const int q = ev.num_points();
  Eigen::VectorXd fw(q);
  for (int k = 0; k < q; ++k) fw(k) = f(v.x.col(k)) * ev.jxw()(k);
  local.noalias() = v.value * fw;
}

}  // namespace iga
