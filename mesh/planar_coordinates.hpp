#pragma once
/// @file
/// Dropping z from the vertices of a mesh file, after checking that the mesh is planar.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace iga {

/// (x, y) of every point. A NaN or infinite coordinate is an InputError naming the point. All z must agree (to 1e-10 x the (x, y) diameter; z = const ≠ 0 is fine);
/// otherwise an InputError "<source>: vertex k (<origin>) has z = ..., vertex 0 has z = ...".
/// `origins` (optional, one per point) says where each point was read, e.g. "line 7".
std::vector<Eigen::Vector2d> planar_coordinates(const std::vector<Eigen::Vector3d>& points,
                                                const std::vector<std::string>& origins, const std::string& source);

}  // namespace iga
