#include "config/config_node.hpp"
#include "spaces/bspline/patch_geometry.hpp"

#include <Eigen/LU>  // Matrix2d::determinant
#include <cmath>
#include <sstream>

#include "config/errors.hpp"
#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

PatchGeometry::PatchGeometry(const KnotVector& knots_u, const KnotVector& knots_v, std::vector<Point2> control_points,
                             std::vector<double> weights, std::string description)
    : knots_u_(knots_u.on_unit_interval()),
      knots_v_(knots_v.on_unit_interval()),
      control_points_(std::move(control_points)),
      weights_(std::move(weights)),
      rational_(!weights_.empty()),
      description_(std::move(description)) {
  const int nu = knots_u_.num_functions(), nv = knots_v_.num_functions();
  const int n = static_cast<int>(control_points_.size());
  if (n != nu * nv)
    throw InputError("the knot vectors need " + std::to_string(nu) + " x " + std::to_string(nv) + " = " +
                     std::to_string(nu * nv) + " control points (got " + std::to_string(n) + ")");
  if (rational_) {
    if (static_cast<int>(weights_.size()) != n)
      throw InputError("need one weight per control point: " + std::to_string(n) + " (got " +
                       std::to_string(weights_.size()) + ")");
    for (int i = 0; i < n; ++i)
      if (!(weights_[i] > 0.0) || !std::isfinite(weights_[i]))
        throw InputError("weights must be positive (weight " + std::to_string(i) + " is " + format_number(weights_[i]) + ")");
  } else {
    weights_.assign(n, 1.0);
  }
  for (const Point2& p : control_points_)
    if (!p.allFinite()) throw InputError("control points must be finite numbers");
}

PatchGeometry PatchGeometry::rectangle(const Point2& min, const Point2& max) {
  if (!(min.x() < max.x()) || !(min.y() < max.y()))
    throw InputError("rectangle needs min < max in both coordinates (got min = [" + format_number(min.x()) + ", " +
                     format_number(min.y()) + "], max = [" + format_number(max.x()) + ", " + format_number(max.y()) + "])");
  const KnotVector linear(1, {0.0, 0.0, 1.0, 1.0});
  PatchGeometry g(linear, linear,
                  {Point2(min.x(), min.y()), Point2(max.x(), min.y()), Point2(min.x(), max.y()), Point2(max.x(), max.y())},
                  {},
                  "rectangle [" + format_number(min.x()) + "," + format_number(max.x()) + "]x[" + format_number(min.y()) + "," + format_number(max.y()) + "]");
  g.affine_ = true;
  g.origin_ = min;
  g.linear_ = (max - min).asDiagonal();
  return g;
}

PatchGeometry PatchGeometry::quarter_annulus(double inner, double outer) {
  if (!(inner > 0.0) || !(inner < outer) || !std::isfinite(outer))
    throw InputError("quarter annulus needs 0 < inner < outer (got inner = " + format_number(inner) + ", outer = " +
                     format_number(outer) + ")");
  const KnotVector radial(1, {0.0, 0.0, 1.0, 1.0});
  const KnotVector angular(2, {0.0, 0.0, 0.0, 1.0, 1.0, 1.0});
  const double w = 1.0 / std::sqrt(2.0);  // the middle weight that makes the conic a circle
  std::vector<Point2> cp;
  std::vector<double> wt;
  const Point2 dirs[3] = {Point2(1.0, 0.0), Point2(1.0, 1.0), Point2(0.0, 1.0)};
  for (int j = 0; j < 3; ++j)
    for (double r : {inner, outer}) {
      cp.push_back(r * dirs[j]);
      wt.push_back(j == 1 ? w : 1.0);
    }
  return PatchGeometry(radial, angular, std::move(cp), std::move(wt),
                       "quarter annulus r in [" + format_number(inner) + "," + format_number(outer) + "]");
}

GeometryJet PatchGeometry::evaluate(const Point2& uv) const {
  return evaluate(uv, knots_u_.find_span(uv.x()), knots_v_.find_span(uv.y()), true);
}

GeometryJet PatchGeometry::evaluate(const Point2& uv, int span_u, int span_v, bool second) const {
  if (affine_) {
    GeometryJet g;
    g.x = origin_ + linear_ * uv;
    g.jacobian = linear_;
    return g;
  }
  const auto d = tensor_map_derivatives(knots_u_, knots_v_, uv.x(), uv.y(), span_u, span_v, second ? 2 : 1,
                                        control_points_, weights_, rational_);
  // Without rational_ the sums are x itself: W = 1 and its derivatives vanish, but summed they come
  // out at round-off (1e-17): through the quotient rule that made ∂x/∂v of the unit square 1e-20
  // instead of 0, and the closed-form element matrices then kept the mixed terms of half the
  // elements (twice the work there).
  GeometryJet g;
  g.x = d[0][0];
  g.jacobian.col(0) = d[1][0];
  g.jacobian.col(1) = d[0][1];
  if (second) {
    g.hessian_x << d[2][0].x(), d[1][1].x(), d[1][1].x(), d[0][2].x();
    g.hessian_y << d[2][0].y(), d[1][1].y(), d[1][1].y(), d[0][2].y();
  }
  return g;
}

void PatchGeometry::check_orientation(const std::string& name) const {
  constexpr int m = 4;  // samples per span and direction, at interior points
  int positive = 0, nonpositive = 0;
  double worst = 0.0;
  Point2 worst_uv(0.0, 0.0);
  for (int su : knots_u_.spans())
    for (int sv : knots_v_.spans())
      for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b) {
          const double u = knots_u_[su] + (a + 0.5) / m * (knots_u_[su + 1] - knots_u_[su]);
          const double v = knots_v_[sv] + (b + 0.5) / m * (knots_v_[sv + 1] - knots_v_[sv]);
          const double det = evaluate(Point2(u, v), su, sv, false).jacobian.determinant();
          if (det > 0.0) {
            ++positive;
          } else {
            if (nonpositive == 0 || det < worst) {
              worst = det;
              worst_uv = Point2(u, v);
            }
            ++nonpositive;
          }
        }
  if (nonpositive == 0) return;
  const std::string at = "det J = " + format_number(worst) + " at parameter (" + format_number(worst_uv.x()) + ", " + format_number(worst_uv.y()) + ")";
  if (positive == 0)
    throw InputError(name + ": the geometry map (" + description_ + ") reverses orientation (" + at +
                     "); order the control points so that the u and v directions turn counterclockwise");
  throw InputError(name + ": the geometry map (" + description_ + ") folds over itself (" + at +
                   "; det J must be > 0)");
}

}  // namespace iga
