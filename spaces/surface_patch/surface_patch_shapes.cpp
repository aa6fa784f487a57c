#include "spaces/surface_patch/surface_patch_shapes.hpp"

#include <cmath>
#include <numbers>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {

constexpr double degree = std::numbers::pi / 180.0;

/// A NURBS curve in a plane: knots, control points (a, b), weights.
struct Curve {
  KnotVector knots{1, {0.0, 0.0, 1.0, 1.0}};
  std::vector<Eigen::Vector2d> points;
  std::vector<double> weights;
};

/// The circular arc of `radius` about `center` from angle a to b (radians, a < b) in ceil((b − a) / 90°)
/// equal rational quadratic pieces: (center + radius (cos t, sin t)).
Curve arc(const Eigen::Vector2d& center, double radius, double a, double b) {
  const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / (std::numbers::pi / 2) - 1e-12)));
  const double delta = (b - a) / pieces, w = std::cos(delta / 2);
  Curve c;
  std::vector<double> knots{0.0, 0.0, 0.0};
  for (int k = 0; k < pieces; ++k) {
    const double t0 = a + k * delta, tm = t0 + delta / 2;
    if (k == 0) {
      c.points.push_back(center + radius * Eigen::Vector2d(std::cos(t0), std::sin(t0)));
      c.weights.push_back(1.0);
    }
    c.points.push_back(center + radius / w * Eigen::Vector2d(std::cos(tm), std::sin(tm)));
    c.weights.push_back(w);
    c.points.push_back(center + radius * Eigen::Vector2d(std::cos(t0 + delta), std::sin(t0 + delta)));
    c.weights.push_back(1.0);
    if (k + 1 < pieces) {
      knots.push_back(double(k + 1) / pieces);
      knots.push_back(double(k + 1) / pieces);
    }
  }
  knots.insert(knots.end(), {1.0, 1.0, 1.0});
  c.knots = KnotVector(2, std::move(knots));
  return c;
}

/// The straight segment from p to q.
Curve segment(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  Curve c;
  c.points = {p, q};
  c.weights = {1.0, 1.0};
  return c;
}

/// The profile (ρ_j, z_j) swept about the z axis by the unit arc `around` (u), profile along v;
/// `axis_x`: then (x, y, z) ← (z, y, x), the axis becomes x.
NurbsSurfaceMap revolve(const Curve& around, const Curve& profile, std::array<bool, 2> periodic,
                        const std::string& description, bool axis_x = false) {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  for (std::size_t j = 0; j < profile.points.size(); ++j)
    for (std::size_t i = 0; i < around.points.size(); ++i) {
      const double rho = profile.points[j].x(), z = profile.points[j].y();
      if (axis_x)
        points.emplace_back(z, rho * around.points[i].y(), rho * around.points[i].x());
      else
        points.emplace_back(rho * around.points[i].x(), rho * around.points[i].y(), z);
      weights.push_back(around.weights[i] * profile.weights[j]);
    }
  return NurbsSurfaceMap(around.knots, profile.knots, std::move(points), std::move(weights), periodic, description);
}

void require_positive(double value, const std::string& what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InputError(what + " must be a positive number (got " + format_number(value) + ")");
}

}  // namespace

std::shared_ptr<const NurbsSurfaceMap> nurbs_cylinder(double radius, double length, double half_angle_degrees) {
  require_positive(radius, "the cylinder's radius");
  require_positive(length, "the cylinder's length");
  require_positive(half_angle_degrees, "the cylinder's half_angle");
  const bool closed = half_angle_degrees >= 180.0;
  const double half = closed ? std::numbers::pi : half_angle_degrees * degree;
  // Revolved about z with θ measured from the x axis, then (x, y, z) ← (z, y, x): the axis becomes
  // x and θ = 0 the crown z = R.
  const Curve around = arc(Eigen::Vector2d::Zero(), 1.0, -half, half);
  const Curve profile = segment({radius, 0.0}, {radius, length});
  const std::string what = closed ? "closed cylinder" : "cylinder sector |θ| <= " + format_number(half_angle_degrees) + "°";
  return std::make_shared<const NurbsSurfaceMap>(revolve(around, profile, {closed, false},
                                                         "NURBS " + what + " R = " + format_number(radius) +
                                                             ", L = " + format_number(length),
                                                         true));
}

std::shared_ptr<const NurbsSurfaceMap> nurbs_torus(double major_radius, double minor_radius) {
  require_positive(minor_radius, "the torus's minor_radius");
  if (!(major_radius > minor_radius) || !std::isfinite(major_radius))
    throw InputError("the torus's major_radius must be greater than its minor_radius (got R = " +
                     format_number(major_radius) + ", r = " + format_number(minor_radius) + ")");
  const Curve around = arc(Eigen::Vector2d::Zero(), 1.0, 0.0, 2 * std::numbers::pi);
  const Curve profile = arc(Eigen::Vector2d(major_radius, 0.0), minor_radius, 0.0, 2 * std::numbers::pi);
  return std::make_shared<const NurbsSurfaceMap>(revolve(around, profile, {true, true},
                                                         "NURBS torus R = " + format_number(major_radius) +
                                                             ", r = " + format_number(minor_radius)));
}

std::shared_ptr<const NurbsSurfaceMap> nurbs_sphere_zone(double radius, double hole_degrees, double sweep_degrees) {
  require_positive(radius, "the sphere's radius");
  if (!(hole_degrees > 0.0 && hole_degrees < 90.0))
    throw InputError("the sphere's hole (polar angle in degrees) must be in (0, 90) (got " + format_number(hole_degrees) +
                     "; 0 would put the singular pole on the surface)");
  if (!(sweep_degrees > 0.0 && sweep_degrees <= 360.0))
    throw InputError("the sphere's sweep must be in (0, 360] degrees (got " + format_number(sweep_degrees) + ")");
  const bool closed = sweep_degrees == 360.0;
  const Curve around = arc(Eigen::Vector2d::Zero(), 1.0, 0.0, sweep_degrees * degree);
  // The meridian from the equator (polar angle 90°) up to the hole, as (ρ, z) = R (sin ψ, cos ψ):
  // angle t = 90° − ψ from 0 to 90° − hole, so v runs from the equator to the hole's rim.
  const Curve profile = arc(Eigen::Vector2d::Zero(), radius, 0.0, (90.0 - hole_degrees) * degree);
  return std::make_shared<const NurbsSurfaceMap>(
      revolve(around, profile, {closed, false},
              "NURBS sphere zone R = " + format_number(radius) + ", hole " + format_number(hole_degrees) + "°" +
                  (closed ? "" : ", sweep " + format_number(sweep_degrees) + "°")));
}

}  // namespace iga
