#include "spaces/surface_patch/nurbs_surface_map.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

NurbsSurfaceMap::NurbsSurfaceMap(const KnotVector& knots_u, const KnotVector& knots_v,
                                 std::vector<Eigen::Vector3d> control_points, std::vector<double> weights,
                                 std::array<bool, 2> periodic, std::string description)
    : knots_u_(knots_u.on_unit_interval()),
      knots_v_(knots_v.on_unit_interval()),
      points_(std::move(control_points)),
      weights_(std::move(weights)),
      periodic_(periodic),
      description_(std::move(description)) {
  const int nu = knots_u_.num_functions(), nv = knots_v_.num_functions();
  if (static_cast<int>(points_.size()) != nu * nv)
    throw InputError(description_ + ": the knot vectors need " + std::to_string(nu) + " x " + std::to_string(nv) + " = " +
                     std::to_string(nu * nv) + " control points (got " + std::to_string(points_.size()) + ")");
  if (!weights_.empty() && weights_.size() != points_.size())
    throw InputError(description_ + ": need one weight per control point: " + std::to_string(points_.size()) + " (got " +
                     std::to_string(weights_.size()) + ")");
  for (std::size_t i = 0; i < weights_.size(); ++i)
    if (!(weights_[i] > 0.0) || !std::isfinite(weights_[i]))
      throw InputError(description_ + ": weights must be positive and finite (weight " + std::to_string(i) + " is " +
                       format_number(weights_[i]) + ")");
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].allFinite())
      throw InputError(description_ + ": control point " + std::to_string(i) + " is not finite");
    lo = lo.cwiseMin(points_[i]);
    hi = hi.cwiseMax(points_[i]);
  }
  size_ = (hi - lo).maxCoeff();
  if (!(size_ > 0.0)) throw InputError(description_ + ": all control points coincide");
  for (int d = 0; d < 2; ++d)
    if (periodic_[d] && measured_continuity(d, 0.0) < 0)
      throw InputError(description_ + ": direction " + std::string(d == 0 ? "u" : "v") +
                       " is declared periodic but the patch does not close there (x at parameter 0 and 1 differ)");
  // A degenerate map (a pole, a collapsed edge) has no normal: refuse it on a sample grid.
  constexpr int m = 4;
  SurfaceJet j;
  for (int su : knots_u_.spans())
    for (int sv : knots_v_.spans())
      for (int a = 0; a <= m; ++a)
        for (int b = 0; b <= m; ++b) {
          const Point2 uv(knots_u_[su] + a / double(m) * (knots_u_[su + 1] - knots_u_[su]),
                          knots_v_[sv] + b / double(m) * (knots_v_[sv + 1] - knots_v_[sv]));
          const auto d = derivatives(uv, su, sv);
          Eigen::Matrix<double, 3, 2> J;
          J << d[1][0], d[0][1];
          fill_surface_jet(j, d[0][0], J);
          if (!(j.area > 1e-10 * size_ * size_))
            throw InputError(description_ + ": the map is degenerate at parameter (" + format_number(uv.x()) + ", " +
                             format_number(uv.y()) + "): |x_u × x_v| = " + format_number(j.area) +
                             " (poles and collapsed edges have no normal)");
        }
}

std::array<std::array<Eigen::Vector3d, 3>, 3> NurbsSurfaceMap::derivatives(const Point2& uv, int span_u,
                                                                          int span_v) const {
  return tensor_map_derivatives(knots_u_, knots_v_, uv.x(), uv.y(), span_u, span_v, 2, points_, weights_, true);
}

Eigen::Vector3d NurbsSurfaceMap::point(const Point2& uv) const {
  return derivatives(uv, knots_u_.find_span(uv.x()), knots_v_.find_span(uv.y()))[0][0];
}

int NurbsSurfaceMap::measured_continuity(int direction, double t) const {
  const KnotVector& along = knots(direction);       // the direction crossing the knot line
  const KnotVector& across = knots(1 - direction);  // the direction along the knot line
  // Left side: the span ending at t (at the seam: the last span, at t = 1); right: the span from t.
  const bool seam = t <= 0.0;
  const int left = seam ? along.spans().back() : along.find_span(t - 1e-12 * (1.0 + std::abs(t)));
  const int right = along.find_span(seam ? 0.0 : t);
  const double t_left = seam ? 1.0 : t, t_right = seam ? 0.0 : t;
  int k = 2;
  constexpr int samples = 7;
  for (int s = 0; s < samples; ++s) {
    const double r = (s + 0.5) / samples;
    const int span = across.find_span(r);
    auto at = [&](double tt, int sp) {
      return direction == 0 ? derivatives(Point2(tt, r), sp, span) : derivatives(Point2(r, tt), span, sp);
    };
    const auto a = at(t_left, left), b = at(t_right, right);
    for (int order = 0; order <= k; ++order) {
      const Eigen::Vector3d& da = direction == 0 ? a[order][0] : a[0][order];
      const Eigen::Vector3d& db = direction == 0 ? b[order][0] : b[0][order];
      const double scale = std::max({da.norm(), db.norm(), size_ * 1e-3});
      if ((da - db).norm() > 1e-9 * scale) {
        k = order - 1;
        break;
      }
    }
    if (k < 0) return -1;
  }
  return k;
}

}  // namespace iga
