#pragma once
/// @file
/// Univariate polynomials in the monomial basis over a field T (double, or an exact rational type
/// for the paper's GCD method), and 3-vectors of them. Degrees here stay small (≤ 25).

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace iga::rsd {

/// Exact zero test of the coefficient field; for double this is `x == 0` (callers apply their
/// own tolerances). Specialised for exact rational types that do not return bool from ==.
template <class T>
struct Field {
  static bool is_zero(const T& x) { return x == T(0); }
};

/// p(t) = Σ c[k] t^k. The zero polynomial has no coefficients (degree −1).
template <class T>
struct Poly {
  std::vector<T> c;

  Poly() = default;
  explicit Poly(std::vector<T> coefficients) : c(std::move(coefficients)) { trim(); }
  static Poly constant(const T& a) { return Poly(std::vector<T>{a}); }
  static Poly monomial(int k, const T& a = T(1)) {
    std::vector<T> v(k + 1, T(0));
    v[k] = a;
    return Poly(v);
  }

  /// Drops exactly-zero leading coefficients.
  void trim() {
    while (!c.empty() && Field<T>::is_zero(c.back())) c.pop_back();
  }
  int degree() const { return static_cast<int>(c.size()) - 1; }
  bool is_zero() const { return c.empty(); }
  T coefficient(int k) const { return k >= 0 && k < static_cast<int>(c.size()) ? c[k] : T(0); }
  T lead() const { return c.back(); }

  T operator()(const T& t) const {
    T value(0);
    for (auto k = c.size(); k-- > 0;) value = value * t + c[k];
    return value;
  }
  Poly derivative() const {
    std::vector<T> d;
    for (std::size_t k = 1; k < c.size(); ++k) d.push_back(T(static_cast<int>(k)) * c[k]);
    return Poly(d);
  }
  /// q(t) = p(1 − t).
  Poly reflected() const {
    Poly result;
    const Poly one_minus_t(std::vector<T>{T(1), T(-1)});
    for (auto k = c.size(); k-- > 0;) result = result * one_minus_t + constant(c[k]);
    return result;
  }

  friend Poly operator+(const Poly& a, const Poly& b) {
    std::vector<T> s(std::max(a.c.size(), b.c.size()), T(0));
    for (std::size_t k = 0; k < a.c.size(); ++k) s[k] = s[k] + a.c[k];
    for (std::size_t k = 0; k < b.c.size(); ++k) s[k] = s[k] + b.c[k];
    return Poly(s);
  }
  friend Poly operator-(const Poly& a, const Poly& b) { return a + (-b); }
  friend Poly operator-(const Poly& a) {
    Poly r = a;
    for (auto& x : r.c) x = -x;
    return r;
  }
  friend Poly operator*(const Poly& a, const Poly& b) {
    if (a.is_zero() || b.is_zero()) return {};
    std::vector<T> s(a.c.size() + b.c.size() - 1, T(0));
    for (std::size_t i = 0; i < a.c.size(); ++i)
      for (std::size_t j = 0; j < b.c.size(); ++j) s[i + j] = s[i + j] + a.c[i] * b.c[j];
    return Poly(s);
  }
  friend Poly operator*(const T& a, const Poly& b) {
    Poly r = b;
    for (auto& x : r.c) x = a * x;
    r.trim();
    return r;
  }
};

/// Quotient and remainder of a ÷ b (b ≠ 0), deg remainder < deg b.
template <class T>
std::pair<Poly<T>, Poly<T>> divide(const Poly<T>& a, const Poly<T>& b) {
  std::vector<T> r = a.c;
  const int db = b.degree();
  std::vector<T> q(std::max(0, a.degree() - db + 1), T(0));
  for (int k = a.degree() - db; k >= 0; --k) {
    const T factor = r[k + db] / b.lead();
    q[k] = factor;
    for (int l = 0; l <= db; ++l) r[k + l] = r[k + l] - factor * b.c[l];
    r[k + db] = T(0);  // exact cancellation also in floating point
  }
  r.resize(std::max(0, db));
  return {Poly<T>(q), Poly<T>(r)};
}

/// A 3-vector of polynomials: a polynomial curve in R^3.
template <class T>
using VecPoly = std::array<Poly<T>, 3>;

template <class T>
VecPoly<T> operator+(const VecPoly<T>& a, const VecPoly<T>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class T>
VecPoly<T> operator-(const VecPoly<T>& a, const VecPoly<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
VecPoly<T> operator*(const Poly<T>& s, const VecPoly<T>& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
/// s(t)·x for a constant vector x.
template <class T>
VecPoly<T> times(const Poly<T>& s, const std::array<T, 3>& x) {
  return {x[0] * s, x[1] * s, x[2] * s};
}
template <class T>
Poly<T> dot(const VecPoly<T>& a, const VecPoly<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
VecPoly<T> cross(const VecPoly<T>& a, const VecPoly<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
int degree(const VecPoly<T>& a) {
  return std::max({a[0].degree(), a[1].degree(), a[2].degree()});
}

}  // namespace iga::rsd
