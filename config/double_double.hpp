#pragma once
/// @file
/// Double-double arithmetic: a number kept as an unevaluated sum hi + lo of two doubles (about 32
/// significant digits, relative rounding ≈ 1e-32), with error-free transformations (two-sum and
/// an FMA two-product). Used where long double (≈ 5e-20) is not enough: residuals and element
/// matrices of fourth-order problems, whose conditioning (h⁻⁴) amplifies the rounding of every
/// entry into an error that grows under refinement.

#include <Eigen/Core>
#include <cmath>

#include "config/cpu_dispatch.hpp"

namespace iga {

struct DoubleDouble {
  double hi = 0, lo = 0;

  DoubleDouble() = default;
  constexpr DoubleDouble(double h) : hi(h), lo(0) {}  // NOLINT: a double is exactly a double-double
  constexpr DoubleDouble(double h, double l) : hi(h), lo(l) {}

  /// The value rounded to double (hi, by construction).
  explicit operator double() const { return hi; }
  /// The value rounded to long double.
  long double to_long_double() const { return static_cast<long double>(hi) + lo; }
  static DoubleDouble from_long_double(long double x) {
    const double h = static_cast<double>(x);
    return {h, static_cast<double>(x - h)};
  }
};

namespace dd_detail {
/// a + b = s + e exactly (Knuth).
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
/// a + b = s + e exactly when |a| >= |b|.
inline DoubleDouble quick_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
/// a b = p + e exactly: with a hardware FMA when the build targets one, else Dekker's splitting
/// (the same exact result; std::fma without the instruction is a slow library call).
inline DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
#ifdef __FMA__
  return {p, std::fma(a, b, -p)};
#else
  constexpr double split = 134217729.0;  // 2^27 + 1
  const double ta = split * a, tb = split * b;
  const double ah = ta - (ta - a), al = a - ah, bh = tb - (tb - b), bl = b - bh;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
#endif
}
}  // namespace dd_detail

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  // The accurate addition (two two-sums): relative error ≈ 2⁻¹⁰⁴ even under cancellation.
  DoubleDouble s = dd_detail::two_sum(a.hi, b.hi);
  const DoubleDouble t = dd_detail::two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = dd_detail::quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return dd_detail::quick_two_sum(s.hi, s.lo);
}
inline DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }
inline DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) { return a + (-b); }
inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  DoubleDouble p = dd_detail::two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return dd_detail::quick_two_sum(p.hi, p.lo);
}
inline DoubleDouble operator*(const DoubleDouble& a, double b) {
  DoubleDouble p = dd_detail::two_prod(a.hi, b);
  p.lo += a.lo * b;
  return dd_detail::quick_two_sum(p.hi, p.lo);
}
inline DoubleDouble operator*(double a, const DoubleDouble& b) { return b * a; }
inline DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
  // One Newton correction of the double quotient.
  const double q1 = a.hi / b.hi;
  const DoubleDouble r = a - b * q1;
  const double q2 = r.hi / b.hi;
  const DoubleDouble r2 = r - b * q2;
  const double q3 = r2.hi / b.hi;
  DoubleDouble q = dd_detail::quick_two_sum(q1, q2);
  return q + DoubleDouble(q3);
}
inline DoubleDouble& operator+=(DoubleDouble& a, const DoubleDouble& b) { return a = a + b; }
inline DoubleDouble& operator-=(DoubleDouble& a, const DoubleDouble& b) { return a = a - b; }
inline DoubleDouble& operator*=(DoubleDouble& a, const DoubleDouble& b) { return a = a * b; }

/// s += a b for doubles a, b, with the product exact before the addition.
inline void add_product(DoubleDouble& s, double a, double b) { s += dd_detail::two_prod(a, b); }
/// s += a b for a double-double a and a double b.
inline void add_product(DoubleDouble& s, const DoubleDouble& a, double b) { s += a * b; }

inline DoubleDouble& operator/=(DoubleDouble& a, const DoubleDouble& b) { return a = a / b; }

/// Hot double-double kernels are compiled twice: for the x86-64 baseline the package targets and,
/// under [[gnu::target("avx2,fma")]], for CPUs with AVX2 and FMA (every x86-64 of the last
/// decade), chosen at run time by cpu_has_avx2_fma() (config/cpu_dispatch.hpp). Inside the FMA
/// copy, products must come from exact_product<true>: Dekker's splitting (two_prod without
/// __FMA__) is unsafe there, as the compiler may contract its products into FMAs and spoil the
/// split.
template <bool kFma>
[[gnu::always_inline]] inline DoubleDouble exact_product(double a, double b) {
  if constexpr (kFma) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
  } else {
    return dd_detail::two_prod(a, b);
  }
}
/// a · b as operator*, with the product of exact_product<kFma>.
template <bool kFma>
[[gnu::always_inline]] inline DoubleDouble multiply(const DoubleDouble& a, const DoubleDouble& b) {
  DoubleDouble p = exact_product<kFma>(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return dd_detail::quick_two_sum(p.hi, p.lo);
}

inline bool operator==(const DoubleDouble& a, const DoubleDouble& b) { return a.hi == b.hi && a.lo == b.lo; }
inline bool operator!=(const DoubleDouble& a, const DoubleDouble& b) { return !(a == b); }
inline bool operator<(const DoubleDouble& a, const DoubleDouble& b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
inline bool operator>(const DoubleDouble& a, const DoubleDouble& b) { return b < a; }

inline DoubleDouble abs(const DoubleDouble& a) { return a.hi < 0 ? -a : a; }
/// Square root: one Newton step from the double root (for a >= 0).
inline DoubleDouble sqrt(const DoubleDouble& a) {
  if (a.hi <= 0) return DoubleDouble(0.0);
  const double s = std::sqrt(a.hi);
  const DoubleDouble r = a - dd_detail::two_prod(s, s);
  return dd_detail::quick_two_sum(s, r.hi / (2 * s));
}

/// A dense matrix of double-doubles as two double matrices (entry (i, j) = hi(i, j) + lo(i, j)).
struct DoubleDoubleMatrix {
  using Scalar = DoubleDouble;
  Eigen::MatrixXd hi, lo;
  DoubleDouble operator()(Eigen::Index i, Eigen::Index j) const { return {hi(i, j), lo(i, j)}; }
  void set(Eigen::Index i, Eigen::Index j, const DoubleDouble& v) {
    hi(i, j) = v.hi;
    lo(i, j) = v.lo;
  }
  void resize(Eigen::Index rows, Eigen::Index cols) {
    hi.resize(rows, cols);
    lo.resize(rows, cols);
  }
  Eigen::Index rows() const { return hi.rows(); }
  Eigen::Index cols() const { return hi.cols(); }
  /// Entries of a long double matrix, exactly (a long double has 64 significant bits).
  template <class Matrix>
  static DoubleDoubleMatrix from_long_double(const Matrix& m) {
    DoubleDoubleMatrix out;
    out.resize(m.rows(), m.cols());
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) out.set(i, j, DoubleDouble::from_long_double(m(i, j)));
    return out;
  }
};

}  // namespace iga
