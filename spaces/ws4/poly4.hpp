#pragma once
/// @file
/// Poly4: a bivariate polynomial of total degree <= 4, the piece of a WS4 basis function on one
/// region of the split. Dense, 15 monomial coefficients. The scalar type is a parameter so the
/// one-time construction can run in long double.

#include <array>
#include <stdexcept>

#include "quadrature/quadrature_rule.hpp"

namespace iga::ws4 {

template <class T>
class BasicPoly4 {
 public:
  static constexpr int max_degree = 4;
  static constexpr int size = 15;  ///< number of monomials x^a y^b with a + b <= 4

  /// Index of x^a y^b: monomials ordered by total degree, then by increasing b.
  static constexpr int index(int a, int b) { return (a + b) * (a + b + 1) / 2 + b; }

  BasicPoly4() { c_.fill(T(0)); }
  static BasicPoly4 constant(T v) {
    BasicPoly4 p;
    p.c_[0] = v;
    return p;
  }
  /// The same polynomial with coefficients converted to scalar type U.
  template <class U>
  BasicPoly4<U> cast() const {
    BasicPoly4<U> r;
    for (int a = 0; a <= max_degree; ++a)
      for (int b = 0; a + b <= max_degree; ++b) r.coefficient(a, b) = static_cast<U>(coefficient(a, b));
    return r;
  }

  T coefficient(int a, int b) const { return c_[index(a, b)]; }
  T& coefficient(int a, int b) { return c_[index(a, b)]; }

  /// this += s * p
  void add_scaled(T s, const BasicPoly4& p) {
    for (int k = 0; k < size; ++k) c_[k] += s * p.c_[k];
  }

  /// (c0 + c1 x + c2 y) * this; requires the degree-4 part of this to be zero unless c1 = c2 = 0.
  BasicPoly4 times_affine(T c0, T c1, T c2) const {
    BasicPoly4 r;
    for (int n = 0; n <= max_degree; ++n)
      for (int b = 0; b <= n; ++b) {
        const T v = c_[index(n - b, b)];
        if (v == T(0)) continue;
        if (n == max_degree && (c1 != T(0) || c2 != T(0)))
          throw std::logic_error("Poly4::times_affine: degree would exceed 4");
        r.c_[index(n - b, b)] += c0 * v;
        if (n < max_degree) {
          r.c_[index(n - b + 1, b)] += c1 * v;
          r.c_[index(n - b, b + 1)] += c2 * v;
        }
      }
    return r;
  }

  /// d/dx (axis 0) or d/dy (axis 1).
  BasicPoly4 derivative(int axis) const {
    BasicPoly4 r;
    for (int n = 1; n <= max_degree; ++n)
      for (int b = 0; b <= n; ++b) {
        const int a = n - b;
        const T v = c_[index(a, b)];
        if (axis == 0 && a > 0) r.c_[index(a - 1, b)] += T(a) * v;
        if (axis == 1 && b > 0) r.c_[index(a, b - 1)] += T(b) * v;
      }
    return r;
  }

  /// Directional derivative along the vector w (not normalised).
  BasicPoly4 directional(const Point2& w) const {
    BasicPoly4 r = derivative(0);
    for (T& v : r.c_) v *= T(w.x());
    r.add_scaled(T(w.y()), derivative(1));
    return r;
  }

  T operator()(const Point2& x) const { return (*this)(T(x.x()), T(x.y())); }
  T operator()(T x, T y) const {
    // Horner in y within each power of x: sum_a x^a (sum_b c_ab y^b).
    T result = T(0);
    for (int a = max_degree; a >= 0; --a) {
      T inner = T(0);
      for (int b = max_degree - a; b >= 0; --b) inner = inner * y + c_[index(a, b)];
      result = result * x + inner;
    }
    return result;
  }

  bool is_zero() const {
    for (const T& v : c_)
      if (v != T(0)) return false;
    return true;
  }

 private:
  std::array<T, size> c_;
};

using Poly4 = BasicPoly4<double>;

}  // namespace iga::ws4
