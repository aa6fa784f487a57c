#pragma once
/// @file
/// The map of a nested level's faces from the level-0 map alone: face f of level L is child f % 4
/// of face f / 4 of level L - 1 (QuadTopology::refined), so its coefficients are the level-0
/// ancestor's subdivided along that path (subdivided_face, the same operations as
/// subdivide_geometry: the same bits). A skeleton keeps this instead of every face's map
/// (2 (m+1)² doubles a face, ≈ 26 bytes per DOF at k = 5).

#include <Eigen/Core>
#include <vector>

#include "spaces/g1_4split/g1_4split_geometry.hpp"
#include "spaces/g1_4split/split_bspline.hpp"

namespace iga {

class NestedGeometry {
 public:
  /// The faces of `level0` refined `levels` times.
  NestedGeometry(const SplitBSpline& b, FaceGeometry level0, int levels)
      : b_(b), level0_(std::move(level0)), levels_(levels) {}

  /// The ancestors of the last face asked for, level by level: consecutive faces share most of
  /// them, so visiting the faces in order subdivides each ancestor once. One per thread.
  struct Path {
    std::vector<long long> face;  ///< ancestor index per level 1..levels (-1: none yet)
    std::vector<Eigen::VectorXd> x, y;
  };

  /// Face f's coefficients at the last level, (x, y) kept in `path` (valid until its next use).
  void face(int f, Path& path, const Eigen::VectorXd*& x, const Eigen::VectorXd*& y) const;

 private:
  SplitBSpline b_;
  FaceGeometry level0_;
  int levels_;
};

}  // namespace iga
