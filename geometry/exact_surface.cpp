#include "geometry/exact_surface.hpp"

#include <cmath>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {

/// The part of p − c away from the centre (sphere) or from the axis (cylinder).
Eigen::Vector3d radial(const ExactSurface& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = p - s.center;
  return s.shape == ExactSurface::Shape::sphere ? d : Eigen::Vector3d(d - d.dot(s.axis) * s.axis);
}

std::string text(const Eigen::Vector3d& v) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "(" + std::string.
  std::string s = "(";
  for (int i = 0; i < 3; ++i) s += (i ? ", " : "") + format_number(v(i));
  return s + ")";
}

}  // namespace

Eigen::Vector3d ExactSurface::closest(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d r = radial(*this, p);
  if (!(r.norm() > 1e-12 * radius))
    throw InputError("the point " + text(p) + " is at the " + (shape == Shape::sphere ? "centre" : "axis") + " of the " +
                     describe() + ": it has no closest point on it");
  return p - r + radius * r.normalized();
}

double ExactSurface::distance(const Eigen::Vector3d& p) const { return radial(*this, p).norm() - radius; }

std::string ExactSurface::describe() const {
  return shape == Shape::sphere ? "sphere R = " + format_number(radius) + " about " + text(center)
                                : "cylinder R = " + format_number(radius) + " about the axis " + text(axis) +
                                      " through " + text(center);
}

}  // namespace iga
