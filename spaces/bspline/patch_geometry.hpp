#pragma once
/// @file
/// PatchGeometry: a tensor-product B-spline or NURBS map F: [0,1]^2 -> R^2 with its first and
/// second derivatives (GeometryJet), the geometry under every B-spline space of iga-run.

#include <string>
#include <vector>

#include "spaces/bspline/knot_vector.hpp"
#include "spaces/push_forward.hpp"

namespace iga {

class PatchGeometry {
 public:
  /// General patch. Knot vectors are rescaled affinely to [0,1]. Control points are numbered
  /// i + j * n_u (i along u, j along v); `weights` is empty (polynomial patch) or holds one
  /// positive weight per control point (NURBS). Throws InputError on a wrong count or a weight
  /// <= 0. `description` is shown in space summaries.
  PatchGeometry(const KnotVector& knots_u, const KnotVector& knots_v, std::vector<Point2> control_points,
                std::vector<double> weights = {}, std::string description = "patch");

  /// The axis-aligned rectangle [min, max] as a bilinear (affine) patch: u along x, v along y.
  /// Throws InputError unless min < max in both coordinates.
  static PatchGeometry rectangle(const Point2& min, const Point2& max);
  /// Quarter annulus {inner <= |x| <= outer, x >= 0, y >= 0}: u radial (u = 0 on the inner arc),
  /// v angular (v = 0 on the x axis), exact circles by NURBS of degree 2 with weights
  /// 1, 1/sqrt(2), 1. Throws InputError unless 0 < inner < outer.
  static PatchGeometry quarter_annulus(double inner, double outer);

  /// Throws InputError "`name`: ..." unless det J > 0 on a sample grid inside every span pair
  /// (a folded or clockwise patch).
  void check_orientation(const std::string& name) const;

  /// F and its derivatives at parameter uv in [0,1]^2, w.r.t. (u, v).
  GeometryJet evaluate(const Point2& uv) const;
  /// Same with the polynomial pieces of the given nonzero spans (chooses the side at a knot, where
  /// second derivatives may jump). `second` = false leaves the Hessians zero.
  GeometryJet evaluate(const Point2& uv, int span_u, int span_v, bool second = true) const;
  /// F(uv) only.
  Point2 point(const Point2& uv) const { return evaluate(uv, knots_u_.find_span(uv.x()), knots_v_.find_span(uv.y()), false).x; }

  const KnotVector& knots_u() const { return knots_u_; }
  const KnotVector& knots_v() const { return knots_v_; }
  bool is_rational() const { return rational_; }
  /// True for maps known to be affine (rectangles).
  bool is_affine() const { return affine_; }
  const std::string& description() const { return description_; }

 private:
  KnotVector knots_u_, knots_v_;
  std::vector<Point2> control_points_;
  std::vector<double> weights_;
  bool rational_ = false;
  bool affine_ = false;
  // An affine map F(uv) = origin_ + linear_ uv, evaluated without the spline sums (3 % of a
  // B-spline Poisson run on a rectangle went to evaluating its bilinear patch).
  Point2 origin_ = Point2::Zero();
  Eigen::Matrix2d linear_ = Eigen::Matrix2d::Zero();
  std::string description_;
};

}  // namespace iga
