#pragma once
/// @file
/// Value, first and second partial derivatives of a triangular Bézier patch with respect to its
/// barycentric parameters (homogeneous form): what element maps into R³ need for Jacobians, normals
/// and curvatures.

#include <Eigen/Core>
#include <array>

#include "geometry/rsd/bezier_triangle.hpp"

namespace iga {

struct BezierJet {
  Eigen::Vector3d x;
  std::array<Eigen::Vector3d, 3> d;                  ///< ∂F/∂t_a
  std::array<std::array<Eigen::Vector3d, 3>, 3> dd;  ///< ∂²F/∂t_a∂t_b (symmetric)
};

/// The jet of `patch` at barycentric t (second derivatives only when `second` is true).
BezierJet bezier_jet(const BezierTriangle& patch, const Eigen::Vector3d& t, bool second);

}  // namespace iga
