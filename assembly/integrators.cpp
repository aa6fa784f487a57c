#include "assembly/integrators.hpp"

#include <cmath>

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

namespace {
/// upper(s + e) += factor Σ_q (A_iq w_q) A_jq for A = hi + lo, with exact products and the sums'
/// rounding kept in e (compensated, as if in double-double).
template <bool kFma>
[[gnu::always_inline]] inline void weighted_square_double_double(const Eigen::MatrixXd& hi, const Eigen::MatrixXd& lo,
                                                                 const Eigen::VectorXd& w, double factor,
                                                                 Eigen::MatrixXd& s, Eigen::MatrixXd& e) {
  const Eigen::Index n = hi.rows(), q = hi.cols();
  thread_local Eigen::MatrixXd aw_hi, aw_lo;  // factor A_iq w_q as a double-double
  aw_hi.resize(n, q);
  aw_lo.resize(n, q);
  for (Eigen::Index k = 0; k < q; ++k)
    for (Eigen::Index i = 0; i < n; ++i) {
      // (hi + lo) w factor as a double-double (factor is 1 or 2: exact).
      const double wk = w(k) * factor;
      DoubleDouble p = exact_product<kFma>(hi(i, k), wk);
      p.lo += lo(i, k) * wk;
      const DoubleDouble aw = dd_detail::quick_two_sum(p.hi, p.lo);
      aw_hi(i, k) = aw.hi;
      aw_lo(i, k) = aw.lo;
    }
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index k = 0; k < q; ++k) {
      const double b = hi(j, k), bl = lo(j, k);
      for (Eigen::Index i = 0; i <= j; ++i) {
        const DoubleDouble p = exact_product<kFma>(aw_hi(i, k), b);
        const DoubleDouble t = dd_detail::two_sum(s(i, j), p.hi);
        s(i, j) = t.hi;
        e(i, j) += t.lo + p.lo + aw_hi(i, k) * bl + aw_lo(i, k) * b;
      }
    }
}

// The hot loop of extended assembly for spaces without closed forms, compiled twice (see
// exact_product in double_double.hpp): about three times faster with AVX2 and FMA.
[[gnu::target("avx2,fma")]] void weighted_square_double_double_fma(const Eigen::MatrixXd& hi, const Eigen::MatrixXd& lo,
                                                                    const Eigen::VectorXd& w, double factor,
                                                                    Eigen::MatrixXd& s, Eigen::MatrixXd& e) {
  weighted_square_double_double<true>(hi, lo, w, factor, s, e);
}

void add_weighted_square_double_double(const Eigen::MatrixXd& hi, const Eigen::MatrixXd& lo, const Eigen::VectorXd& w,
                                       double factor, Eigen::MatrixXd& s, Eigen::MatrixXd& e) {
  if (cpu_has_avx2_fma()) return weighted_square_double_double_fma(hi, lo, w, factor, s, e);
  weighted_square_double_double<false>(hi, lo, w, factor, s, e);
}
}  // namespace

void element_matrix_double_double(BilinearForm form, const ElementValues& ev, DoubleDoubleMatrix& local) {
  const PointValues& v = ev.values();
  const Eigen::VectorXd& w = ev.jxw();
  const int n = ev.num_functions();
  thread_local Eigen::MatrixXd s, e, zero, lap_hi, lap_lo;
  s.setZero(n, n);
  e.setZero(n, n);
  zero.setZero(n, ev.num_points());
  switch (form) {
    case BilinearForm::mass:
      add_weighted_square_double_double(v.value, zero, w, 1, s, e);
      break;
    case BilinearForm::laplace:
      add_weighted_square_double_double(v.dx, zero, w, 1, s, e);
      add_weighted_square_double_double(v.dy, zero, w, 1, s, e);
      if (v.dz.size() > 0) add_weighted_square_double_double(v.dz, zero, w, 1, s, e);
      break;
    case BilinearForm::bilaplace:
      // Δφ = φ_xx + φ_yy exactly, as a double-double.
      lap_hi.resize(n, ev.num_points());
      lap_lo.resize(n, ev.num_points());
      for (Eigen::Index k = 0; k < lap_hi.size(); ++k) {
        const DoubleDouble d = dd_detail::two_sum(v.dxx.data()[k], v.dyy.data()[k]);
        lap_hi.data()[k] = d.hi;
        lap_lo.data()[k] = d.lo;
      }
      add_weighted_square_double_double(lap_hi, lap_lo, w, 1, s, e);
      break;
    case BilinearForm::hessian:
      add_weighted_square_double_double(v.dxx, zero, w, 1, s, e);
      add_weighted_square_double_double(v.dxy, zero, w, 2, s, e);
      add_weighted_square_double_double(v.dyy, zero, w, 1, s, e);
      break;
  }
  local.resize(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i) {
      const DoubleDouble d = dd_detail::quick_two_sum(s(i, j), e(i, j));
      local.set(i, j, d);
      local.set(j, i, d);
    }
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
