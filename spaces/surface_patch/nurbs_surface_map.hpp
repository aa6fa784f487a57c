#pragma once
/// @file
/// NurbsSurfaceMap: a tensor-product B-spline or NURBS map x: [0,1]² → R³ (3D control points,
/// optional weights) with its jets to second order — the exact geometry under the surface_patch
/// spaces (surface_patch_space.hpp). Rational maps are differentiated by the quotient rule on the
/// homogeneous sums A = Σ w P N, W = Σ w N (no differences).
///
/// A direction may be *periodic*: the map closes there (x(0, v) = x(1, v), likewise in v), and the
/// space built on it wraps around. How smooth the map is across each interior breakpoint and across
/// a periodic seam is *measured* (jumps of x, its first and its second derivatives along the knot
/// line), not read from knot multiplicities: the exact NURBS circle of quarter arcs has double knots
/// (C0 by multiplicity) but a C1 parametrisation, and a space may be C1 there (not C2: the speed's
/// derivative jumps, so u ∘ x has a second-derivative jump that a C2 spline cannot follow).

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "geometry/surface_jet.hpp"
#include "spaces/bspline/knot_vector.hpp"
#include "spaces/space.hpp"

namespace iga {

class NurbsSurfaceMap {
 public:
  /// Control points numbered i + j n_u (i along u). `weights` empty (B-spline) or one positive
  /// weight per point. Knot vectors are rescaled to [0,1]. Throws InputError on wrong counts,
  /// non-finite numbers, non-positive weights, a periodic direction that does not close (C0) or a
  /// degenerate map (|x_u × x_v| ≤ 1e-10 · size² somewhere on a sample grid); `description` is
  /// shown in space summaries and messages.
  NurbsSurfaceMap(const KnotVector& knots_u, const KnotVector& knots_v, std::vector<Eigen::Vector3d> control_points,
                  std::vector<double> weights, std::array<bool, 2> periodic, std::string description);

  /// x(uv) (the span containing uv).
  Eigen::Vector3d point(const Point2& uv) const;
  /// The raw derivatives at uv from the given spans: d[a][b] = ∂^a_u ∂^b_v x, a + b ≤ 2.
  std::array<std::array<Eigen::Vector3d, 3>, 3> derivatives(const Point2& uv, int span_u, int span_v) const;

  const KnotVector& knots(int direction) const { return direction == 0 ? knots_u_ : knots_v_; }
  bool periodic(int direction) const { return periodic_[direction]; }
  const std::string& description() const { return description_; }
  /// Largest extent of the control polygon (the length scale of tolerances).
  double size() const { return size_; }

  /// The smoothness of the map across the breakpoint t of `direction` (an interior breakpoint, or
  /// 0 for the seam of a periodic direction): the largest k ≤ 2 such that the derivatives
  /// ∂^a_t x, a ≤ k, agree from both sides at sample points along the knot line within 1e-9 of
  /// their size; -1 when even x jumps (a seam that does not close).
  int measured_continuity(int direction, double t) const;

 private:
  KnotVector knots_u_, knots_v_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<double> weights_;
  std::array<bool, 2> periodic_;
  std::string description_;
  double size_ = 0.0;
};

}  // namespace iga
