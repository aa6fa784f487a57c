#pragma once
/// @file
/// Evaluating a planar space at physical points: which element holds a point and where in its
/// reference cell (Newton's method on the element map, candidates from bounding boxes binned on a
/// grid), and the basis functions there. Written against the Space interface only; the one place
/// that locates points (the Python module, functionals at a point, differences between levels).

#include <Eigen/Geometry>

#include <optional>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// Samples of the reference cell, weights 0: a 5 x 5 grid (square) or its part in the triangle.
QuadratureRule reference_samples(CellShape shape);

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
  /// Samples every element's map once (bounding boxes, binned on a grid of about one bin per
  /// element). Planar spaces only (std::invalid_argument for surfaces in 3D).
  explicit PointLocator(SpacePtr space);

  /// The element holding `x` (the first found where elements share an edge), or nullopt outside
  /// the domain (to 1e-10 x the domain size). The overload with an evaluator of this space reuses
  /// it (one per thread); the other makes one.
  std::optional<PointLocation> locate(const Point2& x) const;
  std::optional<PointLocation> locate(const Point2& x, Space::Evaluator& evaluator) const;

  /// Reference coordinates in `element` of the physical points `x` (2 x q), all at once (one
  /// geometry evaluation per Newton step), starting from `start`. `inside[k]` is false where the
  /// point's preimage is not in the element's reference cell (or Newton did not converge); there
  /// `reference[k]` is meaningless. `evaluator` must be one of this space.
  void invert_map(int element, const Eigen::Matrix2Xd& x, const Point2& start, Space::Evaluator& evaluator,
                  std::vector<Point2>& reference, std::vector<bool>& inside) const;

  /// The basis at located points (an empty PointBasis where a location is nullopt).
  std::vector<PointBasis> basis_at(const std::vector<std::optional<PointLocation>>& where) const;

  /// Elements whose (padded, sampled) bounding box holds x: the only ones that may hold it.
  void candidates(const Point2& x, std::vector<int>& out) const;

  const Space& space() const { return *space_; }

 private:
  SpacePtr space_;
  std::vector<Eigen::AlignedBox2d> boxes_;
  Eigen::AlignedBox2d all_;
  int bins_x_ = 1, bins_y_ = 1;
  std::vector<std::vector<int>> bins_;  ///< elements whose box meets each bin (row-major)
  double size_ = 1.0;
};

}  // namespace iga
