#pragma once
/// @file
/// The robust per-edge G1 solver (note §6.1): prescribe the corrected cross-derivative as
/// V = X u + Y d (d = v̄ − v) with smoothstep blends X, Y of their end values, which come from two
/// consistent 3×2 solves with vertex data only, and divide z = (v − X u − Y d)/(t²(1−t)²) exactly.
/// Degree 3 (Π0) / 4 (Π1), affine-equivariant, independent of edge orientation, and fold-free
/// along the edge (−1 < Y < 0) whenever condition (12) holds.

#include "geometry/rsd/edge_curves.hpp"

namespace iga::rsd {

struct HermiteEdgeSolution {
  double X0 = 0, Y0 = 0, X1 = 0, Y1 = 0;  ///< end values at t = 0 (p_j) and t = 1 (p_i)
  /// Relative residuals of the two 3×2 systems: round-off when the data are coplanar (28).
  double residual0 = 0, residual1 = 0;
  /// Remainder of the division by t²(1−t)², relative to the numerator (round-off when exact).
  double division_remainder = 0;
  bool already_g1 = false;  ///< Δ ≡ 0 up to round-off: the correction is skipped (z = 0)
  VecPoly<double> z;
  Poly<double> X() const;  ///< X(t) = X0 + (X1 − X0)(3t² − 2t³)
  Poly<double> Y() const;
};

/// Solves one double edge from its end data. Never throws: the caller checks the residuals and
/// the range of Y0, Y1 and names the vertices.
HermiteEdgeSolution solve_edge_hermite(RsdTuple tuple, const EdgeEndData<double>& data);

/// Relative remainder of Δ ÷ t²(1−t)² (note §3.4, Prop. 2): round-off for coplanar data (28),
/// of the order of the violation otherwise.
double delta_division_remainder(const EdgeCurves<double>& curves);

}  // namespace iga::rsd
