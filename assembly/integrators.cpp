#include "assembly/integrators.hpp"

#include <cmath>

namespace iga {

void Integrator::scale(DoubleDoubleMatrix& local, double c) {
  for (Eigen::Index j = 0; j < local.cols(); ++j)
    for (Eigen::Index i = 0; i < local.rows(); ++i) local.set(i, j, local(i, j) * c);
}

Form::Form(BilinearForm kind, double coefficient) {
  // Indexed by the tag (the order of bilinear_form.hpp); coefficient 1 shares one object.
  using Make = std::shared_ptr<const Integrator> (*)(double);
  static constexpr Make make[kNumBilinearForms] = {mass_integrator, stiffness_integrator, bilaplace_integrator,
                                                   hessian_integrator};
  static const std::shared_ptr<const Integrator> unit[kNumBilinearForms] = {
      make[0](1.0), make[1](1.0), make[2](1.0), make[3](1.0)};
  const int k = static_cast<int>(kind);
  integrator_ = coefficient == 1.0 ? unit[k] : make[k](coefficient);
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

// Σ_t f_t A_t diag(w) A_tᵀ accumulated in the scalar of `local` (double, or long double for the
// extended-precision residuals); the operands' low parts are below what these sums resolve.
template <class Local>
void squares_matrix(const SymmetricSquaresIntegrator& form, const ElementValues& ev, Local& local) {
  using Scalar = typename Local::Scalar;
  thread_local SymmetricSquaresIntegrator::Scratch scratch;
  SymmetricSquaresIntegrator::Operand ops[SymmetricSquaresIntegrator::kMaxOperands];
  const int count = form.operands(ev.values(), scratch, ops);
  const int n = ev.num_functions();
  local.setZero(n, n);
  for (int t = 0; t < count; ++t) add_weighted_square(*ops[t].hi, ev.jxw(), Scalar(ops[t].factor), local);
  for (int j = 0; j < n; ++j)
    for (int i = j + 1; i < n; ++i) local(i, j) = local(j, i);
}
}  // namespace

void SymmetricSquaresIntegrator::unit_matrix(const ElementValues& ev, Eigen::MatrixXd& local) const {
  squares_matrix(*this, ev, local);
}
void SymmetricSquaresIntegrator::unit_matrix(const ElementValues& ev, MatrixXld& local) const {
  squares_matrix(*this, ev, local);
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

void SymmetricSquaresIntegrator::unit_matrix(const ElementValues& ev, DoubleDoubleMatrix& local) const {
  thread_local Scratch scratch;
  thread_local Eigen::MatrixXd s, e, zero;
  Operand ops[kMaxOperands];
  const int count = operands(ev.values(), scratch, ops);
  const int n = ev.num_functions();
  s.setZero(n, n);
  e.setZero(n, n);
  zero.setZero(n, ev.num_points());
  for (int t = 0; t < count; ++t)
    add_weighted_square_double_double(*ops[t].hi, ops[t].lo ? *ops[t].lo : zero, ev.jxw(), ops[t].factor, s, e);
  local.resize(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= j; ++i) {
      const DoubleDouble d = dd_detail::quick_two_sum(s(i, j), e(i, j));
      local.set(i, j, d);
      local.set(j, i, d);
    }
}

namespace {
bool on_surface(const PointValues& v) { return v.dz.size() > 0; }

/// A standard form: its tag names it and is its closed-form key.
template <BilinearForm Kind, unsigned Flags>
class Standard : public SymmetricSquaresIntegrator {
 public:
  using SymmetricSquaresIntegrator::SymmetricSquaresIntegrator;
  unsigned flags() const override { return Flags; }
  std::string name() const override { return to_string(Kind); }
  std::optional<BilinearForm> closed_form_kind() const override { return Kind; }
};

class MassIntegrator final : public Standard<BilinearForm::mass, update_values> {
 public:
  using Standard::Standard;
  int operands(const PointValues& v, Scratch&, Operand (&out)[kMaxOperands]) const override {
    out[0] = {&v.value, nullptr, 1};
    return 1;
  }
};

class StiffnessIntegrator final : public Standard<BilinearForm::laplace, update_gradients> {
 public:
  using Standard::Standard;
  int operands(const PointValues& v, Scratch&, Operand (&out)[kMaxOperands]) const override {
    out[0] = {&v.dx, nullptr, 1};
    out[1] = {&v.dy, nullptr, 1};
    if (!on_surface(v)) return 2;
    out[2] = {&v.dz, nullptr, 1};
    return 3;
  }
};

class BilaplaceIntegrator final : public Standard<BilinearForm::bilaplace, update_hessians> {
 public:
  using Standard::Standard;
  int operands(const PointValues& v, Scratch& scratch, Operand (&out)[kMaxOperands]) const override {
    // Δφ = trace of the Hessian as a double-double (exact in the plane): its rounding to double
    // (hi) is a perturbation of the functions, not of K, for the double and long double sums.
    scratch.hi.resize(v.dxx.rows(), v.dxx.cols());
    scratch.lo.resize(v.dxx.rows(), v.dxx.cols());
    const bool surface = v.dzz.size() > 0;
    for (Eigen::Index k = 0; k < scratch.hi.size(); ++k) {
      DoubleDouble d = dd_detail::two_sum(v.dxx.data()[k], v.dyy.data()[k]);
      if (surface) {
        const DoubleDouble t = dd_detail::two_sum(d.hi, v.dzz.data()[k]);
        d = dd_detail::quick_two_sum(t.hi, t.lo + d.lo);
      }
      scratch.hi.data()[k] = d.hi;
      scratch.lo.data()[k] = d.lo;
    }
    out[0] = {&scratch.hi, &scratch.lo, 1};
    return 1;
  }
};

class HessianIntegrator final : public Standard<BilinearForm::hessian, update_hessians> {
 public:
  using Standard::Standard;
  int operands(const PointValues& v, Scratch&, Operand (&out)[kMaxOperands]) const override {
    // D²u : D²v over the symmetric entries, off-diagonal ones twice.
    out[0] = {&v.dxx, nullptr, 1};
    out[1] = {&v.dxy, nullptr, 2};
    out[2] = {&v.dyy, nullptr, 1};
    if (v.dzz.size() == 0) return 3;
    out[3] = {&v.dxz, nullptr, 2};
    out[4] = {&v.dyz, nullptr, 2};
    out[5] = {&v.dzz, nullptr, 1};
    return 6;
  }
};

template <class T>
std::shared_ptr<const Integrator> make(double coefficient) {
  return std::make_shared<const T>(coefficient);
}
}  // namespace

std::shared_ptr<const Integrator> mass_integrator(double c) { return make<MassIntegrator>(c); }
std::shared_ptr<const Integrator> stiffness_integrator(double c) { return make<StiffnessIntegrator>(c); }
std::shared_ptr<const Integrator> bilaplace_integrator(double c) { return make<BilaplaceIntegrator>(c); }
std::shared_ptr<const Integrator> hessian_integrator(double c) { return make<HessianIntegrator>(c); }

}  // namespace iga
