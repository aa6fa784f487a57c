#pragma once
/// @file
/// The 51 scaled simplex splines B_i = w_i M_{Ξ_i} of the WS4 split on the reference triangle,
/// stored as one Poly4 per (region, function): 252 x 51 quartic pieces, computed once by the
/// simplex-spline recurrence (notes §3) in polynomial arithmetic. Values and derivatives of any
/// order at any point then come from the piece of the region the point lies in; points on split
/// lines or on the boundary take the one-sided piece of Ws4Split::locate (notes §4).

#include <vector>

#include "config/double_double.hpp"
#include "spaces/push_forward.hpp"
#include "spaces/ws4/poly4.hpp"
#include "spaces/ws4/ws4_split.hpp"

namespace iga::ws4 {

class Ws4Basis {
 public:
  static constexpr int size = 51;

  /// The reference basis (built on first use, then shared; thread-safe).
  static const Ws4Basis& reference();

  const Ws4Split& split() const { return split_; }
  /// Piece of B_{i+1} on region r (i = 0..50), a polynomial in x - center(r).
  const Poly4& piece(int region, int i) const { return pieces_[region * size + i]; }
  /// The same piece in long double, as built (for the extended-precision reference matrices).
  const BasicPoly4<long double>& piece_extended(int region, int i) const {
    return pieces_extended_[region * size + i];
  }
  /// All pieces (region-major, as piece()) built again in double-double, for reference matrices
  /// beyond long double (a one-time cost of a fraction of a second).
  std::vector<BasicPoly4<DoubleDouble>> pieces_double_double() const;
  /// Origin of the local coordinates of the pieces of region r (its vertex average).
  const Point2& center(int region) const { return split_.regions()[region].centroid; }

  /// Values, first and second reference derivatives of the 51 functions at `points`
  /// (each located with Ws4Split::locate). Arrays of `out` are 51 x points.size().
  void tabulate(const std::vector<Point2>& points, ReferenceDerivatives& out) const;

  /// D_{w_1} ... D_{w_k} B_{i+1}(x) for reference vectors w (k <= 4), one-sided at x.
  /// @param[out] out 51 values, one per function.
  void directional_derivatives(const Point2& x, const std::vector<Point2>& w, double* out) const;

 private:
  Ws4Basis();

  const Ws4Split& split_;
  std::vector<Poly4> pieces_;  ///< regions x 51
  std::vector<BasicPoly4<long double>> pieces_extended_;
};

}  // namespace iga::ws4
