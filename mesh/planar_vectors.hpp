#pragma once
/// @file
/// Small vector helpers of the planar mesh checks.
#include <Eigen/Core>

namespace iga {

/// z-component of a × b: positive when b turns counter-clockwise from a.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace iga
