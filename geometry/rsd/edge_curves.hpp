#pragma once
/// @file
/// The data of the uncorrected RSD interpolant restricted to a double edge (note §3.2), as
/// univariate polynomials in t = λ_i (t = 1 at p_i, t = 0 at p_j, i < j):
///   c(t) edge curve, u = c', v = D_{u_m} f_n, v̄ = D_{ū_m} f_n̄ with u_m = p_k − ½(p_i + p_j).
/// By the RSD property they depend only on the data at the two end vertices.

#include "geometry/rsd/rsd_tuple.hpp"

namespace iga::rsd {

template <class T>
using Vec3 = std::array<T, 3>;

/// First-order data seen from one double edge (i < j, third vertices k and k̄).
template <class T>
struct EdgeEndData {
  Vec3<T> f_i, f_j;
  Vec3<T> g_ij, g_ji;
  Vec3<T> g_ik, g_jk;        ///< towards k (triangle n)
  Vec3<T> g_ikbar, g_jkbar;  ///< towards k̄ (triangle n̄)
};

template <class T>
struct EdgeCurves {
  VecPoly<T> c, u, v, vbar;
  VecPoly<T> d() const { return vbar - v; }
  /// w = d × u (this sign, so that Δ = det[v, v̄, u] = ⟨v, w⟩).
  VecPoly<T> w() const { return cross(d(), u); }
  Poly<T> Delta() const { return dot(v, w()); }
};

template <class T>
Vec3<T> combine(const T& a, const Vec3<T>& x, const T& b, const Vec3<T>& y) {
  return {a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2]};
}

template <class T>
EdgeCurves<T> edge_curves(RsdTuple tuple, const EdgeEndData<T>& e) {
  const Poly<T> p0 = psi0<T>(tuple), p1 = psi1<T>(tuple);
  const Poly<T> p0r = p0.reflected(), p1r = p1.reflected();
  const Poly<T> t = Poly<T>::monomial(1), one_minus_t(std::vector<T>{T(1), T(-1)});
  EdgeCurves<T> curves;
  curves.c = times(p0, e.f_i) + times(p0r, e.f_j) + times(one_minus_t * p1, e.g_ij) + times(t * p1r, e.g_ji);
  curves.u = {curves.c[0].derivative(), curves.c[1].derivative(), curves.c[2].derivative()};
  const T half = T(1) / T(2);
  curves.v = times(p1, combine(T(1), e.g_ik, -half, e.g_ij)) + times(p1r, combine(T(1), e.g_jk, -half, e.g_ji));
  curves.vbar =
      times(p1, combine(T(1), e.g_ikbar, -half, e.g_ij)) + times(p1r, combine(T(1), e.g_jkbar, -half, e.g_ji));
  return curves;
}

/// s(t) = t²(1 − t)², the factor every correction term carries on its edge.
template <class T>
Poly<T> edge_bubble() {
  return Poly<T>(std::vector<T>{T(0), T(0), T(1), T(-2), T(1)});
}

}  // namespace iga::rsd
