#pragma once
/// @file
/// A sphere or a circular cylinder given by its numbers, and the closest point on it: the target a
/// quad mesh's facets are mapped onto before a smooth surface is fitted to them (a g1_4split
/// surface's `fit_onto`, docs/spaces/g1_4split.md), so that the fitted surface approximates the
/// exact one rather than the polyhedron of its facets.

#include <Eigen/Core>
#include <string>

namespace iga {

struct ExactSurface {
  enum class Shape { sphere, cylinder };
  Shape shape = Shape::sphere;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< the sphere's centre, or a point of the cylinder's axis
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   ///< the cylinder's axis (unit)
  double radius = 1.0;

  /// The closest point: radially from the centre (sphere) or from the axis (cylinder). p must
  /// not be the centre or on the axis (InputError there).
  Eigen::Vector3d closest(const Eigen::Vector3d& p) const;
  /// Signed distance |p − c| − R (sphere) or distance from the axis − R (cylinder).
  double distance(const Eigen::Vector3d& p) const;
  /// "sphere R = 10 about (0, 0, 0)", for summaries and messages.
  std::string describe() const;
};

}  // namespace iga
