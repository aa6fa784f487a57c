#pragma once
/// @file
/// The two RSD shape-function tuples of the RSD G1 construction (../shared/notes/rsd-g1-surfaces.md
/// §2.5, with the corrected χ coefficients 15/6 and 15/15·t_b).

#include <string>

#include "geometry/rsd/univariate_polynomial.hpp"

namespace iga::rsd {

/// Π0: Ψ0 = Φ, Ψ1 = Θ (patches of degree 5 before correction; no linear precision).
/// Π1: Ψ0 = Ψ1 = Φ (degree 6; reproduces affine data).
enum class RsdTuple { pi0, pi1 };

inline std::string tuple_name(RsdTuple tuple) { return tuple == RsdTuple::pi0 ? "pi0" : "pi1"; }

/// Φ(t) = t³(10 − 15t + 6t²), the quintic smoothstep.
template <class T>
Poly<T> phi() {
  return Poly<T>(std::vector<T>{T(0), T(0), T(0), T(10), T(-15), T(6)});
}

/// Θ(t) = t³(4 − 3t).
template <class T>
Poly<T> theta() {
  return Poly<T>(std::vector<T>{T(0), T(0), T(0), T(4), T(-3)});
}

template <class T>
Poly<T> psi0(RsdTuple) {
  return phi<T>();
}

template <class T>
Poly<T> psi1(RsdTuple tuple) {
  return tuple == RsdTuple::pi0 ? theta<T>() : phi<T>();
}

/// Polynomial degree of the uncorrected patches: 5 (Π0) or 6 (Π1).
inline int rsd_degree(RsdTuple tuple) { return tuple == RsdTuple::pi0 ? 5 : 6; }

}  // namespace iga::rsd
