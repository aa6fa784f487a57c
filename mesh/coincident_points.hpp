#pragma once
/// @file
/// Finds two points of a mesh closer than a tolerance in linear time: a hash grid of cells about
/// the tolerance wide, each point compared only with those in its own and the neighbouring cells.
/// Shared by the planar and the quad surface mesh checks, whose files may put every vertex on one
/// coordinate line (a sort on one coordinate then compares all pairs).

#include <Eigen/Core>

#include <optional>
#include <utility>
#include <vector>

namespace iga {

/// When two points count as coincident: each coordinate differs by at most the tolerance, or
/// their Euclidean distance is at most the tolerance.
enum class Closeness { every_coordinate, distance };

/// The first coincident pair {earlier, later} among points[ids[k]], taking the ids in the order
/// given: `later` is the first id close to an id before it, `earlier` the first such id. Points
/// with a coordinate that is not finite are never coincident. No pair: nullopt.
template <int Dim>
std::optional<std::pair<int, int>> find_coincident_points(const std::vector<Eigen::Matrix<double, Dim, 1>>& points,
                                                          const std::vector<int>& ids, double tolerance,
                                                          Closeness closeness);

extern template std::optional<std::pair<int, int>> find_coincident_points<2>(const std::vector<Eigen::Vector2d>&,
                                                                             const std::vector<int>&, double,
                                                                             Closeness);
extern template std::optional<std::pair<int, int>> find_coincident_points<3>(const std::vector<Eigen::Vector3d>&,
                                                                             const std::vector<int>&, double,
                                                                             Closeness);

}  // namespace iga
