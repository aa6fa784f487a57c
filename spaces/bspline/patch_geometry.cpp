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
  const int pu = knots_u_.degree(), pv = knots_v_.degree();
  const int nu = knots_u_.num_functions();
  const int nder = second ? 2 : 1;
  const SpanDerivatives Nu(knots_u_, span_u, uv.x(), nder);
  const SpanDerivatives Nv(knots_v_, span_v, uv.y(), nder);
  // Homogeneous sums A = sum w P N M and W = sum w N M with derivatives d^a/du^a d^b/dv^b.
  Point2 A[3][3];
  double W[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      A[a][b].setZero();
      W[a][b] = 0.0;
    }
  for (int jb = 0; jb <= pv; ++jb) {
    const int j = span_v - pv + jb;
    for (int ia = 0; ia <= pu; ++ia) {
      const int idx = (span_u - pu + ia) + j * nu;
      const double w = weights_[idx];
      const Point2 wp = w * control_points_[idx];
      for (int a = 0; a <= nder; ++a)
        for (int b = 0; a + b <= nder; ++b) {
          const double s = Nu(a, ia) * Nv(b, jb);
          A[a][b] += s * wp;
          W[a][b] += s * w;
        }
    }
  }
  GeometryJet g;
  if (!rational_) {
    // W = 1 and its derivatives vanish, but summed they come out at round-off (1e-17): through the
    // quotient rule that made ∂x/∂v of the unit square 1e-20 instead of 0, and the closed-form
    // element matrices then kept the mixed terms of half the elements (twice the work there).
    g.x = A[0][0];
    g.jacobian.col(0) = A[1][0];
    g.jacobian.col(1) = A[0][1];
    if (second) {
      g.hessian_x << A[2][0].x(), A[1][1].x(), A[1][1].x(), A[0][2].x();
      g.hessian_y << A[2][0].y(), A[1][1].y(), A[1][1].y(), A[0][2].y();
    }
    return g;
  }
  // Quotient rule for x = A / W:
  //   x_k = (A_k - W_k x) / W,  x_kl = (A_kl - W_kl x - W_k x_l - W_l x_k) / W.
  const double w0 = W[0][0];
  g.x = A[0][0] / w0;
  const Point2 xu = (A[1][0] - W[1][0] * g.x) / w0;
  const Point2 xv = (A[0][1] - W[0][1] * g.x) / w0;
  g.jacobian.col(0) = xu;
  g.jacobian.col(1) = xv;
  if (second) {
    const Point2 xuu = (A[2][0] - W[2][0] * g.x - 2.0 * W[1][0] * xu) / w0;
    const Point2 xuv = (A[1][1] - W[1][1] * g.x - W[1][0] * xv - W[0][1] * xu) / w0;
    const Point2 xvv = (A[0][2] - W[0][2] * g.x - 2.0 * W[0][1] * xv) / w0;
    g.hessian_x << xuu.x(), xuv.x(), xuv.x(), xvv.x();
    g.hessian_y << xuu.y(), xuv.y(), xuv.y(), xvv.y();
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
