#pragma once
/// @file
/// Evaluating a planar space at physical points: which element holds a point and where in its
/// reference cell (Newton's method on the element map, candidates from bounding boxes), and the
/// basis functions there. Written against the Space interface only; used to evaluate discrete
/// solutions at arbitrary points (the Python module).

#include <Eigen/Geometry>

#include <optional>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// A physical point's element and reference coordinates.
struct PointLocation {
  int element = -1;
  Point2 reference = Point2::Zero();
};

/// The active basis functions at one point: global indices, values and physical gradients.
struct PointBasis {
  std::vector<int> dofs;
  Eigen::VectorXd value, dx, dy;
};

class PointLocator {
 public:
  /// Samples every element's map once (bounding boxes). Planar spaces only (std::invalid_argument
  /// for surfaces in 3D).
  explicit PointLocator(SpacePtr space);

  /// The element holding `x` (the first found where elements share an edge), or nullopt outside
  /// the domain (to 1e-10 x the domain size).
  std::optional<PointLocation> locate(const Point2& x) const;

  /// The basis at located points (an empty PointBasis where a location is nullopt).
  std::vector<PointBasis> basis_at(const std::vector<std::optional<PointLocation>>& where) const;

  const Space& space() const { return *space_; }

 private:
  SpacePtr space_;
  std::vector<Eigen::AlignedBox2d> boxes_;
  double size_ = 1.0;
};

}  // namespace iga
